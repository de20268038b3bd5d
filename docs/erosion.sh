#!/usr/bin/env bash
# Makes the pictures of docs/erosion.md: one default world at each erosion stage (`--stage ...`;
# left to right original, young, mature, old, peneplain), its rivers and lakes from above, and its
# splat maps (erosion, deposition, wetness, flow). Usage: docs/erosion.sh
# (needs scripts/build)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sansui=build/sansui
common=(--size 1025 --cell 10 --seed 5)
pictures=()
for stage in original young mature old peneplain; do
  "$sansui" terrain "${common[@]}" --stage "$stage" -o "$work/$stage.r32" >/dev/null
  "$sansui" render "$work/$stage.r32" --width 480 --height 300 --camera-azimuth 200 --camera-elevation 22 --exaggeration 3 --draw-water \
    -o "$work/$stage.png" >/dev/null
  pictures+=("$work/$stage.png")
done
convert "${pictures[@]}" +append docs/images/erosion-stages.png
# Rivers and lakes from above, on the mature island, with a smaller channel threshold.
"$sansui" terrain "${common[@]}" --stage mature --flow-channel-area 2e5 -o "$work/mature.r32" \
  --rivers "$work/rivers.geojson" --erosion-map "$work/erosion.png" --deposition-map "$work/deposition.png" \
  --wetness-map "$work/wetness.png" --flow-map "$work/flow.png" >/dev/null
"$sansui" render "$work/mature.r32" --view top --width 700 --draw-water --flow-channel-area 2e5 -o docs/images/erosion-rivers.png >/dev/null
maps=()
for map in erosion deposition wetness flow; do
  convert "$work/$map.png" -auto-level -resize 256x256 "$work/$map-small.png"
  maps+=("$work/$map-small.png")
done
convert "${maps[@]}" +append docs/images/erosion-maps.png
rm -f docs/images/erosion-rivers.png.json  # the sidecar of a picture made for the docs
