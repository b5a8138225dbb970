#!/usr/bin/env bash
# Markdown table of results/fig4.3/fig4.3.csv: relMSE against the BDPT reference and small-step
# acceptance per method (mean ± standard error over seeds), the mean wall-clock seconds per run from
# the runs CSV, then the thesis's claim. usage: fig4.3-table.sh CSV RUNS.csv > TABLE.md
set -euo pipefail
cols=$(cat "$(dirname "$0")/csv-col.awk")
awk -F, "$cols"'
FNR == 1 { file++ }
file == 2 { if (!/^#/) { sec[get("method")] += get("seconds"); nsec[get("method")]++ } next }
/^# resolution/ { res = $0; sub(/^# resolution /, "", res) }
/^# spp/ { spp = $0; sub(/^# spp /, "", spp) }
/^# p_large/ { pl = $0; sub(/^# p_large /, "", pl) }
/^# reference/ { ref = $0; sub(/^# reference /, "", ref) }
/^#/ { next }
{ v = get("method"); q = get("quantity"); m[v, q] = get("mean"); s[v, q] = get("se"); n = get("seeds") }
END {
    printf "`scenes/window` at %s, %s samples (mutations) per pixel, PSSMLT p_large = %s, %d seeds (mean ± standard error); reference %s.\n\n", res, spp, pl, n, ref
    print "| method | relMSE | relMSE / PSSMLT | small-step acceptance | seconds per run |"
    print "| --- | ---: | ---: | ---: | ---: |"
    split("bdpt pssmlt pssmlt-cdc", V, " ")
    name["bdpt"] = "BDPT"; name["pssmlt"] = "PSSMLT"; name["pssmlt-cdc"] = "PSSMLT `--cdc`"
    for (i = 1; i <= 3; i++) {
        v = V[i]
        a = (v, "small_accept") in m ? sprintf("%.4f ± %.4f", m[v, "small_accept"], s[v, "small_accept"]) : "–"
        printf "| %s | %.4f ± %.4f | %.2f | %s | %.1f |\n", name[v], m[v, "relmse"], s[v, "relmse"], m[v, "relmse"] / m["pssmlt", "relmse"], a, sec[v] / nsec[v]
    }
    printf "\nThe reference'"'"'s own error, estimated from the BDPT runs, adds about %.4f to every relMSE.\n", m["reference", "relmse_own"]
    print "Thesis: keeping discrete numbers fixed in small steps keeps the chain on the paths that reflect off the window: higher small-step acceptance and lower error than plain PSSMLT; BDPT has difficulty with this scene."
}' "$1" "$2"
