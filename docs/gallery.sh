#!/usr/bin/env bash
# Makes docs/gallery.png: the six gallery scenes of examples/scenes/gallery/, rendered by
# `sansui run` (each from where a person would stand) and laid out three by two at half size; and
# docs/images/scene-main-job.png and scene-main-job-ground.png, the README's pictures of the main job. Usage: docs/gallery.sh  (needs scripts/build)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

scenes=(alpine-summer-noon tropical-coast desert-dusk boreal-winter-morning temperate-autumn-overcast night-with-stars)
pictures=()
for scene in "${scenes[@]}"; do
  build/sansui run "examples/scenes/gallery/$scene.toml" --out-dir "$work" >/dev/null
  pictures+=("$work/$scene.png")
done
build/bench/contact_sheet docs/gallery.png 3 2 "${pictures[@]}"
cp "$work/tropical-coast.png" docs/images/scene-main-job.png   # the README's pictures: the main job's scene
cp "$work/tropical-coast-ground.png" docs/images/scene-main-job-ground.png
