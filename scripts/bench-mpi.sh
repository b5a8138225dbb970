#!/usr/bin/env bash
# Scaling from one MPI rank to two on this machine (make bench-mpi; README "MPI: paper-scale runs"):
# the same total of threads, 1 rank x T against 2 ranks x T/2, so the figure is what ranks cost
# against threads of one process: the pass agreement and the ordered image reduction (the rate is
# render's own, so start-up and the scene's load are outside it).
# Usage: bench-mpi.sh RENDER [SCENE] ; RUNS (default 3), SECONDS_PER_RUN (default 2) and THREADS (the
# total, default 2) from the environment. --bind-to none: with two processes or fewer mpirun binds
# each rank to one core, and a rank's threads would then share it.
set -euo pipefail
render=$1
scene=${2:-scenes/cornell-box/scene.json}
runs=${RUNS:-3}
seconds=${SECONDS_PER_RUN:-2}
threads=${THREADS:-2}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_btl_vader_single_copy_mechanism=${OMPI_MCA_btl_vader_single_copy_mechanism:-none}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The median over the runs of the rate in render's summary line (samples/s or mutations/s).
rate() {
  local np=$1 t=$2 method=$3 r=()
  for ((i = 0; i < runs; i++)); do
    r+=("$(mpirun -q --oversubscribe --bind-to none -np "$np" "$render" "$scene" --method "$method" --time "$seconds" --threads "$t" \
      --resolution 320x180 --max-length 8 --quiet --out "$tmp/x" | sed -n 's/.*, \([0-9]*\) \(samples\|mutations\)\/s.*/\1/p')")
  done
  printf '%s\n' "${r[@]}" | sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'
}

half=$((threads / 2 > 0 ? threads / 2 : 1))
echo "MPI scaling on $(nproc) cores, $scene at 320x180, max length 8, --time $seconds, median of $runs runs"
echo
echo "| method | unit | 1 rank x $threads threads | 2 ranks x $half threads | ratio |"
echo "|---|---|---:|---:|---:|"
for method in pt bdpt mmlt; do
  unit=samples/s
  [ "$method" = mmlt ] && unit=mutations/s
  one=$(rate 1 "$threads" "$method")
  two=$(rate 2 "$half" "$method")
  awk -v m="$method" -v u="$unit" -v a="$one" -v b="$two" 'BEGIN {printf "| %s | %s | %.0f | %.0f | %.3f |\n", m, u, a, b, b / a}'
done
