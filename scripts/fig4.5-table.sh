#!/usr/bin/env bash
# Markdown table of results/fig4.5/fig4.5.csv: per length, both methods' mean acceptance with its
# batch-means standard error, and the MCTLS / MMLT ratio; then the ratios of the other runs
# (fixed numbers of drawn trials, the thesis's k + 2 count) and, from RATIOS (fig4.5-ratios.csv), the
# mean number of techniques that carry light for a pair of subpaths that has any; then, from TRIALS
# (fig4.5-trials.csv), both acceptances predicted from independent pairs of subpaths and the factors
# of their ratio.
# usage: fig4.5-table.sh CSV [RATIOS [TRIALS]] > TABLE.md
set -euo pipefail
cols=$(cat "$(dirname "$0")/csv-col.awk")
awk -F, "$cols"'
/^#/ { next }
ARGC > 3 && FILENAME == ARGV[3] { len = get("length") + 0; st = get("statistic"); tv[len, st] = get("value"); ts[len, st] = get("se"); tr = 1; next }
FILENAME != ARGV[1] { if (get("ratio") == "contributing-techniques") { len = get("length") + 0; ct[len] = get("value"); cts[len] = get("se") }; next }
{ key = get("length") + 0; meth = get("method"); m[meth, key] = get("mean_accept"); s[meth, key] = get("stderr"); if (key > K) K = key }
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
    print "| length | 1 trial / MMLT | 2 trials / MMLT | 4 trials / MMLT | MCTLS / MMLT (k + 1) | MCTLS / MMLT (k + 2) | techniques with light, of k + 1 | proposals with light, MCTLS / MMLT | acceptance given light, MCTLS / MMLT |"
    print "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    for (k = 1; k <= K; k++) {
        a = m["mmlt-large", k]; t = m["mctls-tries1-t0", k]
        if (!(a > 0) || !(t > 0)) continue
        c = (k in ct) ? sprintf("%.2f ± %.2f of %d", ct[k], cts[k], k + 1) : "–"
        # E[min(1, a)] = P(light) E[min(1, a) | light]: the ratio splits into the two factors
        l = (k in ct) ? sprintf("%.2f", (k + 1) / ct[k]) : "–"
        g = (k in ct) ? sprintf("%.2f", m["mctls", k] / a * ct[k] / (k + 1)) : "–"
        printf "| %d | %.2f | %.2f | %.2f | %.2f | %.2f | %s | %s | %s |\n", k, m["mctls-tries1", k] / a, m["mctls-tries2", k] / a, m["mctls-tries4", k] / a, m["mctls", k] / a, m["mctls", k] / t, c, l, g
    }
    if (!tr) exit
    print ""
    print "Predicted from independent pairs of subpaths (both large steps are independence samplers: acceptance = E[min(W1, W2)] / E[W] over the proposal; jackknife errors). The ratio MCTLS / MMLT = (proposals with light) x (acceptance given light); the last column is the second factor with MCTLS'"'"'s target the mean over the techniques with light instead of their sum:"
    print ""
    print "| length | MMLT large steps | MCTLS | MCTLS / MMLT | proposals with light, MCTLS / MMLT | acceptance given light, MCTLS / MMLT | techniques with light | their coefficient of variation | acceptance given light, target = mean over the techniques |"
    print "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    for (k = 2; k <= K; k++) {
        if (!((k, "accept_mmlt") in tv)) continue
        printf "| %d | %.5f ± %.5f | %.5f ± %.5f", k, tv[k, "accept_mmlt"], ts[k, "accept_mmlt"], tv[k, "accept_mctls"], ts[k, "accept_mctls"]
        n = split("accept_ratio light_ratio given_light_ratio techniques_with_light techniques_cv given_light_ratio_mean", q, " ")
        for (i = 1; i <= n; i++) printf " | %.3f ± %.3f", tv[k, q[i]], ts[k, q[i]]
        printf " |\n"
    }
}' "$@"
