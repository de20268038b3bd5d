#!/usr/bin/env bash
# Flow routing beside GRASS GIS on the same DEM, whole processes on the same machine in one run
# (issue 13): a SIZE x SIZE midpoint terrain (10 m cells, sea at 0 m) routed by
#   - Sansui: `sansui run` of a scene that reads the DEM and writes its flow map (depressions
#     routed over their passes, D8 receivers, stack, drainage area; 16-bit PNG out);
#   - GRASS: r.fill.dir (depressionless DEM and flow directions) and r.watershed (flow
#     accumulation, drainage directions, basins), each on the imported DEM.
# The GRASS session's start-up and the import are timed alone and subtracted; so is Sansui's
# reading and writing (a scene with a heightmap output only). Prints a Markdown table.
# Usage: bench/peers_flow.sh [SIZE=4097] [RUNS=3]      (needs build/sansui: scripts/build)
#   SKIP_FILL=1 leaves out r.fill.dir (about 200 s a run at 4097^2; r.watershed is the goal's peer)
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-4097}
runs=${2:-3}

scripts/setup --bench >&2  # installs grass-core (GRASS GIS) and bc if missing
[[ -x build/sansui ]] || scripts/build >&2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
sansui=$PWD/build/sansui

"$sansui" terrain --size "$size" --cell 10 --seed 7 -o "$work/dem.r32" >/dev/null
scene() {  # scene FILE KIND: the DEM in, one output of KIND out
  cat >"$work/$1.toml" <<TOML
sansui_recipe = 1
source = "file"
[file]
path = "dem.r32"
[flow]
sea_level = 0.0
[[output]]
file = "$1.$3"
kind = "$2"
TOML
}
scene flow flow_map png
scene copy heightmap r32

source bench/timing.sh

region="g.region rows=$size cols=$size n=$((size * 10)) s=0 e=$((size * 10)) w=0 res=10 >/dev/null"
import="r.in.bin -f input=$work/dem.r32 output=dem bytes=4 order=little north=$((size * 10)) south=0 east=$((size * 10)) west=0 rows=$size cols=$size --quiet"
grass_with() { grass --tmp-location XY --exec bash -c "$region && $import && $1"; }
grass_import() { grass_with "true"; }
grass_fill() { grass_with "r.fill.dir input=dem output=filled direction=dir --quiet"; }
grass_watershed() { grass_with "r.watershed elevation=dem accumulation=acc drainage=drain basin=basin threshold=10000 --quiet"; }
grass_watershed_d8() { grass_with "r.watershed -s elevation=dem accumulation=acc drainage=drain basin=basin threshold=10000 --quiet"; }
sansui_flow() { (cd "$work" && "$sansui" run flow.toml); }
sansui_copy() { (cd "$work" && "$sansui" run copy.toml); }

sansui_s=$(median_seconds sansui_flow)
copy_s=$(median_seconds sansui_copy)
import_s=$(median_seconds grass_import)
fill_s=$([[ -n "${SKIP_FILL:-}" ]] && echo "$import_s" || median_seconds grass_fill)
watershed_s=$(median_seconds grass_watershed)
watershed_d8_s=$(median_seconds grass_watershed_d8)
net() { echo "$1 - $2" | bc -l; }
sansui_net=$(net "$sansui_s" "$copy_s")
fill_net=$(net "$fill_s" "$import_s")
watershed_net=$(net "$watershed_s" "$import_s")
watershed_d8_net=$(net "$watershed_d8_s" "$import_s")

echo "uptime: $(uptime)"
echo
echo "| ${size}x${size} DEM | whole process (s) | minus start-up, reading and writing (s) | GRASS / Sansui |"
echo "|---|---|---|---|"
printf '| Sansui flow map (routed over depressions, D8, drainage area) | %.2f | %.2f | 1 |\n' "$sansui_s" "$sansui_net"
[[ -n "${SKIP_FILL:-}" ]] ||
  printf '| GRASS r.fill.dir | %.2f | %.2f | %.1f |\n' "$fill_s" "$fill_net" "$(echo "$fill_net / $sansui_net" | bc -l)"
printf '| GRASS r.watershed (multiple flow directions, its default) | %.2f | %.2f | %.1f |\n' "$watershed_s" "$watershed_net" "$(echo "$watershed_net / $sansui_net" | bc -l)"
printf '| GRASS r.watershed -s (single flow direction, D8) | %.2f | %.2f | %.1f |\n' "$watershed_d8_s" "$watershed_d8_net" "$(echo "$watershed_d8_net / $sansui_net" | bc -l)"
echo
echo "(median of $runs runs; GRASS start-up + import: ${import_s} s; Sansui read + write of the DEM alone: ${copy_s} s)"
