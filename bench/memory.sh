#!/usr/bin/env bash
# Peak memory (maximum resident set) of terrain generation, whole processes, beside the size of
# the float32 grid itself. Prints a Markdown table. Usage: bench/memory.sh  (needs scripts/build)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup --bench >&2  # GNU time
[[ -x build/sansui ]] || scripts/build >&2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Prints "peak_MiB seconds" of a command.
measure() {
  /usr/bin/time -f '%M %e' -o "$work/time" "$@" >/dev/null 2>&1
  awk '{ printf "%.1f %.2f\n", $1 / 1024, $2 }' "$work/time"
}
grid_mib() { echo "$1 * $1 * 4 / 1048576" | bc -l; }

echo "| job | peak MiB | seconds | float32 grid MiB | peak / grid |"
echo "|---|---:|---:|---:|---:|"
row() {
  local label=$1 side=$2
  shift 2
  read -r peak seconds < <(measure "$@")
  local grid
  grid=$(grid_mib "$side")
  printf '| %s | %s | %s | %.1f | %.2f |\n' "$label" "$peak" "$seconds" "$grid" "$(echo "$peak / $grid" | bc -l)"
}
row "8193x8193 terrain to .r32" 8193 build/sansui terrain --size 8193 -o "$work/big.r32"
row "4097x4097 terrain to .r32" 4097 build/sansui terrain --size 4097 -o "$work/mid.r32"
row "one 4097 tile (7,9) of a 65537 world to .r32" 4097 \
  build/sansui terrain --world-size 65537 --tile 7,9 --tile-size 4097 -o "$work/tile.r32"
