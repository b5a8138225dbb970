#!/usr/bin/env bash
# The thesis's chapter-6 claims checked on one bin/ch6_equal summary.csv (largest budget):
#  (1) PSSMLT is worst (highest relMSE), because it evaluates all connections (fewest mutations/s);
#  (2) MMLT's error is streaky/splotchy, PITP's most uniform: the spread (coefficient of variation of
#      the per-block relMSE) is lower for PITP than for MMLT.
# z = difference / combined standard error over seeds. usage: ch6-claims.sh SUMMARY.csv
set -euo pipefail
[ $# -eq 1 ] && [ -f "$1" ] || { echo "usage: ch6-claims.sh SUMMARY.csv" >&2; exit 2; }
awk -F, '!/^#/ && $1 != "scene" { if ($3 + 0 >= T + 0) T = $3 }
  { rows[NR] = $0 }
  END {
    for (i = 1; i <= NR; i++) { n = split(rows[i], c, ","); if (rows[i] ~ /^#/ || c[1] == "scene" || c[3] + 0 != T + 0) continue
      m = c[2]; scene = c[1]; have[m] = 1; r[m] = c[5]; rs[m] = c[6]; s[m] = c[7]; ss[m] = c[8]; mps[m] = c[9] }
    printf "Claims on %s at %s s per run:\n\n", scene, T
    if (have["pssmlt"] && have["mmlt"]) {
      z = (r["pssmlt"] - r["mmlt"]) / sqrt(rs["pssmlt"]^2 + rs["mmlt"]^2)
      worst = 1; for (m in have) if (m != "pssmlt" && r[m] >= r["pssmlt"]) worst = 0
      printf "- PSSMLT worst: relMSE %.4g ± %.2g vs MMLT %.4g ± %.2g (z = %.1f), %.0f vs %.0f mutations/s: **%s**\n",
        r["pssmlt"], rs["pssmlt"], r["mmlt"], rs["mmlt"], z, mps["pssmlt"], mps["mmlt"],
        (worst && z > 2) ? "holds" : worst ? "holds in the mean, not significantly (z < 2)" : "does not hold"
    }
    if (have["mmlt"] && have["pitp"]) {
      z = (s["mmlt"] - s["pitp"]) / sqrt(ss["mmlt"]^2 + ss["pitp"]^2)
      printf "- PITP more uniform than MMLT: block-relMSE spread %.3g ± %.2g (PITP) vs %.3g ± %.2g (MMLT), z = %.1f: **%s**\n",
        s["pitp"], ss["pitp"], s["mmlt"], ss["mmlt"], z, (z > 2) ? "holds" : (z > 0) ? "holds in the mean, not significantly" : "does not hold"
    } else if (have["mmlt"]) {
      printf "- PITP more uniform than MMLT: **not tested** (pitp is not in this build); MMLT spread %.3g ± %.2g", s["mmlt"], ss["mmlt"]
      if (have["pssmlt"]) printf ", PSSMLT %.3g ± %.2g", s["pssmlt"], ss["pssmlt"]
      printf "\n"
    }
  }' "$1"
