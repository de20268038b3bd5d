#!/usr/bin/env bash
# Regenerates the pictures of docs/contour.md from the examples (needs build/sansui: scripts/build).
set -euo pipefail
cd "$(dirname "$0")/.."
s=build/sansui
out=docs/images
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
$s contour examples/contours/ridge.geojson --method simple --offset 20 --map "$out/contour_ridge_simple.png" --map-width 900
$s contour examples/contours/ridge.geojson --offset 20 --map "$out/contour_ridge_revised.png" --map-width 900 \
  --dem "$work/ridge.r32" --dem-size 1025
$s contour examples/contours/neck.geojson --offset 15 --map "$out/contour_neck.png" --map-width 900
$s contour examples/contours/c_shape.csv --offset 15 --outward 4 --map "$out/contour_c_shape.png" --map-width 900
$s contour examples/contours/ridge.geojson --offset 20 --z0 300 --base 255 --crater-depth 35 --crater-width 0.4 \
  --map "$out/contour_crater_map.png" --map-width 900 --dem "$work/crater.r32" --dem-size 513
$s render "$work/crater.r32" --width 900 --camera-elevation 45 --sea-level 100 --snow-line 1 --exaggeration 3 \
  -o "$out/contour_crater_render.png"
rm -f "$out"/contour_crater_*.png.json
real=examples/dem/jacksboro_ridge.tif
$s contour --from-dem $real --level 800 --contours "$work/m.geojson" --dem "$work/m.tif"
$s compare $real "$work/m.tif" --inside "$work/m.geojson" --interval 10 \
  --map-real "$out/contour_jacksboro_real.png" --map-generated "$out/contour_jacksboro_generated.png"
