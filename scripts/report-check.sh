#!/usr/bin/env bash
# The report in a real browser: headless Chromium loads results/report/index.html, every image must
# decode (naturalWidth > 0, checked by the page's own script after load), every local link must name
# an existing file, every claims-ledger verdict must be holds, contradicted or undecided and every
# figure on the page with a claims.csv must have its rows in the ledger (the page's script checks both),
# and a screenshot is written to results/report/screenshot.png.
# usage: report-check.sh [INDEX.html]; exit 0 ok, 1 a failure, 77 no Chromium.
set -euo pipefail
page=${1:-results/report/index.html}
[ -f "$page" ] || { echo "report-check: $page not found (make report)" >&2; exit 1; }
chrome=$(command -v chromium || command -v chromium-browser || true)
[ -n "$chrome" ] || { echo "report-check: no chromium" >&2; exit 77; }
dir=$(cd "$(dirname "$page")" && pwd) url="file://$(cd "$(dirname "$page")" && pwd)/$(basename "$page")"
flags=(--headless --no-sandbox --disable-gpu --allow-file-access-from-files --virtual-time-budget=10000)
dom=$("$chrome" "${flags[@]}" --dump-dom "$url" 2>/dev/null)
check=$(printf '%s' "$dom" | grep -o 'data-imgcheck="[^"]*"' | head -1)
case $check in
  *'"OK '*) ;;
  *) echo "report-check: images did not all decode: ${check:-page script did not run}" >&2; exit 1 ;;
esac
ledger=$(printf '%s' "$dom" | grep -o 'data-ledgercheck="[^"]*"' | head -1 | sed 's/^data-ledgercheck="//; s/"$//; s/&quot;/"/g')
case $ledger in
  'OK '*) ;;
  *) echo "report-check: claims ledger: ${ledger:-page script did not run}" >&2; exit 1 ;;
esac
broken=0
while read -r href; do
  case $href in http*|\#*) continue ;; esac
  [ -e "$dir/$href" ] || { echo "report-check: broken link $href" >&2; broken=1; }
done < <(grep -o 'href="[^"]*"' "$page" | sed 's/href="//; s/"$//')
[ $broken = 0 ] || exit 1
shot="$dir/screenshot.png"
rm -f "$shot"
# The whole page in one tall window. Without a fixed device scale factor and with scroll bars,
# headless Chromium painted only the top ~2400 px of a 5000 px window and left the rest black.
(cd "$dir" && "$chrome" "${flags[@]}" --window-size=1300,16000 --force-device-scale-factor=1 --hide-scrollbars \
  --screenshot="$shot" "$url" >/dev/null 2>&1)
[ -s "$shot" ] || { echo "report-check: no screenshot written" >&2; exit 1; }
echo "report-check: ${check#data-imgcheck=}, ledger "$ledger", links ok, screenshot $shot"
