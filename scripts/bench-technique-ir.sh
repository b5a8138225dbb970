#!/usr/bin/env bash
# Instructions of PITP's technique move beside those of a small step (make bench; callgrind, since
# a virtual machine often has no hardware counter): bin/render on SCENE (default the Cornell box)
# at 48x48, one thread, seed 1, 10 000 seed paths. A small step: PITP at --pitp-rate 0 with
# --p-large 0 (every iteration one of MMLT's small steps), (Ir at 24 - Ir at 4 mutations per pixel)
# / (48 * 48 * 20), which cancels the seed pass and chain starts. A technique move: PITP at P = 1
# minus P = 0 (--p-large 0.1), same seed, 24 mutations per pixel (the same iterations, seed pass and
# chain starts), over the P = 1 run's perturbations (its CSV's pitp_perturbations). Only builds
# made the same way compare (PGO and LTO move these).
# usage: bench-technique-ir.sh BIN_DIR [SCENE.json]
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: bench-technique-ir.sh BIN_DIR [SCENE.json]" >&2; exit 2; }
bin=$1 scene=${2:-scenes/cornell-box/scene.json}
command -v valgrind >/dev/null || { echo "bench-technique-ir: no valgrind: instructions not measured"; exit 0; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
args() { echo "$scene --method pitp --pitp-rate $1 --p-large $2 --resolution 48x48 --threads 1 --seed 1 --seed-paths 10000 --spp $3"; }
# ir NAME RATE P_LARGE SPP: the run's instructions up to its image's writing (callgrind dumps them
# there; the encoding is not counted)
ir() {
  # shellcheck disable=SC2046
  valgrind --tool=callgrind --dump-before=img_write_exr_png --callgrind-out-file="$tmp/$1.out" "$bin/render" \
    $(args "$2" "$3" "$4") --out "$tmp/$1" --quiet >/dev/null 2>&1 || true
  awk '/^totals:/ { print $2 }' "$tmp/$1.out.1" 2>/dev/null
}
s4=$(ir small4 0 0 4) s24=$(ir small24 0 0 24) p0=$(ir p0 0 0.1 24) p1=$(ir p1 1 0.1 24)
[ -n "$s4" ] && [ -n "$s24" ] && [ -n "$p0" ] && [ -n "$p1" ] || { echo "bench-technique-ir: a callgrind run failed" >&2; exit 1; }
# the P = 1 run's perturbations, from the same run without valgrind (reproducible from its seed)
# shellcheck disable=SC2046
"$bin/render" $(args 1 0.1 24) --out "$tmp/p1" --quiet >/dev/null 2>&1
moves=$(awk '$2 == "pitp_perturbations" { print $3 }' "$tmp/p1.csv")
awk -v s4="$s4" -v s24="$s24" -v p0="$p0" -v p1="$p1" -v moves="$moves" -v scene="$scene" 'BEGIN {
  small = (s24 - s4) / (48 * 48 * 20); move = (p1 - p0) / moves
  printf "# %s at 48x48, 1 thread, callgrind instructions\n", scene
  printf "%-44s %12.0f   pitp --pitp-rate 0 --p-large 0, (24 - 4 per pixel)\n", "small step (instructions)", small
  printf "%-44s %12.0f   pitp P = 1 minus P = 0 per perturbation (%d), %.2fx a small step\n", "technique move (instructions)", move, moves, move / small
}'
