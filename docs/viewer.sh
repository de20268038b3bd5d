#!/usr/bin/env bash
# Makes docs/viewer.png: the viewer's four panes (front, side, top, perspective) and its
# parameter panel on examples/scenes/island.toml in autumn, drawn in an X server with no screen
# (Xvfb) by the viewer's own scripted mode. Usage: docs/viewer.sh (needs scripts/build)
set -euo pipefail
cd "$(dirname "$0")/.."
xvfb-run -a -s '-screen 0 1440x860x24' build/sansui-viewer --no-recent --width 1440 --height 860 \
  --scene examples/scenes/island.toml \
  --script 'wait; set season.season autumn; set land.snow_line 0.7; orbit 215 28 0; wait; screenshot docs/viewer.png'
