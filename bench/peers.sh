#!/usr/bin/env bash
# Times Sansui beside a real peer, whole processes on the same machine in the same run:
# GRASS GIS r.surf.fractal (spectral synthesis of fractal surfaces) against `sansui terrain`,
# both at SIZE x SIZE samples writing their result to disk. Prints a Markdown table.
# Usage: bench/peers.sh [SIZE=4097] [RUNS=3]      (needs build/sansui: scripts/build)
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-4097}
runs=${2:-3}

scripts/setup --bench >&2  # installs grass-core (GRASS GIS) and bc if missing
[[ -x build/sansui ]] || scripts/build >&2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

source bench/timing.sh

grass_job() {
  grass --tmp-location XY --exec bash -c \
    "g.region rows=$size cols=$size n=$size s=0 e=$size w=0 >/dev/null && r.surf.fractal output=fractal dimension=2.2 --quiet"
}
# The GRASS session's own start-up, timed alone so it can be subtracted.
grass_startup() { grass --tmp-location XY --exec bash -c "g.region rows=$size cols=$size n=$size s=0 e=$size w=0 >/dev/null"; }
sansui_job() { build/sansui terrain --size "$size" --hurst 0.8 -o "$work/terrain.r32"; }

sansui_s=$(median_seconds sansui_job)
grass_s=$(median_seconds grass_job)
startup_s=$(median_seconds grass_startup)
grass_net=$(echo "$grass_s - $startup_s" | bc -l)

echo "| ${size}x${size} fractal terrain, whole process, median of $runs | seconds | ratio to sansui |"
echo "|---|---:|---:|"
printf '| sansui terrain (midpoint displacement + additions, .r32) | %.3f | 1.0 |\n' "$sansui_s"
printf '| GRASS r.surf.fractal (spectral synthesis), with session start-up | %.3f | %.1fx |\n' "$grass_s" "$(echo "$grass_s / $sansui_s" | bc -l)"
printf '| GRASS r.surf.fractal, start-up (%.2f s) subtracted | %.3f | %.1fx |\n' "$startup_s" "$grass_net" "$(echo "$grass_net / $sansui_s" | bc -l)"
