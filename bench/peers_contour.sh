#!/usr/bin/env bash
# Contours to DEM beside a real peer, whole processes on the same machine in the same run:
# GRASS GIS r.surf.contour (the approach our rasteriser follows: interpolation between the
# nearest lower and upper contour) against `sansui contour --dem`, on the same contours, at
# SIZE x SIZE cells. GRASS gets the contours as lines rasterised with v.to.rast; only
# r.surf.contour itself is timed. Sansui is timed as a whole process that also generates the
# contours (revised method) and writes the DEM. Prints a Markdown table.
# Usage: bench/peers_contour.sh [SIZE=1025] [RUNS=3] [GRASS_RUNS=1]   (needs build/sansui: scripts/build)
# (r.surf.contour takes minutes at 1025: one GRASS run is the default.)
set -euo pipefail
cd "$(dirname "$0")/.."
size=${1:-1025}
runs=${2:-3}
grass_runs=${3:-1}
seed=examples/contours/ridge.geojson
contour_args=(--offset 10 --interval 10)

scripts/setup --bench >&2  # grass-core, bc
[[ -x build/sansui ]] || scripts/build >&2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }
seconds_of() {  # wall-clock seconds of one run of a command
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}

# The contours, and the same contours as closed lines for GRASS.
build/sansui contour "$seed" "${contour_args[@]}" --contours "$work/mountain.geojson" >&2
python3 - "$work/mountain.geojson" "$work/lines.geojson" <<'PY'
import json, sys
features = json.load(open(sys.argv[1]))["features"]
lines = [{"type": "Feature", "properties": {"elevation": f["properties"]["elevation_m"]},
          "geometry": {"type": "LineString", "coordinates": f["geometry"]["coordinates"][0]}} for f in features]
json.dump({"type": "FeatureCollection", "features": lines}, open(sys.argv[2], "w"))
PY

sansui_job() { build/sansui contour "$seed" "${contour_args[@]}" --dem "$work/dem.r32" --dem-size "$size"; }
sansui_job >"$work/sansui.log" 2>&1  # warm-up, and the DEM size for the table
sansui_times=()
for ((i = 0; i < runs; i++)); do sansui_times+=("$(seconds_of sansui_job)"); done
sansui_s=$(printf '%s\n' "${sansui_times[@]}" | median)

# GRASS: import, rasterise the lines on a grid of the same extent and size, then time r.surf.contour.
cat >"$work/grass.sh" <<SH
set -e
v.in.ogr input=$work/lines.geojson output=contours -o --quiet
g.region vector=contours
eval \$(g.region -g)
pad=\$(echo "(\$e - \$w) * 0.05" | bc -l)
g.region n=\$(echo "\$n + \$pad" | bc -l) s=\$(echo "\$s - \$pad" | bc -l) e=\$(echo "\$e + \$pad" | bc -l) w=\$(echo "\$w - \$pad" | bc -l)
eval \$(g.region -g)
g.region res=\$(echo "if (\$e - \$w > \$n - \$s) (\$e - \$w) / ($size - 1) else (\$n - \$s) / ($size - 1)" | bc -l)
eval \$(g.region -g)
echo "\$rows \$cols" > $work/grass_size
v.to.rast input=contours output=lines type=line use=attr attribute_column=elevation --quiet
for i in \$(seq $grass_runs); do
  start=\$(date +%s.%N)
  r.surf.contour input=lines output=dem_\$i --quiet
  end=\$(date +%s.%N)
  echo "\$end - \$start" | bc -l >> $work/grass_times
done
SH
grass --tmp-location XY --exec bash "$work/grass.sh" >/dev/null 2>&1
grass_s=$(median <"$work/grass_times")

read -r grass_rows grass_cols <"$work/grass_size"
echo "| contours to DEM, longer side $size cells | cells | seconds | ratio to sansui |"
echo "|---|---:|---:|---:|"
printf '| sansui contour --dem (whole process: generate + rasterise + write), median of %d | %s | %.3f | 1.0 |\n' "$runs" "$(sed -n 's/.*DEM \([0-9]*x[0-9]*\).*/\1/p' "$work/sansui.log")" "$sansui_s"
printf '| GRASS r.surf.contour (the module alone, same contours), median of %d | %sx%s | %.3f | %.1fx |\n' "$grass_runs" "$grass_cols" "$grass_rows" "$grass_s" "$(echo "$grass_s / $sansui_s" | bc -l)"
