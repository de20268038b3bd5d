#!/usr/bin/env bash
# Makes the terrain pictures of the README and docs/terrain.md: the paper's five geomorphic stage filters on its raw
# fractal (no erosion, its sea level and version 1's H and sigma), and a preview beside the full
# world. Usage: docs/terrain_images.sh  (needs scripts/build)
set -euo pipefail
cd "$(dirname "$0")/.."
sansui=build/sansui
images=docs/images
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

paper=(--no-erode --paper-sea-level --hurst 0.8 --sigma 400)
for stage in original young mature old peneplain; do
  $sansui terrain "${paper[@]}" --size 513 --cell 20 --seed 5 --stage "$stage" -o "$work/$stage.r32"
  $sansui render "$work/$stage.r32" --width 400 --height 240 -o "$images/terrain-stage-$stage.png"
done

# Preview equals final: every 8th sample of a 4097 world, and the world itself.
$sansui terrain "${paper[@]}" --world-size 4097 --lod 3 --cell 2.5 --seed 5 -o "$work/preview.r32"
$sansui terrain "${paper[@]}" --world-size 4097 --cell 2.5 --seed 5 -o "$work/final.r32"
$sansui render "$work/preview.r32" --view top --width 400 -o "$images/terrain-lod3.png"
$sansui render "$work/final.r32" --view top --width 400 -o "$images/terrain-lod0.png"
rm -f "$images"/terrain-*.png.json  # the pictures' sidecars stay out of docs/
