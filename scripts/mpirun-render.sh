#!/usr/bin/env bash
# bin/render over MPI ranks, for a tool that runs the renderer as a process of its own:
#   bin/ch6_equal --render scripts/mpirun-render.sh ...
# (bin/ render built with `make MPI=1`). MPIRUN_ARGS: mpirun's options (default: 2 ranks, not bound
# to one core each, so that a rank's --threads spread). README "MPI: paper-scale runs".
set -euo pipefail
# shellcheck disable=SC2086  # MPIRUN_ARGS is a list of options
exec mpirun ${MPIRUN_ARGS:--np 2 --bind-to none} "$(dirname "$0")/../bin/render" "$@"
