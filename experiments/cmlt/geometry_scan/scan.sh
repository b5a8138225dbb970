#!/usr/bin/env bash
# One candidate of the CMLT toy's geometry scan (../README.md): copies the toy's sources, overrides
# constants of cmlt_scene.h (NAME=VALUE for #define CMLT_NAME; K1 also sets EXPK1), builds scan.c
# against them and the built core (run `make` first) and prints PSS-MLT-1 and -2's RMSE and ratio.
# usage: experiments/cmlt/geometry_scan/scan.sh N_MILLIONS SEEDS REF_SPP [NAME=VALUE ...]
# e.g.   experiments/cmlt/geometry_scan/scan.sh 16 8 4096 A1=0.11
set -euo pipefail
root=$(cd "$(dirname "$0")/../../.." && pwd)
nm=$1 ns=$2 spp=$3
shift 3
d=$(mktemp -d)
trap 'rm -rf "$d"' EXIT
mkdir -p "$d/cmlt"
cp "$root"/experiments/cmlt/*.[ch] "$d/cmlt/"
for kv in "$@"; do
  k=${kv%%=*} v=${kv#*=}
  grep -q "^#define CMLT_$k " "$d/cmlt/cmlt_scene.h" || { echo "scan.sh: no constant CMLT_$k in cmlt_scene.h" >&2; exit 2; }
  sed -i "s|^#define CMLT_$k .*|#define CMLT_$k $v|" "$d/cmlt/cmlt_scene.h"
  if [ "$k" = K1 ]; then
    e=$(awk -v k="$v" 'BEGIN { printf "%.17g", exp(k) }')
    sed -i "s|^#define CMLT_EXPK1 .*|#define CMLT_EXPK1 $e|" "$d/cmlt/cmlt_scene.h"
  fi
done
cc -I"$d" -I"$root/core" -I"$root/experiments" -I"$root/build" -D_DEFAULT_SOURCE -std=c11 -O3 -fno-math-errno -pthread \
  -o "$d/scan" "$root/experiments/cmlt/geometry_scan/scan.c" \
  "$d"/cmlt/cmlt_charts.c "$d"/cmlt/cmlt_mcmc.c "$d"/cmlt/cmlt_reference.c "$d"/cmlt/cmlt_scene.c \
  "$root/experiments/common/die.c" \
  "$root/build/libcore.a" -lembree3 -lcjson -lgsl -lgslcblas -lOpenEXRCore -lpng -lm -ldl
echo "[$*] $("$d/scan" "$nm" "$ns" "$spp")"
