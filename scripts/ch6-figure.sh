#!/usr/bin/env bash
# Chapter-6 figures from a bin/ch6_equal folder (make fig6.2 ... fig6.7).
# usage: ch6-figure.sh insets|full DIR OUT.png [X,Y,W,H X,Y,W,H]
#   insets: top row the reference with the two rectangles (red, yellow) and every method's image;
#           below, the first and the second inset of each (nearest-pixel enlargement), labelled.
#   full:   the reference and every method's full image side by side, labelled.
#   The insets default to DIR/summary.csv's `# insets` line (bin/ch6_equal --insets, or its scale's).
# The methods are those of DIR/summary.csv (in its order; a skipped method has no row there).
set -euo pipefail
[ $# -eq 3 ] || [ $# -eq 5 ] || { echo "usage: ch6-figure.sh insets|full DIR OUT.png [X,Y,W,H X,Y,W,H]" >&2; exit 2; }
mode=$1 dir=$2 out=$3
[ -f "$dir/summary.csv" ] && [ -f "$dir/reference.png" ] || { echo "ch6-figure: $dir has no summary.csv or reference.png (run bin/ch6_equal)" >&2; exit 2; }
if [ $# -eq 3 ]; then
  read -r -a insets < <(sed -n 's/^# insets //p' "$dir/summary.csv")
  [ "$mode" = full ] || [ ${#insets[@]} -eq 2 ] || { echo "ch6-figure: $dir/summary.csv has no '# insets' line; give X,Y,W,H X,Y,W,H" >&2; exit 2; }
  set -- "$1" "$2" "$3" "${insets[@]}"
fi
here=$(cd "$(dirname "$0")" && pwd)
methods=$(awk -F, "$(cat "$here/csv-col.awk")"'!/^#/ && !seen[get("method")]++ { print get("method") }' "$dir/summary.csv")
read -r W H < <(oiiotool --info "$dir/reference.png" | awk '{for (i = 1; i < NF; i++) if ($(i + 1) == "x") {sub(",", "", $(i + 2)); print $i, $(i + 2); exit}}')
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ "$mode" = full ]; then
  args=("$dir/reference.png" "reference (BDPT)")
  for m in $methods; do args+=("$dir/$m.png" "$m"); done
  n=$(( ${#args[@]} / 2 ))
  bash "$here/ch4-montage.sh" "$out" "$n" "${W}x${H}" "${args[@]}"
  exit 0
fi
[ "$mode" = insets ] || { echo "ch6-figure: mode must be insets or full, got '$mode'" >&2; exit 2; }
IFS=, read -r x1 y1 w1 h1 <<<"$4"
IFS=, read -r x2 y2 w2 h2 <<<"$5"
oiiotool "$dir/reference.png" --box:color=1,0.1,0.1 "$x1,$y1,$((x1 + w1 - 1)),$((y1 + h1 - 1))" \
  --box:color=1,0.9,0.1 "$x2,$y2,$((x2 + w2 - 1)),$((y2 + h2 - 1))" -o "$tmp/ref-boxed.png"
row0=("$tmp/ref-boxed.png" "reference (BDPT)") row1=() row2=()
for m in reference $methods; do
  oiiotool "$dir/$m.png" --cut "${w1}x${h1}+${x1}+${y1}" -o "$tmp/$m-1.png"
  oiiotool "$dir/$m.png" --cut "${w2}x${h2}+${x2}+${y2}" -o "$tmp/$m-2.png"
  [ "$m" = reference ] || row0+=("$dir/$m.png" "$m")
  row1+=("$tmp/$m-1.png" "$m, red inset")
  row2+=("$tmp/$m-2.png" "$m, yellow inset")
done
n=$(( ${#row0[@]} / 2 ))
bash "$here/ch4-montage.sh" "$out" "$n" "${W}x${H}" "${row0[@]}" "${row1[@]}" "${row2[@]}"
