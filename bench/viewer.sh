#!/usr/bin/env bash
# The viewer's speed under Xvfb with Mesa's software rasteriser (issue 12's figures):
#   1. frame time of the perspective pane of a 4097x4097 terrain at 1280x720: drawn in full every
#      frame (a still view) and while the camera orbits a degree a frame (half resolution), with
#      the scene's 1.1 M trees and without plants; and the same in the four-pane layout;
#   2. time from a change of H to the regenerated 1025x1025 terrain on screen (first picture and
#      full resolution), one pane and four.
# Usage: bench/viewer.sh (needs scripts/build; prints JSON lines)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
viewer() {
  xvfb-run -a -s '-screen 0 1280x760x24' build/sansui-viewer --no-recent --width 1280 --height 760 "$@"
}
frames() { python3 -c "import json,sys; r=json.load(open(sys.argv[1])); print(sys.argv[2], json.dumps(r['frames']))" "$@"; }
regenerations() {
  python3 -c "import json,sys; r=json.load(open(sys.argv[1])); print(sys.argv[2], json.dumps(r['regenerations'][1:]))" "$@"
}

big=examples/scenes/bench/full-scene-4097.toml
for plants in true false; do
  viewer --scene "$big" --report "$work/big.json" --script "set vegetation.enabled $plants; wait; panel off; view perspective; wait;
    measure 20; measure-orbit 40; layout four; panel on; wait; measure 10; measure-orbit 40"
  frames "$work/big.json" "4097x4097 plants=$plants [one pane still, one pane orbiting, four panes still, four panes orbiting]:"
done
viewer --report "$work/h.json" --script 'wait; set midpoint.hurst 0.6; wait; set midpoint.hurst 0.7; wait; set midpoint.hurst 0.75; wait;
  panel off; view perspective; wait; set midpoint.hurst 0.6; wait; set midpoint.hurst 0.7; wait; set midpoint.hurst 0.75; wait'
regenerations "$work/h.json" "H change at 1025x1025 [three with four panes, three with one]:"
