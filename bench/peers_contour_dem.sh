#!/usr/bin/env bash
# A DEM from a real contour map beside GRASS GIS r.surf.contour, on the same contours and grid,
# whole processes on the same machine in one run (issue 17 item 6). The real DEMs are
# matplotlib's Jacksboro fault sample (python-matplotlib-data, examples/dem/make_jacksboro.py):
#   - small: examples/dem/jacksboro_ridge.tif (110 x 111 cells of 74.5 m) and its 40 m contours
#     (examples/contours/jacksboro_40m.geojson, gdal_contour), rebuilt on the DEM's grid;
#   - full:  the whole sample (403 x 426 cells of 74.5 m), 20 m contours traced by gdal_contour,
#     rebuilt on the DEM's grid and on a 4x finer one (18.625 m, 1613 x 1705) for the timing.
# RMSE and MAE against the real DEM (on its own grid). GRASS gets the contours rasterised with
# v.to.rast (as r.surf.contour needs); only r.surf.contour itself is timed (bash's `time`), while
# Sansui is timed as a whole process (reading the GeoJSON and writing the DEM included). Both the
# wall-clock and the CPU seconds (user + system) are given: on a loaded machine the wall clock
# of a short process is mostly waiting for a core.
# Prints a Markdown table. Usage: bench/peers_contour_dem.sh [RUNS=3]   (needs build/sansui)
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-3}
sansui=${SANSUI:-$PWD/build/sansui}

scripts/setup --bench >&2  # grass-core, bc, python-matplotlib-data
command -v gdal_contour >/dev/null || apt-get install -y gdal-bin >&2
[[ -x "$sansui" ]] || scripts/build sansui_cli >&2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

cp examples/dem/jacksboro_ridge.tif "$work/small.tif"
cp examples/contours/jacksboro_40m.geojson "$work/small.geojson"
python3 -c "
import sys; sys.path.insert(0, 'examples/dem'); import make_jacksboro as m
m.COLUMNS = (0, 403); m.ROWS = (0, 344); sys.argv = ['', '$work/full.asc']; m.main()"
gdal_translate -q -of GTiff -ot Float32 "$work/full.asc" "$work/full.tif"
gdal_contour -q -a elev -i 20 "$work/full.tif" "$work/full.geojson" -f GeoJSON

# grass_case NAME RES: r.surf.contour of NAME.geojson on NAME.tif's extent at RES; prints
# "WALL CPU RMSE MAE" (medians; RMSE, MAE only on the DEM's own grid).
grass_case() {
  cat >"$work/grass.sh" <<GRASS
set -e
r.in.gdal input=$work/$1.tif output=real -o --quiet
g.region raster=real res=$2
v.in.ogr input=$work/$1.geojson output=c -o --quiet
v.to.rast input=c output=crast use=attr attribute_column=elev type=line --quiet
TIMEFORMAT='%R %U %S'
for i in \$(seq $runs); do { time r.surf.contour input=crast output=surf --overwrite --quiet; } 2>>$work/grass_times; done
g.region raster=real
r.mapcalc "d2 = (surf - real)^2" --quiet
r.mapcalc "d1 = abs(surf - real)" --quiet
echo "\$(r.univar -g d2 | sed -n 's/^mean=//p') \$(r.univar -g d1 | sed -n 's/^mean=//p')" > $work/grass_errors
GRASS
  rm -f "$work/grass_times"
  grass --tmp-location XY --exec bash "$work/grass.sh" >/dev/null 2>&1
  local seconds errors
  seconds=$(sort -g "$work/grass_times" | awk '{ a[NR] = $1; c[NR] = $2 + $3 } END { print a[int((NR + 1) / 2)], c[int((NR + 1) / 2)] }')
  read -r mse mae <"$work/grass_errors"
  echo "$seconds $(echo "sqrt($mse)" | bc -l) $mae"
}

# sansui_errors NAME: RMSE and MAE of $work/NAME.r32 against NAME's real DEM.
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

echo "uptime: $(uptime)"
echo
echo "| contours, grid | GRASS r.surf.contour: wall, CPU (s) | Sansui contour-dem, whole process: wall, CPU (s) | GRASS / Sansui: wall, CPU | RMSE GRASS / Sansui (m) | MAE GRASS / Sansui (m) |"
echo "|---|---|---|---|---|---|"
row() {  # row LABEL NAME RES SANSUI_GRID_ARGS...
  local label=$1 name=$2 res=$3
  shift 3
  read -r g_s g_cpu g_rmse g_mae <<<"$(grass_case "$name" "$res")"
  rm -f "$work/sansui_times"
  for ((i = 0; i < runs; i++)); do
    /usr/bin/time -a -o "$work/sansui_times" -f "%e %U %S" "$sansui" --quiet contour-dem "$work/$name.geojson" "$@" --dem "$work/$name.out.r32" >/dev/null
  done
  local s_s s_cpu
  read -r s_s s_cpu <<<"$(sort -g "$work/sansui_times" | awk '{ a[NR] = $1; c[NR] = $2 + $3 } END { print a[int((NR + 1) / 2)], c[int((NR + 1) / 2)] }')"
  local errors="- / -" mae="- / -"
  if [[ "$res" == "74.5" ]]; then
    read -r s_rmse s_mae <<<"$(errors_of "$name" "$name.out.r32")"
    errors=$(printf '%.2f / %.2f' "$g_rmse" "$s_rmse")
    mae=$(printf '%.2f / %.2f' "$g_mae" "$s_mae")
  fi
  printf '| %s | %.2f, %.2f | %.2f, %.2f | %.1f, %.1f | %s | %s |\n' "$label" "$g_s" "$g_cpu" "$s_s" "$s_cpu" "$(echo "$g_s / $s_s" | bc -l)" \
    "$(echo "$g_cpu / $s_cpu" | bc -l)" "$errors" "$mae"
}
row "Jacksboro ridge, 40 m contours, 110 x 111 cells of 74.5 m" small 74.5 --grid-from "$work/small.tif"
row "Jacksboro full, 20 m contours, 403 x 426 cells of 74.5 m" full 74.5 --grid-from "$work/full.tif"
row "Jacksboro full, 20 m contours, 1613 x 1705 cells of 18.625 m" full 18.625 --cell 18.625
echo
echo "(median of $runs runs; RMSE and MAE against the real DEM on its own grid; GRASS's time is r.surf.contour alone)"
