#!/usr/bin/env bash
# Labelled side-by-side figure for the chapter-4 figures (make fig4.1, fig4.2, fig4.3).
# usage: ch4-montage.sh OUT.png COLUMNS TILE_WxH IMAGE LABEL [IMAGE LABEL ...]
# Every image is resampled to TILE_WxH (nearest pixel, so noise stays visible) and captioned in its
# top-left corner; labels need a DejaVu font (fonts-dejavu-core), without it the figure is written
# unlabelled. OUT.png is written atomically.
set -euo pipefail
[ $# -ge 5 ] && [ $(( ($# - 3) % 2 )) -eq 0 ] || { echo "usage: ch4-montage.sh OUT.png COLUMNS TILE_WxH IMAGE LABEL [IMAGE LABEL ...]" >&2; exit 2; }
out=$1 cols=$2 tile=$3
shift 3
font=/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf
[ -f "$font" ] || font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
args=() n=0
while [ $# -gt 0 ]; do
  [ -f "$1" ] || { echo "ch4-montage: $1 not found" >&2; exit 2; }
  args+=("$1" --resample "$tile")
  if [ -f "$font" ]; then
    args+=(--text:x=7:y=21:size=15:color=0,0,0:font="$font" "$2" --text:x=6:y=20:size=15:color=1,0.85,0.2:font="$font" "$2")
  fi
  n=$((n + 1))
  shift 2
done
rows=$(( (n + cols - 1) / cols ))
tmp="$(dirname "$out")/.$(basename "$out" .png).tmp$$.png"
. "$(dirname "$0")/out-file.sh"
write_via ch4-montage "$out" "$tmp" oiiotool "${args[@]}" --mosaic:pad=4 "${cols}x${rows}" -o "$tmp"
echo "ch4-montage: wrote $out" >&2
