#!/usr/bin/env bash
# Markdown table of results/fig4.6/fig4.6.csv. usage: fig4.6-table.sh CSV > TABLE.md
set -euo pipefail
awk -F, '
/^#/ || $1 == "method" { next }
{ n++; name[n] = $1; sec[n] = $2; mut[n] = $3; err[n] = $4; if (n == 1 || $4 < best) best = $4 }
END {
    print "| method (equal time) | seconds | mutations | mutations/s | relMSE | relMSE / best |"
    print "| --- | ---: | ---: | ---: | ---: | ---: |"
    for (i = 1; i <= n; i++)
        printf "| %s | %.1f | %d | %.0f | %.4g | %.2f |\n", name[i], sec[i], mut[i], mut[i] / sec[i], err[i], err[i] / best
}' "$1"
