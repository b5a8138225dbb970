#!/usr/bin/env bash
# Markdown table of results/fig6.1/fig6.1.csv: per length, the mean acceptance (± batch-means
# standard error) of small steps that keep and that change the technique, MMLT and PITP, and the
# ratio changes / keeps for each. usage: fig6.1-table.sh CSV > TABLE.md
set -euo pipefail
cols=$(cat "$(dirname "$0")/csv-col.awk")
awk -F, "$cols"'
/^#/ { next }
{ key = get("length") + 0; v = get("method"); t = get("technique_changed"); m[v, key, t] = get("mean_accept"); s[v, key, t] = get("stderr"); if (key > K) K = key }
function cell(meth, k, c) { return ((meth, k, c) in m) ? sprintf("%.4f ± %.4f", m[meth, k, c], s[meth, k, c]) : "–" }
function ratio(meth, k) { return (((meth, k, "yes") in m) && ((meth, k, "no") in m) && m[meth, k, "no"] > 0) ? sprintf("%.2f", m[meth, k, "yes"] / m[meth, k, "no"]) : "–" }
END {
    print "| length | MMLT keeps technique | MMLT changes technique | MMLT changes / keeps | PITP keeps technique | PITP changes technique | PITP changes / keeps |"
    print "| ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    for (k = 2; k <= K; k++)
        printf "| %d | %s | %s | %s | %s | %s | %s |\n", k, cell("mmlt", k, "no"), cell("mmlt", k, "yes"), ratio("mmlt", k),
               cell("pitp", k, "no"), cell("pitp", k, "yes"), ratio("pitp", k)
}' "$1"
