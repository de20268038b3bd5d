#!/usr/bin/env bash
# A DEM from a real contour map beside GRASS GIS r.surf.contour, on the same contours and grid,
# both measured in one run on the same machine (issue 17 items 6 and 7). The real DEMs are
# matplotlib's Jacksboro fault sample (python-matplotlib-data, examples/dem/make_jacksboro.py):
#   - small: examples/dem/jacksboro_ridge.tif (110 x 111 cells of 74.5 m) and its 40 m contours
#     (examples/contours/jacksboro_40m.geojson, gdal_contour), rebuilt on the DEM's grid;
#   - full:  the whole sample (403 x 426 cells of 74.5 m), 20 m contours traced by gdal_contour,
#     rebuilt on the DEM's grid and on a 4x finer one (18.625 m; the real DEM resampled bilinearly
#     to it is the reference there).
# Like is timed with like, three ways (medians of RUNS):
#   whole      each tool's whole process: `r.surf.contour` (GRASS gets the contours rasterised by
#              v.to.rast first, untimed, as r.surf.contour needs) and `sansui contour-dem` (which
#              also parses the GeoJSON and rasterises the lines itself);
#   - start-up each whole process less the same process on a 2 x 2 grid (GRASS: r.surf.contour
#              with g.region rows=2 cols=2; Sansui: contour-dem of one short line, --dem-size 2);
#   step       GRASS's whole less start-up (its raster read and write included) beside Sansui's
#              interpolation alone, the library call on the parsed lines (bench_contour_dem
#              ContourMapToDem_File, 1 and 2 threads).
# RMSE and MAE against the real DEM on its own grid. Wall-clock seconds; the load average is
# printed before and after (the figures mean little above about 1.3 on the 2-core machine).
# Prints a Markdown table. Usage: bench/peers_contour_dem.sh [RUNS=3]
#   SANSUI=build/sansui BENCH=build/bench/bench_contour_dem (both Release builds)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
sansui=${SANSUI:-$PWD/build/sansui}
bench=${BENCH:-$PWD/build/bench/bench_contour_dem}

scripts/setup --bench >&2  # grass-core, bc, python-matplotlib-data
command -v gdal_contour >/dev/null || apt-get install -y gdal-bin >&2
[[ -x "$sansui" ]] || scripts/build sansui_cli >&2
[[ -x "$bench" ]] || scripts/build bench_contour_dem >&2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cp examples/dem/jacksboro_ridge.tif "$work/small.tif"
cp examples/contours/jacksboro_40m.geojson "$work/small.geojson"
python3 -c "
import sys; sys.path.insert(0, 'examples/dem'); import make_jacksboro as m
m.COLUMNS = (0, 403); m.ROWS = (0, 344); sys.argv = ['', '$work/full.asc']; m.main()"
gdal_translate -q -of GTiff -ot Float32 "$work/full.asc" "$work/full.tif"
gdal_contour -q -a elev -i 20 "$work/full.tif" "$work/full.geojson" -f GeoJSON
# The fine grid: the real DEM resampled bilinearly to 4x finer cells, the grid both tools rebuild
# on and the reference both are measured against there.
gdalwarp -q -r bilinear -tr 18.625 18.625 "$work/full.tif" "$work/fine.tif"
cp "$work/full.geojson" "$work/fine.geojson"
echo '{"type":"FeatureCollection","features":[{"type":"Feature","properties":{"elev":1},"geometry":{"type":"LineString","coordinates":[[0,0],[10,10]]}}]}' >"$work/tiny.geojson"

median() { sort -g | awk '{ a[NR] = $1 } END { print a[int((NR + 1) / 2)] }'; }

# grass_case NAME RES: r.surf.contour of NAME.geojson on NAME.tif's extent at RES; prints
# "WHOLE STARTUP RMSE MAE" (RMSE, MAE only on the DEM's own grid).
grass_case() {
  cat >"$work/grass.sh" <<GRASS
set -e
r.in.gdal input=$work/$1.tif output=real -o --quiet
g.region raster=real res=$2
v.in.ogr input=$work/$1.geojson output=c -o --quiet
v.to.rast input=c output=crast use=attr attribute_column=elev type=line --quiet
TIMEFORMAT='%R'
for i in \$(seq $runs); do { time r.surf.contour input=crast output=surf --overwrite --quiet; } 2>>$work/grass_whole; done
g.region raster=real
r.mapcalc "d2 = (surf - real)^2" --quiet
r.mapcalc "d1 = abs(surf - real)" --quiet
echo "\$(r.univar -g d2 | sed -n 's/^mean=//p') \$(r.univar -g d1 | sed -n 's/^mean=//p')" > $work/grass_errors
g.region rows=2 cols=2
for i in \$(seq $runs); do { time r.surf.contour input=crast output=tiny --overwrite --quiet; } 2>>$work/grass_startup; done
GRASS
  rm -f "$work/grass_whole" "$work/grass_startup"
  grass --tmp-location XY --exec bash "$work/grass.sh" >/dev/null 2>&1
  read -r mse mae <"$work/grass_errors"
  echo "$(median <"$work/grass_whole") $(median <"$work/grass_startup") $(echo "sqrt($mse)" | bc -l) $mae"
}

# errors_of NAME OUT: RMSE and MAE of $work/OUT (.r32) against NAME's real DEM.
errors_of() {
  gdal_translate -q -of ENVI -ot Float32 "$work/$1.tif" "$work/$1_real.bin"
  python3 - "$work/$2" "$work/$1_real.bin" <<'PY'
import math, struct, sys
read = lambda p: struct.unpack("<%df" % (len(open(p, "rb").read()) // 4), open(p, "rb").read())
a, b = read(sys.argv[1]), read(sys.argv[2])
d = [x - y for x, y in zip(a, b)]
print(math.sqrt(sum(x * x for x in d) / len(d)), sum(abs(x) for x in d) / len(d))
PY
}

# seconds COMMAND...: wall-clock seconds of COMMAND, the median of $runs runs.
seconds() {
  for ((i = 0; i < runs; i++)); do /usr/bin/time -f "%e" -o "$work/t" "$@" >/dev/null 2>&1 && cat "$work/t"; done | median
}

# step NAME [CELL]: the interpolation alone (ms, median of its repetitions), 1 and 2 threads.
step() {
  SANSUI_CONTOUR_MAP="$work/$1.geojson" SANSUI_CONTOUR_GRID="$work/$1.tif" SANSUI_CONTOUR_CELL="${2:-}" \
    "$bench" --benchmark_filter=ContourMapToDem_File --benchmark_repetitions="$runs" --benchmark_report_aggregates_only=true \
    --benchmark_format=csv 2>/dev/null | awk -F, '/_median/ { gsub(/"/, "", $1); print $3 / 1000 }' | tr '\n' ' '
}

echo "uptime before: $(uptime)"
echo
echo "| contours, grid | GRASS r.surf.contour whole, less start-up (s) | Sansui contour-dem whole, less start-up (s) | Sansui interpolation, 1 and 2 threads (s) | GRASS / Sansui: whole, less start-up, step (2 threads) | RMSE GRASS / Sansui (m) | MAE GRASS / Sansui (m) |"
echo "|---|---|---|---|---|---|---|"
row() {  # row LABEL NAME RES [CELL] -- SANSUI_GRID_ARGS...
  local label=$1 name=$2 res=$3 cell=$4
  shift 5
  read -r g_whole g_start g_rmse g_mae <<<"$(grass_case "$name" "$res")"
  local s_whole s_start s_one s_two
  s_whole=$(seconds "$sansui" --quiet contour-dem "$work/$name.geojson" "$@" --dem "$work/$name.out.r32")
  s_start=$(seconds "$sansui" --quiet contour-dem "$work/tiny.geojson" --dem-size 2 --dem "$work/tiny.out.r32")
  read -r s_one s_two <<<"$(step "$name" "$cell")"
  local errors="- / -" mae="- / -"
  if [[ -z "$cell" ]]; then
    read -r s_rmse s_mae <<<"$(errors_of "$name" "$name.out.r32")"
    errors=$(printf '%.2f / %.2f' "$g_rmse" "$s_rmse")
    mae=$(printf '%.2f / %.2f' "$g_mae" "$s_mae")
  fi
  local g_less s_less
  g_less=$(echo "$g_whole - $g_start" | bc -l)
  s_less=$(echo "$s_whole - $s_start" | bc -l)
  printf '| %s | %.3f, %.3f | %.3f, %.3f | %.4f, %.4f | %.1f, %.1f, %.1f | %s | %s |\n' "$label" "$g_whole" "$g_less" "$s_whole" "$s_less" \
    "$s_one" "$s_two" "$(echo "$g_whole / $s_whole" | bc -l)" "$(echo "$g_less / $s_less" | bc -l)" "$(echo "$g_less / $s_two" | bc -l)" \
    "$errors" "$mae"
}
row "Jacksboro ridge, 40 m contours (117 lines), 110 x 111 cells of 74.5 m" small 74.5 "" -- --grid-from "$work/small.tif"
row "Jacksboro full, 20 m contours (1,745 lines), 403 x 426 cells of 74.5 m" full 74.5 "" -- --grid-from "$work/full.tif"
row "the same contours, 1612 x 1704 cells of 18.625 m" fine 18.625 "" -- --grid-from "$work/fine.tif"
echo
echo "uptime after: $(uptime)"
echo "(medians of $runs runs; RMSE and MAE against the real DEM on its own grid, and on the fine grid against the real DEM resampled bilinearly to it)"
