#!/usr/bin/env bash
# Markdown table of results/fig4.6/fig4.6.csv (mean ± standard error over seeds per method).
# usage: fig4.6-table.sh CSV > TABLE.md
set -euo pipefail
cols=$(cat "$(dirname "$0")/csv-col.awk")
awk -F, "$cols"'
/^#/ { next }
{ n++; for (i = 1; i <= q; i++) c[n, i] = get(name[i]) }
BEGIN { q = split("method seeds relmse relmse_se us_per_proposal us_per_proposal_se cost_vs_mmlt rays_per_proposal acceptance acceptance_se", name, " ") }
END {
    print "| method (equal CPU time) | seeds | relMSE | CPU µs per proposal | cost vs MMLT large steps | rays per proposal | acceptance |"
    print "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"
    for (i = 1; i <= n; i++)
        printf "| %s | %d | %.4g ± %.2g | %.3g ± %.2g | %.2f | %.2f | %.4f ± %.4f |\n", c[i, 1], c[i, 2], c[i, 3], c[i, 4],
            c[i, 5], c[i, 6], c[i, 7], c[i, 8], c[i, 9], c[i, 10]
}' "$1"
[ -f "$(dirname "$1")/claims.md" ] && { echo; cat "$(dirname "$1")/claims.md"; }
exit 0
