#!/usr/bin/env bash
# The full-scale runs' text outputs, kept in git: a full-scale ledger takes ~8 h of 2 cores, more than
# one sitting, and results/ is not committed. `save DIR...` copies every CSV and Markdown file under
# each results/ folder given (per-run files included, images left out) into results/baselines/full-record/,
# mirrored; `restore` copies them back into results/ (newer than the scenes, so make does not redo
# the runs), so that `make report SCALE=full` can show runs from several sittings. Each file
# keeps its `#` metadata lines (command, commit, seed, scale, threads, seconds).
# usage: full-record.sh save results/ch6-full/ajar ... | restore
set -euo pipefail
rec=results/baselines/full-record
case ${1:-} in
  save)
    shift
    for d in "$@"; do
      case $d in results/*) ;; *) echo "full-record: $d is not under results/" >&2; exit 2 ;; esac
      [ -d "$d" ] || { echo "full-record: no folder $d" >&2; exit 2; }
      (cd results && find "${d#results/}" -type f \( -name '*.csv' -o -name '*.md' -o -name '*.key' \) -print0) |
        while IFS= read -r -d '' f; do mkdir -p "$rec/$(dirname "$f")"; cp -p "results/$f" "$rec/$f"; done
      echo "full-record: saved $d"
    done ;;
  restore)
    [ -d "$rec" ] || { echo "full-record: nothing recorded in $rec" >&2; exit 2; }
    (cd "$rec" && find . -type f ! -name README.md -print0) |
      while IFS= read -r -d '' f; do mkdir -p "results/$(dirname "$f")"; cp "$rec/$f" "results/$f"; done
    echo "full-record: restored $(cd "$rec" && find . -type f ! -name README.md | wc -l) files into results/" ;;
  *) echo "usage: full-record.sh save results/DIR... | restore" >&2; exit 2 ;;
esac
