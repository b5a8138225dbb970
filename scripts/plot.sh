#!/usr/bin/env bash
# usage: plot.sh SCRIPT CSV OUT [GNUPLOT_ASSIGNMENTS]
# Runs a gnuplot script with csv='CSV' and out set to a temporary prefix beside OUT, then puts each
# file it wrote (TMP.png, TMP.pdf) in place as OUT.png / OUT.pdf, checked whole and synced
# (scripts/out-file.sh): OUT.* are the old plots or the complete new ones. When anything fails (a
# full disk, gnuplot itself) the temporaries are removed, the only message is one line
# "plot: OUT.EXT: cannot write (REASON)", and the status is 1.
set -uo pipefail
script=$1 csv=$2 out=$3 extra=${4:-}
tmp="$(dirname "$out")/.tmp$$-$(basename "$out")"
trap 'rm -f "$tmp.png" "$tmp.pdf"' EXIT
. "$(dirname "$0")/out-file.sh"
write_via plot "$out.png" "$tmp.png" gnuplot -e "csv='$csv'; out='$tmp'; $extra" "$script"
[ -f "$tmp.pdf" ] && write_via plot "$out.pdf" "$tmp.pdf" true
exit 0
