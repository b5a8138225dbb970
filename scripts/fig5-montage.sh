#!/usr/bin/env bash
# Side-by-side labelled panels of Figures 5.5 / 5.6: fig5-montage.sh DIR IMAGE LABEL [IMAGE LABEL]...
# writes DIR/<basename of DIR>.png (atomically). Labels need a DejaVu font (fonts-dejavu-core);
# without it the panels are unlabelled.
set -euo pipefail
dir=${1:?usage: fig5-montage.sh DIR IMAGE LABEL [IMAGE LABEL]...}
shift
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
args=()
n=0
while (($#)); do
  img="$dir/$1" label="$2"
  shift 2
  [ -f "$img" ] || { echo "fig5-montage: $img not found" >&2; exit 2; }
  args+=("$img")
  if [ -f "$font" ]; then args+=(--text:x=6:y=16:size=13:color=1,0.3,0.3:font="$font" "$label"); fi
  n=$((n + 1))
done
out="$dir/$(basename "$dir").png"
tmp="$dir/.montage.tmp$$.png"
. "$(dirname "$0")/out-file.sh"
write_via fig5-montage "$out" "$tmp" oiiotool "${args[@]}" --mosaic:pad=4 "${n}x1" -o "$tmp"
echo "fig5-montage: wrote $out" >&2
