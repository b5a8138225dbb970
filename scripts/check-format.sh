#!/usr/bin/env bash
# Every git-tracked C and C++ source against the project's .clang-format, under clang-format 14 (the
# version the layout is written for: another version lays some constructs out differently). Run by
# `make lint`. Prints clang-format's diagnostics, then one summary line; with --list, only the names
# of the files that differ, one a line. Exit status 1 when any file differs. Reformats nothing.
#
#   scripts/check-format.sh [--list]      CLANG_FORMAT=... picks the binary (default clang-format-14)
set -euo pipefail
cd "$(dirname "$0")/.."
cf=${CLANG_FORMAT:-clang-format-14}
list=0
case "${1:-}" in
  --list) list=1 ;;
  "") ;;
  *) echo "check-format: unknown option '$1' (expected --list)" >&2; exit 2 ;;
esac
command -v "$cf" > /dev/null || { echo "check-format: $cf not found (scripts/install-deps.sh --lint)" >&2; exit 2; }
mapfile -t files < <(git ls-files '*.c' '*.h' '*.cpp')
# One clang-format process for every file (one per file is minutes on a loaded machine); its
# diagnostics start "FILE:LINE:COL: error:", which names the files that differ.
log=$(mktemp)
trap 'rm -f "$log"' EXIT
rc=0
"$cf" --dry-run --Werror "${files[@]}" 2> "$log" || rc=$?
[ $list = 1 ] || cat "$log" >&2
mapfile -t bad < <(sed -n 's/^\([^:]*\):[0-9]*:[0-9]*: error:.*/\1/p' "$log" | sort -u)
if [ $rc -ne 0 ] && [ ${#bad[@]} -eq 0 ]; then
  cat "$log" >&2
  echo "check-format: $cf failed without naming a file (exit status $rc)" >&2
  exit 2
fi
[ $list = 1 ] && [ ${#bad[@]} -gt 0 ] && printf '%s\n' "${bad[@]}"
if [ ${#bad[@]} -gt 0 ]; then
  echo "check-format: ${#bad[@]} of ${#files[@]} files differ from .clang-format ($cf -i FILE rewrites one)" >&2
  exit 1
fi
echo "check-format: ${#files[@]} files laid out as .clang-format says"
