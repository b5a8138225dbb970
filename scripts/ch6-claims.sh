#!/usr/bin/env bash
# The thesis's chapter-6 claims checked on one bin/ch6_equal summary.csv (largest budget), each
# against every other method of the file:
#  (1) PSSMLT is worst: the highest relMSE (it evaluates all connections: fewest mutations/s);
#  (2) MMLT is streaky/splotchy: the largest spread (coefficient of variation of the per-16x16-block
#      relMSE) of the methods;
#  (3) PITP is the most uniform: the smallest spread.
# z = difference / combined standard error over seeds, for the method against each other one. A claim
# "holds" when it holds in the mean against every method with z > 2 each; "holds in the mean, not
# significantly" when some z <= 2; otherwise "does not hold" (naming the method that breaks it); a
# method missing from the file makes its claim "not tested". usage: ch6-claims.sh SUMMARY.csv
set -euo pipefail
[ $# -eq 1 ] && [ -f "$1" ] || { echo "usage: ch6-claims.sh SUMMARY.csv" >&2; exit 2; }
awk -F, '!/^#/ && $1 != "scene" { if ($3 + 0 >= T + 0) T = $3 }
  { rows[NR] = $0 }
  # claim: method m has the largest (sign 1) or smallest (sign -1) value v[] among all methods
  function extreme(title, m, v, se, sign, what,    o, z, zmin, ok, list, bad, verdict) {
    if (!have[m]) { printf "- %s: **not tested** (%s is not in this run)\n", title, m; return }
    ok = 1; zmin = 1e9; list = ""; bad = ""
    for (o in have) {
      if (o == m) continue
      z = sign * (v[m] - v[o]) / sqrt(se[m]^2 + se[o]^2)
      if (z < zmin) zmin = z
      if (sign * (v[m] - v[o]) <= 0) { ok = 0; bad = bad " " o }
      list = list sprintf("; %s %.4g ± %.2g (z = %.1f)", o, v[o], se[o], z)
    }
    verdict = !ok ? "does not hold (not " (sign > 0 ? "above" : "below") bad ")" : (zmin > 2) ? "holds" : "holds in the mean, not significantly (some z <= 2)"
    printf "- %s: %s %s %.4g ± %.2g%s: **%s**\n", title, m, what, v[m], se[m], list, verdict
  }
  END {
    for (i = 1; i <= NR; i++) { n = split(rows[i], c, ","); if (rows[i] ~ /^#/ || c[1] == "scene" || c[3] + 0 != T + 0) continue
      m = c[2]; scene = c[1]; have[m] = 1; r[m] = c[5]; rs[m] = c[6]; s[m] = c[7]; ss[m] = c[8]; mps[m] = c[9] }
    printf "Claims on %s at %s s per run (mean ± standard error over seeds; spread = CV of the 16x16-block relMSE):\n\n", scene, T
    extreme("(1) PSSMLT worst (highest relMSE)", "pssmlt", r, rs, 1, "relMSE")
    if (have["pssmlt"]) { printf "  mutations/s:"; for (o in have) printf " %s %.0f", o, mps[o]; printf "\n" }
    extreme("(2) MMLT streaky/splotchy (largest block-relMSE spread)", "mmlt", s, ss, 1, "spread")
    extreme("(3) PITP most uniform (smallest block-relMSE spread)", "pitp", s, ss, -1, "spread")
  }' "$1"
