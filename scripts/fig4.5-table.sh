#!/usr/bin/env bash
# Markdown table of results/fig4.5/fig4.5.csv: per length, both methods' mean acceptance with its
# batch-means standard error, and the MCTLS / MMLT ratio. usage: fig4.5-table.sh CSV > TABLE.md
set -euo pipefail
awk -F, '
/^#/ || $1 == "method" { next }
{ key = $2 + 0; m[$1, key] = $4; s[$1, key] = $5; if (key > K) K = key }
END {
    print "| length | MMLT large steps | MCTLS | MCTLS / MMLT |"
    print "| ---: | ---: | ---: | ---: |"
    for (k = 1; k <= K; k++) {
        if (!(("mmlt-large", k) in m) && !(("mctls", k) in m)) { printf "| %d | no light | no light | – |\n", k; continue }
        a = m["mmlt-large", k]; b = m["mctls", k]
        r = (a > 0) ? sprintf("%.2f", b / a) : "–"
        printf "| %d | %.5f ± %.5f | %.5f ± %.5f | %s |\n", k, a, s["mmlt-large", k], b, s["mctls", k], r
    }
}' "$1"
