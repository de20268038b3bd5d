#!/usr/bin/env bash
# The figures of docs/erosion.md's "Is it land? Measured": landform measures (water/landform.hpp)
# of the default terrain, raw and eroded, over seeds, and of each erosion stage.
# Usage: bench/real_land.sh [SEEDS] [SIZE]   (default 20 seeds of 1025x1025; needs scripts/build)
set -euo pipefail
cd "$(dirname "$0")/.."
seeds=${1:-20}
size=${2:-1025}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sansui=build/sansui
landform=build/bench/landform
for seed in $(seq 1 "$seeds"); do
  "$sansui" terrain --size "$size" --seed "$seed" --no-erode -o "$work/raw-$seed.r32" --quiet >/dev/null
  "$sansui" terrain --size "$size" --seed "$seed" -o "$work/eroded-$seed.r32" --quiet >/dev/null
done
echo "# raw (--no-erode)"
"$landform" --sea 0 "$work"/raw-*.r32
echo "# eroded (the default)"
"$landform" --sea 0 "$work"/eroded-*.r32
echo "# stages, seed 1"
for stage in original young mature old peneplain; do
  "$sansui" terrain --size "$size" --seed 1 --stage "$stage" -o "$work/stage-$stage.r32" --quiet >/dev/null
  "$landform" --sea 0 "$work/stage-$stage.r32" | tail -1
done
