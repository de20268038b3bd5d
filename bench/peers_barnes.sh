#!/usr/bin/env bash
# One landscape-evolution step beside Barnes's reference code, in one run on one machine
# (issue 32): Richard Barnes, "Accelerating a fluvial incision and landscape evolution model with
# parallelism", Geomorphology 330 (2019), code at github.com/r-barnes/Barnes2019-Landscape.
#   - fastscape_RB    serial, and fastscape_RB+P  OpenMP on 2 threads, built with
#     g++ -O3 -march=native (-fopenmp) outside the project, run on SIZE x SIZE for STEPS steps
#     (its own random terrain; per step = ("Overall" - "Initialize") / STEPS: its set-up excluded);
#   - Sansui's step (bench_water StreamPowerStep: routing across depressions, incision,
#     deposition, diffusion) and the in-tree plain FastScape step (Reference_FastScapeStep).
# Nothing is downloaded: give the path of a checkout (or a bare git directory, as `fetch` leaves).
# Usage: bench/peers_barnes.sh BARNES_REPO [SIZE=4097] [STEPS=5] [RUNS=5]
#   BENCH=build/bench/bench_water (a Release build)
set -euo pipefail
cd "$(dirname "$0")/.."
repo=${1:?the path of a Barnes2019-Landscape checkout or git directory}
size=${2:-4097}
steps=${3:-5}
runs=${4:-5}
bench=${BENCH:-$PWD/build/bench/bench_water}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

if [[ -d "$repo/.git" || -f "$repo/HEAD" ]]; then
  git --git-dir="$(git -C "$repo" rev-parse --absolute-git-dir 2>/dev/null || echo "$repo")" archive HEAD | tar -x -C "$work"
else
  cp -r "$repo"/. "$work"
fi
defines=(-DGIT_HASH='"peers"' -DCOMPILE_TIME='"peers"')
(cd "$work" && g++ -O3 -march=native "${defines[@]}" -o rb CumulativeTimer.cpp random.cpp fastscape_RB.cpp -Wno-unknown-pragmas &&
  g++ -O3 -march=native "${defines[@]}" -o rbp CumulativeTimer.cpp random.cpp fastscape_RB+P.cpp -fopenmp) >&2

echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
per_step() {  # per_step EXE THREADS: median seconds per step over RUNS runs
  for ((r = 0; r < runs; ++r)); do
    OMP_NUM_THREADS=$2 "$work/$1" "$size" "$steps" "$work/out" 1 2>&1 |
      awk -v s="$steps" '/Initialize/ {init = $(NF-1)} /Overall/ {print ($(NF-1) - init) / 1e6 / s}'
  done | sort -n | awk '{v[NR]=$1} END {printf "%.3f (%.3f-%.3f)", v[int((NR+1)/2)], v[1], v[NR]}'
}
echo "| code | threads | s per step at ${size}² (median, min-max of $runs) | ns per cell-step |"
echo "|---|---|---|---|"
for spec in "rb 1" "rbp 2"; do
  set -- $spec
  t=$(per_step "$1" "$2")
  echo "| Barnes fastscape_$([[ $1 == rb ]] && echo RB || echo RB+P) | $2 | $t | $(awk -v t="${t%% *}" -v n="$size" 'BEGIN {printf "%.0f", t * 1e9 / (n * n)}') |"
done
"$bench" --benchmark_filter='Reference_FastScapeStep|StreamPowerStep|FlowRouting' --benchmark_repetitions="$runs" \
  --benchmark_format=csv 2>/dev/null | awk -F, -v n="$size" '/_median"/ {gsub(/"/, "", $1); printf "| Sansui %s | %d | %.3f | %.0f |\n", $1, ($1 ~ /Reference/ ? 1 : 2), $3 / 1e3, $3 * 1e6 / (n * n)}'
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
