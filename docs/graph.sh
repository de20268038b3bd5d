#!/usr/bin/env bash
# Makes the pictures of docs/recipes.md's graph section: the graph of each example of
# examples/scenes/graphs/ drawn by `sansui run --graph` and Graphviz (Debian's graphviz), and the
# scene each renders. Usage: docs/graph.sh  (needs scripts/build and graphviz)
set -euo pipefail
cd "$(dirname "$0")/.."
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for scene in mountain-in-landscape terraces-on-steep-slopes; do
  build/sansui run --graph "examples/scenes/graphs/$scene.toml" | dot -Tpng -Gdpi=72 -o "docs/images/graph-$scene.png"
  build/sansui run "examples/scenes/graphs/$scene.toml" --out-dir "$work" >/dev/null
  convert "$work/$scene.png" -resize 640x "docs/images/graph-$scene-render.png"
done
