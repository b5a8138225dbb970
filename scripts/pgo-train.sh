#!/usr/bin/env bash
# Training renders for profile-guided optimisation (Makefile, PGO=1): every estimator on the
# Cornell box at the benchmark's settings, plus scenes that reach the other BSDFs, the
# environment map and MCTLS, so their code is profiled too rather than left to the defaults.
# Fixed seeds, spp and one thread: the profile, and so the build, is the same on every run.
# usage: pgo-train.sh RENDER OUTDIR
set -euo pipefail
render=$1 out=$2
mkdir -p "$out"
r() { "$render" "$@" --seed 1 --threads 1 --quiet --out "$out/img" >/dev/null; }
box=scenes/cornell-box/scene.json
r "$box" --method pt --spp 8 --resolution 320x180
r "$box" --method bdpt --spp 2 --resolution 320x180
r "$box" --method pssmlt --spp 2 --resolution 320x180 --seed-paths 20000
r "$box" --method mmlt --spp 16 --resolution 320x180 --seed-paths 20000
for scene in materials sky-courtyard ajar; do
  for m in pt bdpt; do r "scenes/$scene/scene.json" --method $m --spp 2 --resolution 64x36; done
  for m in pssmlt mmlt; do r "scenes/$scene/scene.json" --method $m --spp 2 --resolution 64x36 --seed-paths 20000; done
done
r scenes/ajar/scene.json --method mmlt --large-step mctls --spp 4 --resolution 64x36 --seed-paths 20000
