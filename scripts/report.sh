#!/usr/bin/env bash
# make report: results/report/index.html, one static page with every figure the harness makes. Each
# entry shows the figure (when it has been run; otherwise the command that makes it), the source's
# claim, the measured statistics with their uncertainties (the run's own Markdown tables), whether the
# claim holds, and links to the CSV, tables and images. Paths in the page are relative to it.
# usage: report.sh [SCALE]   (default quick; the chapter-6 folders are results/ch6-SCALE/...)
# REPORT_DIR (default results/report) is where the page goes; tests put it elsewhere. A page that
# cannot be written leaves the previous one, with one line naming it and status 1.
set -euo pipefail
page_only=
[ "${1:-}" = --page ] && { page_only=1; shift; } # the page on stdout: how the script calls itself
scale=${1:-quick}
out=${REPORT_DIR:-results/report} # tests write elsewhere
esc() { sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g'; }
ch6=results/ch6-$scale hyb=results/hybrid-study-$scale tech=results/mmlt-ratio/technique-k6-$scale meq=results/mmlt-equal-$scale
bg=results/bdpt-pt-$scale cdc=results/cdc-ch6-$scale mis=results/mis-robust-$scale md=results/mmlt-design-$scale
pr=results/pitp-rate-$scale f4=results/mmlt-fig4-$scale f9=results/mmlt-fig9-$scale fd=results/fused-door-$scale
fc=results/fused-caustic-$scale
# The claims ledger's files: every claims.csv of the figures at this scale.
ledger=$(ls results/fig*/claims.csv results/inverse-density/claims.csv results/table1-cmlt/claims.csv "$ch6"/*/claims.csv \
  results/mmlt-ratio/"$scale"/*/claims.csv "$hyb"/*/claims.csv "$meq"/*/claims.csv "$tech"/claims.csv "$bg"/*/claims.csv \
  "$cdc"/*/claims.csv "$mis"/*/claims.csv "$md"/*/claims.csv "$pr"/*/claims.csv "$f4"/*/claims.csv "$f9"/*/claims.csv \
  "$fd"/*/claims.csv "$fc"/*/claims.csv 2>/dev/null || true)
# id | title | make command | images (space-separated) | data files | claim | verdict: the README's quick-scale
# result, or @FILE... = the measured verdicts, the '- ' lines of those files (written by the run's scripts)
entries=(
"fig4.1|Thesis Fig. 4.1: isotropic vs resolution-aware small steps|make fig4.1|results/fig4.1/fig4.1.png results/fig4.1/fig4.1-profiles.png|results/fig4.1/fig4.1.csv results/fig4.1/fig4.1.md results/fig4.1/claims.csv|Isotropic small steps stretch the noise horizontally by about the aspect ratio (1.78); resolution-aware steps make it isotropic.|@results/fig4.1/claims.md"
"fig4.2|Thesis Fig. 4.2: the wall at 1024², 512², 256² and resolution-scaled steps|make fig4.2|results/fig4.2/fig4.2.png results/fig4.2/fig4.2-plot.png|results/fig4.2/fig4.2.csv results/fig4.2/fig4.2.md results/fig4.2/claims.csv|Smaller images get smaller steps in pixels and blotchier noise; scaling the step to the resolution removes it, but in glossy-to-glossy transport it lowers acceptance as the resolution decreases (§4.1).|@results/fig4.2/claims.md"
"fig4.3|Thesis Fig. 4.3: constrained discrete choices, a room reflected in a window|make fig4.3|results/fig4.3/fig4.3.png|results/fig4.3/fig4.3.csv results/fig4.3/fig4.3.md results/fig4.3/claims.csv|--cdc keeps the chain on reflected paths: higher acceptance and lower error than PSSMLT; BDPT has difficulty.|@results/fig4.3/claims.md"
"fig4.5|Thesis Fig. 4.5: acceptance of MMLT large steps vs MCTLS|make fig4.5|results/fig4.5/fig4.5.png results/fig4.5/fig4.5-ratio.png|results/fig4.5/fig4.5.csv results/fig4.5/fig4.5-ratios.csv results/fig4.5/fig4.5-trials.csv results/fig4.5/fig4.5.md results/fig4.5/claims.csv|MCTLS is accepted more often than MMLT large steps, by a ratio growing to about 5× at length 11.|@results/fig4.5/claims.md"
"fig4.6|Thesis Fig. 4.6: equal-time MMLT large steps vs MCTLS vs hybrid (no small steps)|make fig4.6|results/fig4.6/fig4.6.png|results/fig4.6/fig4.6.csv results/fig4.6/fig4.6-runs.csv results/fig4.6/fig4.6.md results/fig4.6/claims.csv|At equal time MMLT large steps and MCTLS are similarly noisy: an MCTLS step costs about 5x as much, which cancels its higher acceptance (§4.3).|@results/fig4.6/claims.md"
"fig5.5|Thesis Fig. 5.5: angle change of MMLT vs controlled small steps|make fig5.5|results/fig5.5/fig5.5.png|results/fig5.5/fig5.5.csv results/fig5.5/fig5.5.md results/fig5.5/claims.csv|MMLT's small steps change the path more near edges; controlled steps do not.|@results/fig5.5/claims.md"
"fig5.6|Thesis Fig. 5.6: rendered images, MMLT vs controlled small steps|make fig5.6|results/fig5.6/fig5.6.png|results/fig5.6/fig5.6.csv results/fig5.6/fig5.6.md results/fig5.6/claims.csv|Controlled small steps give streaky, splotchy noise and are not better.|@results/fig5.6/claims.md"
"inverse-density|Thesis §5.1, Eq. 5.3: inverted numbers against forward ones, every sampling function with an inverse|make inverse-density||results/inverse-density/inverse_density.csv results/inverse-density/inverse_density.md results/inverse-density/claims.csv|The numbers an inverse random walk returns for a path are distributed as the numbers with which the path was sampled.|@results/inverse-density/claims.md"
"fig6.1|Thesis Fig. 6.1: small-step acceptance per length, MMLT vs PITP, split by technique change|make fig6.1|results/fig6.1/fig6.1.png|results/fig6.1/fig6.1.csv results/fig6.1/fig6.1-pitp.csv results/fig6.1/fig6.1.md results/fig6.1/claims.csv|Technique changes in MMLT are very unlikely to be accepted, whereas technique changes in PITP have little effect on the acceptance probability (§6.1).|@results/fig6.1/claims.md"
"table1-cmlt|CMLT paper Table 1 and Fig. 3: the two-light toy|make table1-cmlt|results/table1-cmlt/fig3.png|results/table1-cmlt/table1.csv results/table1-cmlt/table1_stats.csv results/table1-cmlt/table1.md results/table1-cmlt/claims.csv|PSS-MLT-1 has about twice PSS-MLT-2's RMSE; PSS-MLT-AVG is worse than PSS-MLT-2; PSS-MLT-MIX is better than AVG; CMLT-EPSM is just worse than MIX; CMLT is best.|@results/table1-cmlt/claims.md"
"fig6.2|Thesis Fig. 6.2: living room, equal time, insets|make fig6.2|$ch6/living-room/fig6.2.png $ch6/living-room/error-vs-time.png|$ch6/living-room/summary.csv $ch6/living-room/runs.csv $ch6/living-room/living-room.md $ch6/living-room/claims.md $ch6/living-room/claims.csv|PSSMLT worst (all connections cost); MMLT streaky/splotchy; PITP most uniform.|@$ch6/living-room/claims.md"
"fig6.3|Thesis Fig. 6.3: staircase, equal time, insets|make fig6.3|$ch6/staircase/fig6.3.png $ch6/staircase/error-vs-time.png|$ch6/staircase/summary.csv $ch6/staircase/runs.csv $ch6/staircase/staircase.md $ch6/staircase/claims.md $ch6/staircase/claims.csv|PSSMLT worst (all connections cost); MMLT streaky/splotchy; PITP most uniform.|@$ch6/staircase/claims.md"
"fig6.4|Thesis Fig. 6.4: ajar, equal time, insets|make fig6.4|$ch6/ajar/fig6.4.png $ch6/ajar/error-vs-time.png|$ch6/ajar/summary.csv $ch6/ajar/runs.csv $ch6/ajar/ajar.md $ch6/ajar/claims.md $ch6/ajar/claims.csv|PSSMLT worst (all connections cost); MMLT streaky/splotchy; PITP most uniform.|@$ch6/ajar/claims.md"
"fig6.5|Thesis Fig. 6.5: living room, full images|make fig6.5|$ch6/living-room/fig6.5.png|$ch6/living-room/summary.csv $ch6/living-room/claims.md $ch6/living-room/claims.csv|Full-resolution images of Fig. 6.2's methods: PSSMLT worst; MMLT streaky/splotchy; PITP most uniform.|@$ch6/living-room/claims.md"
"fig6.6|Thesis Fig. 6.6: staircase, full images|make fig6.6|$ch6/staircase/fig6.6.png|$ch6/staircase/summary.csv $ch6/staircase/claims.md $ch6/staircase/claims.csv|Full-resolution images of Fig. 6.3's methods: PSSMLT worst; MMLT streaky/splotchy; PITP most uniform.|@$ch6/staircase/claims.md"
"fig6.7|Thesis Fig. 6.7: ajar, full images|make fig6.7|$ch6/ajar/fig6.7.png|$ch6/ajar/summary.csv $ch6/ajar/claims.md $ch6/ajar/claims.csv|Full-resolution images of Fig. 6.4's methods: PSSMLT worst; MMLT streaky/splotchy; PITP most uniform.|@$ch6/ajar/claims.md"
"mmlt-ratio|MMLT paper §5 and Fig. 5: non-zero samples; per-technique contributions and sample counts (ajar, length 4)|make mmlt-ratio|$tech/technique-images.png|results/mmlt-ratio/mmlt-ratio.md $tech/tech.md $tech/follow-mmlt.csv $tech/follow-pssmlt.csv results/mmlt-ratio/$scale/ajar-direct/claims.csv $tech/claims.csv|11.81 % of PSSMLT's samples vs 29.75 % of MMLT's have non-zero contribution (door scene); MMLT's per-technique sample counts follow the per-technique contributions, PSSMLT's do not.|@results/mmlt-ratio/mmlt-ratio.md $tech/tech.md"
"hybrid-study|Thesis §4.3/§7.1: hybrid MCTLS at equal time, with small steps|make hybrid-study||$hyb/hybrid-study.md $hyb/ajar/summary.csv $hyb/living-room/summary.csv $hyb/ajar/claims.csv $hyb/living-room/claims.csv|Open question: do MMLT large steps for short paths plus MCTLS for long ones beat both?|@$hyb/ajar/claims.md $hyb/living-room/claims.md"
"cdc-ch6|Thesis §4.2: constrained discrete choices on the chapter-6 scenes (PSSMLT with and without --cdc, equal time)|make cdc-ch6||$cdc/living-room/claims.csv $cdc/staircase/claims.csv $cdc/ajar/claims.csv|In other scenes the effect of CDC is usually subtle.|@$cdc/living-room/claims.md $cdc/staircase/claims.md $cdc/ajar/claims.md"
"mis-robust|Thesis Fig. 3.3: path tracing, next-event estimation and MIS of the two on Veach's plates and lights (direct light, equal samples)|make mis-robust|$mis/veach-mis/bsdf.png $mis/veach-mis/nee.png $mis/veach-mis/mis.png $mis/veach-mis/reference.png|$mis/veach-mis/summary.csv $mis/veach-mis/veach-mis.md $mis/veach-mis/claims.csv|Both techniques alone show sampling deficiencies for certain material-emitter combinations; MIS is robust over all combinations.|@$mis/veach-mis/claims.md"
"bdpt-pt|Thesis Fig. 3.4: BDPT vs path tracing at equal samples (ajar)|make bdpt-pt||$bg/ajar/summary.csv $bg/ajar/ajar.md $bg/ajar/claims.csv|BDPT has lower variance than path tracing at equal samples.|@$bg/ajar/claims.md"
"pitp-rate|The harness's question: how often should PITP move the technique? (--pitp-rate P, equal time, chapter-6 scenes)|make pitp-rate|$pr/ajar/pitp-rate.png $pr/living-room/pitp-rate.png $pr/staircase/pitp-rate.png|$pr/pitp-rate.md $pr/living-room/claims.csv $pr/staircase/claims.csv $pr/ajar/claims.csv|Neither source asks: the thesis moves the technique before every small step (P = 1), Tungsten's reversible jump at a rate of 0.05.|@$pr/living-room/claims.md $pr/staircase/claims.md $pr/ajar/claims.md"
"mmlt-design|MMLT paper §4: b_k once or progressively, one chain per length or one over all (equal time; ajar with direct light, the paper's setting, and the chapter-6 scenes)|make mmlt-design||$md/ajar-direct/claims.csv $md/living-room/claims.csv $md/staircase/claims.csv $md/ajar/claims.csv|b_k estimated progressively is less likely to miss rare bounces; one chain per path length is more efficient.|@$md/ajar-direct/claims.md $md/living-room/claims.md $md/staircase/claims.md $md/ajar/claims.md"
"mmlt-equal|MMLT paper §5 and Fig. 4: BDPT, PSSMLT and MMLT at equal time (ajar, up to 8 bounces)|make mmlt-equal||$meq/ajar/summary.csv $meq/ajar/ajar.md $meq/ajar/claims.csv|BDPT and PSSMLT are noisy, PSSMLT barely improves on BDPT, MMLT is less noisy than both.|@$meq/ajar/claims.md"
"mmlt-fig4|MMLT paper Figs. 1, 4 and 6: BDPT, PSSMLT, Veach's MLT and MMLT at equal time (ajar, up to 8 bounces; the glossy pixels)|make mmlt-fig4|$f4/ajar/glossy-mask.png|$f4/ajar/summary.csv $f4/ajar/ajar.md $f4/ajar/claims.csv|MMLT renders glossy surfaces more accurately than original MLT, which shows splotchy artifacts there and converges more slowly on them than elsewhere; PSSMLT is noisy overall.|@$f4/ajar/claims.md"
"mmlt-fig9|MMLT paper Fig. 9: the diffuse door, PSSMLT, Veach's MLT and MMLT at equal time|make mmlt-fig9||$f9/ajar-diffuse/summary.csv $f9/ajar-diffuse/ajar-diffuse.md $f9/ajar-diffuse/claims.csv|On a diffuse door original MLT beats MMLT, which beats PSSMLT.|@$f9/ajar-diffuse/claims.md"
"fused-door|Veach's perturbations fused into MMLT and PITP through the inverse (Otsu et al. 2017; thesis §7.1): the door scene (ajar)|make fused-door||$fd/ajar/summary.csv $fd/ajar/ajar.md $fd/ajar/claims.csv|Original MLT wins on a door scene; the fused chain is robust (beats MMLT and original MLT); do other perturbations through the inverse help PITP (§7.1)?|@$fd/ajar/claims.md"
"fused-caustic|Veach's perturbations fused into MMLT and PITP through the inverse (Otsu et al. 2017; thesis §7.1): the caustic scene (glass-marble)|make fused-caustic||$fc/glass-marble/summary.csv $fc/glass-marble/glass-marble.md $fc/glass-marble/claims.csv|MMLT wins on a caustic scene; the fused chain is robust (beats MMLT and original MLT); do other perturbations through the inverse help PITP (§7.1)?|@$fc/glass-marble/claims.md"
)
# REPORT_TARGETS (make report: its FIGURE_TARGETS): every figure target has an entry, so that none
# of them (and none of its claims) can be left out of the page and the ledger.
# (No `printf | grep -q`: under pipefail, grep's early exit can fail the printf with SIGPIPE.)
for t in ${REPORT_TARGETS:-}; do
  found=
  for e in "${entries[@]}"; do [ "${e%%|*}" = "$t" ] && found=1; done
  [ -n "$found" ] || { echo "report: make $t has no entry in scripts/report.sh (entries=)" >&2; exit 1; }
done
page() {
cat <<'HEAD'
<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>pss-harness report</title>
<style>
body { font-family: sans-serif; max-width: 1300px; margin: 1em auto; color: #222; }
section { border-top: 1px solid #ccc; padding: 0.5em 0 1em; }
img { max-width: 100%; border: 1px solid #ddd; margin: 4px 0; }
pre { background: #f6f6f6; padding: 0.5em; overflow-x: auto; font-size: 12px; }
table { border-collapse: collapse; font-size: 13px; } td, th { border: 1px solid #ccc; padding: 2px 5px; }
.v-holds { background: #dfd; } .v-contradicted { background: #fdd; } .v-undecided { background: #ffd; } .v-notrep { background: #eee; }
.missing { color: #a00; } .claim { background: #eef4ff; padding: 0.4em; } .verdict { background: #efe; padding: 0.4em; }
</style></head><body>
<h1>pss-harness: every figure</h1>
HEAD
echo "<p>Generated $(date -u '+%Y-%m-%d %H:%M UTC') from commit $(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown), scale $scale (the chapter-6 figures and mmlt-ratio at that scale; every other figure as last run: each ledger row names its own scale), on a shared 2-core machine.</p>"
# The claims ledger: every row of every claims.csv the figures wrote (their verdicts come from the
# runs, experiments/common/verdict.c), first; columns read by name (scripts/csv-col.awk). Above it,
# the coverage of the sources' claims (results/claims-catalogue.csv) by the rows with exactly their ID.
csvcol=$(cat "$(dirname "$0")/csv-col.awk")
echo "<section id=\"ledger\"><h2>Claims ledger</h2>"
if [ -z "$ledger" ]; then echo "<p class=\"missing\">No figure with claims has been run yet (make fig4.6, make fig6.2 ...).</p>"
else
  # shellcheck disable=SC2086  # the ledger is a list of paths without spaces
  bash "$(dirname "$0")/claims-coverage.sh" --html results/claims-catalogue.csv $ledger
  # Beside each row, what the source says and where (the catalogue's reading); after the rows, one
  # row per claim the harness cannot test, with what it would need.
  echo "<table><tr><th>id</th><th>the source (where: the claim)</th><th>this row's claim</th><th>statistic</th><th>value ± s.e.</th><th>z (deciding)</th><th>verdict</th><th>scale</th><th>command</th></tr>"
  for f in $ledger; do
    awk -F, -v catalogue=results/claims-catalogue.csv "$csvcol"'
      FILENAME == catalogue && !/^#/ { k = get("id"); said[k] = get("source") " " get("where") ": " get("claim"); next }
      !/^#/ {
        base = get("id"); sub(/^harness:?/, "", base)
        need = (get("verdict") == "undecided" && get("seeds_needed") > 0) ? sprintf(" (%d seeds would decide it)", get("seeds_needed")) : ""
        if (("mixing" in col) && get("mixing") != "") need = need " ⚠ " get("mixing")
        printf "<tr class=\"ledger-row\" data-claims=\"%s\"><td>%s</td><td>%s</td><td>%s (%s)</td><td>%s</td><td>%s %.4g ± %.2g</td><td>%.1f</td><td class=\"v-%s\">%s</td><td>%s</td><td>%s</td></tr>\n",
          href, get("id"), (base in said) ? said[base] : "", get("claim"), get("source"), get("statistic"), get("method"), get("value"), get("se"), get("z_min"),
          get("verdict"), get("verdict") need, get("scale"), get("command") }' href="../${f#results/}" results/claims-catalogue.csv "$f" | sed 's/&/\&amp;/g'
  done
  awk -F, "$csvcol"'!/^#/ && get("needs") != "" {
      printf "<tr><td>%s</td><td>%s %s: %s</td><td>%s</td><td></td><td></td><td></td><td class=\"v-notrep\">not reproduced: needs %s</td><td></td><td></td></tr>\n",
        get("id"), get("source"), get("where"), get("claim"), get("compares"), get("needs") }' results/claims-catalogue.csv | sed 's/&/\&amp;/g'
  echo "</table>"
fi
echo "</section>"
echo "<ul>"
for e in "${entries[@]}"; do IFS='|' read -r id title _ <<<"$e"; echo "<li><a href=\"#$id\">$(printf '%s' "$title" | esc)</a></li>"; done
echo "</ul>"
for e in "${entries[@]}"; do
  IFS='|' read -r id title cmd imgs data claim verdict <<<"$e"
  echo "<section id=\"$id\"><h2>$(printf '%s' "$title" | esc)</h2>"
  echo "<p class=\"claim\"><b>Claim:</b> $(printf '%s' "$claim" | esc)</p>"
  have=0
  for i in $imgs; do [ -f "$i" ] && have=1; done
  for d in $data; do [ -f "$d" ] && have=1; done
  if [ $have = 0 ]; then
    echo "<p class=\"missing\">Not run yet: <code>$(printf '%s' "$cmd" | esc)</code> makes it.</p></section>"
    continue
  fi
  for i in $imgs; do
    if [ -f "$i" ]; then echo "<a href=\"../${i#results/}\"><img src=\"../${i#results/}\" alt=\"$id\"></a>"
    else echo "<p class=\"missing\">$(basename "$i") not made yet: <code>$(printf '%s' "$cmd" | esc)</code></p>"; fi
  done
  for d in $data; do
    case $d in *.md) [ -f "$d" ] && { echo "<pre>"; esc < "$d"; echo "</pre>"; } ;; esac
  done
  if [ "${verdict:0:1}" = @ ]; then
    echo "<div class=\"verdict\"><b>Holds? (measured on this run)</b><ul>"
    for vf in ${verdict:1}; do
      # "- " lines, or the rows of a claims.md table (id | claim | statistic | value | against | verdict)
      if [ -f "$vf" ]; then { { grep '^- ' "$vf" || true; } | sed 's/^- //'; { grep '^| ' "$vf" || true; } | { grep -v -e '^| claim |' -e '^| id |' -e '^| ---' || true; } |
          sed -e 's/^| //; s/ |$//; s/ | /: /; s/ | /; /g; s/\\|/|/g'; } | esc | sed -e 's|\*\*\([^*]*\)\*\*|<b>\1</b>|g' -e 's|^|<li>|; s|$|</li>|'
      else echo "<li class=\"missing\">$(basename "$vf") not made yet: <code>$(printf '%s' "$cmd" | esc)</code></li>"; fi
    done
    echo "</ul></div>"
  elif [ -n "$verdict" ]; then echo "<p class=\"verdict\"><b>Holds?</b> $(printf '%s' "$verdict" | esc)</p>"
  else echo "<p class=\"verdict\"><b>Holds?</b> see the claims and tables above (measured on this run).</p>"; fi
  echo "<p>Data:"
  for d in $data; do [ -f "$d" ] && echo " <a href=\"../${d#results/}\">$(basename "$d")</a>"; done
  echo "</p></section>"
done
cat <<'TAIL'
<script>
window.addEventListener('load', function () {
  var bad = [], n = 0;
  document.querySelectorAll('img').forEach(function (im) { n++; if (!(im.complete && im.naturalWidth > 0)) bad.push(im.getAttribute('src')); });
  document.body.setAttribute('data-imgcheck', bad.length ? 'BROKEN ' + bad.join(' ') : 'OK ' + n);
  // The ledger: every verdict one of the three words, and a row for every figure on the page that
  // links a claims.csv (the figure exists), so a figure's claims cannot drop out of the ledger.
  var words = ['holds', 'contradicted', 'undecided'], lbad = [], rows = document.querySelectorAll('tr.ledger-row');
  var inLedger = {};
  rows.forEach(function (tr) {
    inLedger[tr.getAttribute('data-claims')] = true;
    var td = tr.querySelector('td[class^="v-"]'), w = td ? td.className.slice(2) : '';
    if (words.indexOf(w) < 0 || td.textContent.split(' ')[0] !== w) lbad.push('verdict "' + (td ? td.textContent : '') + '"');
  });
  var figs = 0;
  document.querySelectorAll('section[id] a[href$="claims.csv"]').forEach(function (a) {
    figs++;
    if (!inLedger[a.getAttribute('href')]) lbad.push('no ledger row for ' + a.getAttribute('href'));
  });
  document.body.setAttribute('data-ledgercheck', lbad.length ? 'BAD ' + lbad.join('; ') : 'OK ' + rows.length + ' rows, ' + figs + ' figures');
});
</script>
</body></html>
TAIL
}
if [ "$page_only" ]; then page; exit 0; fi
# A claims.csv of a run older than the claims catalogue has no id column: name it, and what remakes it.
for f in $ledger; do
  if ! grep -q '^id,' "$f"; then
    echo "report: $f is from a run older than the claims catalogue (no id column): make that figure again" >&2
    exit 1
  fi
done
mkdir -p "$out"
bash "$(dirname "$0")/to-file.sh" report "$out/index.html" bash "$0" --page "$scale" || exit 1
echo "report: wrote $out/index.html" >&2
