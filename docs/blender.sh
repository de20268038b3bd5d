#!/usr/bin/env bash
# Makes docs/images/blender-render.png (a 513² terrain added by the add-on, rendered by Cycles on
# the CPU: about a minute and a half on two cores) and docs/images/blender-panel.png (Blender's
# window with the Sidebar's Sansui panel, drawn in an X server with no screen, Xvfb), both through
# docs/blender_pictures.py, then cut to 256 colours so that each stays under 300 kB.
# Usage: docs/blender.sh [BUILD_DIR]   (default build; needs blender, xvfb-run, python3-pil)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
blender -b --factory-startup --python-exit-code 1 --python docs/blender_pictures.py -- \
  --build "$build" --render "$out/render.png"
xvfb-run -a -s '-screen 0 1280x800x24' blender --factory-startup --enable-event-simulate \
  --python-exit-code 1 --python docs/blender_pictures.py -- --build "$build" --panel "$out/panel.png"
for picture in render panel; do
  /usr/bin/python3 -c 'import sys; from PIL import Image
Image.open(sys.argv[1]).convert("RGB").quantize(256, method=Image.Quantize.MEDIANCUT).save(sys.argv[2], optimize=True)' \
    "$out/$picture.png" "docs/images/blender-$picture.png"
done
ls -l docs/images/blender-render.png docs/images/blender-panel.png
