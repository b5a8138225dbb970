#!/usr/bin/env bash
# Markdown table of results/fig5.5/fig5.5.csv (kind,region,mean,stderr,seeds) or
# results/fig5.6/fig5.6.csv (kind,relmse,stderr,seeds,accept_small,mutations_per_second,corrlen,corrlen_se,
# blur8,blur8_se, ..., glossy_corrlen,glossy_corrlen_se,glossy_blur4,glossy_blur4_se: the columns by name).
# usage: fig5-table.sh CSV > TABLE.md
set -euo pipefail
cols=$(cat "$(dirname "$0")/csv-col.awk")
awk -F, "$cols"'
/^#/ { next }
{ fig = ("region" in col) ? 5 : 6 }
fig == 5 { kind = get("kind"); region = get("region"); m[kind, region] = get("mean"); s[kind, region] = get("stderr"); n = get("seeds") }
fig == 6 { printf "%s| %s | %.5f ± %.5f | %.2f ± %.2f | %.3f ± %.3f | %.2f ± %.2f | %.3f ± %.3f | %.3f | %.0f |\n", (rows++ ? "" : "| small step | relMSE (± s.e. over " get("seeds") " seeds) | error correlation length (px) | error share in 8×8 blobs | on the rings: correlation length (px) | on the rings: share in 4×4 blobs | small-step acceptance | mutations/s |\n| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n"), get("kind"), get("relmse"), get("stderr"), get("corrlen"), get("corrlen_se"), get("blur8"), get("blur8_se"), get("glossy_corrlen"), get("glossy_corrlen_se"), get("glossy_blur4"), get("glossy_blur4_se"), get("accept_small"), get("mutations_per_second") }
END {
    if (fig != 5) exit
    print "| small step | mean Δψ (rad), all pixels | within 2 px of an edge | elsewhere | edge / elsewhere |"
    print "| --- | ---: | ---: | ---: | ---: |"
    nk = split("mmlt controlled root", k, " ")
    for (i = 1; i <= nk; i++) if ((k[i], "all") in m)
        printf "| %s | %.4f ± %.4f | %.4f ± %.4f | %.4f ± %.4f | %.3f ± %.3f |\n", k[i], m[k[i], "all"], s[k[i], "all"],
            m[k[i], "edge"], s[k[i], "edge"], m[k[i], "elsewhere"], s[k[i], "elsewhere"], m[k[i], "ratio"], s[k[i], "ratio"]
    print ""
    print "Standard errors over " n " seeds."
}' "$1"
