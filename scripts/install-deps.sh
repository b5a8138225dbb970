#!/usr/bin/env bash
# Installs exactly the Debian packages the harness needs; does nothing when they are all present.
# Used by the README's set-up, by `make` (deps target), by `make report` (with --report), by
# `make MPI=1` (with --mpi), by `make fuzz` (with --fuzz), by `make lint` (with --lint) and by .ci/run.
set -euo pipefail
pkgs=(
  build-essential pkg-config
  libembree-dev            # ray casting (Embree 3)
  libopenimageio-dev openimageio-tools   # reading images (textures, references), image comparison tools
  libopenexr-dev libpng-dev              # writing EXR and PNG (core/io/image_encode.h)
  libgsl-dev               # statistics: chi-square, normal quantiles
  libcjson-dev             # scene JSON
  libcriterion-dev         # test framework
  gnuplot-nox              # figures
  fonts-dejavu-core        # labels in oiiotool montages (cmlt-montage.sh)
)
# `--report`: also the browser that checks results/report/index.html (make report, CI); large, so
# only when asked. `--mpi`: Open MPI's compiler wrapper, headers and mpirun, for `make MPI=1`
# (README "MPI: paper-scale runs"); the default build does not use them. `--fuzz`: clang 14 and
# its libFuzzer runtime, for `make fuzz` (tests/README.md, "Fuzzing") and CI. `--lint`: clang-format 14,
# the version the sources' layout is checked with (`make lint`).
for arg in "$@"; do
  case "$arg" in
    --report) pkgs+=(chromium) ;;
    --mpi) pkgs+=(libopenmpi-dev openmpi-bin) ;;
    --fuzz) pkgs+=(clang-14 libfuzzer-14-dev) ;;
    --lint) pkgs+=(clang-format-14) ;;
    *) echo "install-deps: unknown option '$arg' (expected --report, --mpi, --fuzz or --lint)" >&2; exit 2 ;;
  esac
done
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
