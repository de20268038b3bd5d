#!/usr/bin/env bash
# Tiled worlds over MPI ranks on this machine (docs/worlds.md): strong scaling (4097^2, 1 and 2
# ranks), weak scaling (2 ranks, 4097^2 and 8193^2), a large world on 4 ranks, each rank's peak
# memory, and the untiled runs of the same worlds for reference.
# Usage: bench/worlds.sh BUILD_DIR OUT_DIR [SIZE:TILE_SIZE:RANKS ...]
set -euo pipefail
build=$(realpath "$1")
out=$(realpath -m "$2")
shift 2
cases=("$@")
[[ ${#cases[@]} -gt 0 ]] || cases=(4097:1025:1 4097:1025:2 8193:2049:2 8193:2049:4)
mkdir -p "$out"
peak='import resource,subprocess,sys,os,time;t=time.time();c=subprocess.call(sys.argv[1:],stdout=subprocess.DEVNULL);print("rank",os.environ.get("OMPI_COMM_WORLD_RANK","-"),"peak_MB",resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss//1000,"seconds",round(time.time()-t,1),flush=True);sys.exit(c)'
recipe() {  # SIZE TILE_SIZE TILED
  printf 'sansui_recipe = 4\nsource = "midpoint"\n\n[world]\nsize = %s\ntile_size = %s\n%s\n\n[[shape]]\nstep = "erode"\n\n[[output]]\nfile = "heights.%s"\nkind = "heightmap"\n' \
    "$1" "$2" "$([[ $3 == 1 ]] && echo 'tiled = true')" "$([[ $3 == 1 ]] && echo vrt || echo tif)"
}
for c in "${cases[@]}"; do
  IFS=: read -r size tile ranks <<<"$c"
  recipe "$size" "$tile" 1 >"$out/tiled_$size.toml"
  echo "== $size^2 in tiles of $tile samples, $ranks ranks (load $(cut -d' ' -f1 /proc/loadavg))"
  start=$(date +%s.%N)
  mpirun --allow-run-as-root --oversubscribe -np "$ranks" /usr/bin/python3 -c "$peak" "$build/sansui" run "$out/tiled_$size.toml" \
    --out-dir "$out/tiled_${size}_$ranks" | sort
  echo "wall $(echo "$(date +%s.%N) - $start" | bc) s"
done
if [[ "${UNTILED:-1}" == 1 ]]; then
  for size in $(printf '%s\n' "${cases[@]}" | cut -d: -f1 | sort -u); do
    [[ $size -le 16385 ]] || continue
    recipe "$size" 1025 0 >"$out/whole_$size.toml"
    echo "== $size^2 untiled (load $(cut -d' ' -f1 /proc/loadavg))"
    /usr/bin/python3 -c "$peak" "$build/sansui" run "$out/whole_$size.toml" --out-dir "$out/whole_$size"
  done
fi
