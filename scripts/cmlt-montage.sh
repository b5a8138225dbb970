#!/usr/bin/env bash
# Figure 3 of the CMLT paper from the images table1_cmlt wrote into DIR: first row the reference,
# second row PSS-MLT-1, PSS-MLT-2, PSS-MLT-AVG, third row PSS-MLT-MIX, CMLT-EPSM, CMLT, all at the
# largest budget in DIR/table1.csv (seed 0). Labels need a DejaVu font (fonts-dejavu-core); without
# it the figure is written unlabelled. Output: DIR/fig3.png (written atomically).
set -euo pipefail
dir=${1:?usage: cmlt-montage.sh DIR}
[ -f "$dir/table1.csv" ] || { echo "cmlt-montage: $dir/table1.csv not found" >&2; exit 2; }
n=$(awk -F, "$(cat "$(dirname "$0")/csv-col.awk")"'!/^#/ && get("n") + 0 > m { m = get("n") + 0 } END { print m }' "$dir/table1.csv")
if (( n % 1000000 == 0 )); then label="$((n / 1000000))M"; elif (( n % 1000 == 0 )); then label="$((n / 1000))k"; else label=$n; fi
font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
tile() { # image, caption -> a 256x256 tile with the caption on it, as oiiotool arguments
  local args=("$1" --resample 256x256)
  if [ -f "$font" ]; then args+=(--text:x=6:y=18:size=14:color=1,1,1:font="$font" "$2"); fi
  printf '%s\0' "${args[@]}"
}
mapfile -d '' A < <(
  printf '%s\0' --pattern constant:color=0,0,0 256x256 3
  tile "$dir/reference.png" "reference"
  printf '%s\0' --pattern constant:color=0,0,0 256x256 3
  for a in PSS-MLT-1 PSS-MLT-2 PSS-MLT-AVG PSS-MLT-MIX CMLT-EPSM CMLT; do
    [ -f "$dir/${a}_$label.png" ] || { echo "cmlt-montage: $dir/${a}_$label.png not found" >&2; exit 2; }
    tile "$dir/${a}_$label.png" "$a  n=$label"
  done)
tmp="$dir/.fig3.tmp$$.png"
. "$(dirname "$0")/out-file.sh"
write_via cmlt-montage "$dir/fig3.png" "$tmp" oiiotool "${A[@]}" --mosaic:pad=4 3x3 -o "$tmp"
echo "cmlt-montage: wrote $dir/fig3.png (n = $label)" >&2
