#!/usr/bin/env bash
# Markdown table of results/fig4.5/fig4.5.csv: per length, both methods' mean acceptance with its
# batch-means standard error, and the MCTLS / MMLT ratio; then the ratios of the other runs
# (fixed numbers of drawn trials, the thesis's k + 2 count). usage: fig4.5-table.sh CSV > TABLE.md
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
    if (!(("mctls-tries1-t0", K) in m)) exit
    print ""
    print "Acceptance over MMLT large steps per length: with 1, 2, 4 trials drawn uniformly among the k + 1 techniques, and MCTLS over MMLT large steps drawn among k + 2 (the thesis count, t = 0 a failed try):"
    print ""
    print "| length | 1 trial / MMLT | 2 trials / MMLT | 4 trials / MMLT | MCTLS / MMLT (k + 1) | MCTLS / MMLT (k + 2) |"
    print "| ---: | ---: | ---: | ---: | ---: | ---: |"
    for (k = 1; k <= K; k++) {
        a = m["mmlt-large", k]; t = m["mctls-tries1-t0", k]
        if (!(a > 0) || !(t > 0)) continue
        printf "| %d | %.2f | %.2f | %.2f | %.2f | %.2f |\n", k, m["mctls-tries1", k] / a, m["mctls-tries2", k] / a, m["mctls-tries4", k] / a, m["mctls", k] / a, m["mctls", k] / t
    }
}' "$1"
