#!/usr/bin/env bash
# Markdown answer of the hybrid-MCTLS study from bin/ch6_equal summaries (make hybrid-study): relMSE
# per method (mean +- standard error over seeds) and each hybrid against MMLT large steps and MCTLS
# (difference and z = difference / combined standard error; negative = the hybrid is better).
# usage: ch6-hybrid.sh SUMMARY.csv...
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: ch6-hybrid.sh SUMMARY.csv..." >&2; exit 2; }
csvcol=$(cat "$(dirname "$0")/csv-col.awk")
for f in "$@"; do
  [ -f "$f" ] || { echo "ch6-hybrid: $f not found" >&2; exit 2; }
  awk -F, "$csvcol"'!/^#/ { k = get("method"); scene = get("scene"); m[++n] = k; r[k] = get("relmse"); se[k] = get("relmse_se")
      mps[k] = get("mutations_per_s"); seeds = get("seeds"); t = get("budget") }
    END {
      printf "**%s**, %s s per run, %d seeds\n\n| method | relMSE | mutations/s | vs MMLT large steps (z) | vs MCTLS (z) |\n| --- | ---: | ---: | ---: | ---: |\n", scene, t, seeds
      for (i = 1; i <= n; i++) {
        k = m[i]; a = ""; b = ""
        if (k ~ /^hybrid/) {
          a = sprintf("%+.4f (%+.1f)", r[k] - r["mmlt"], (r[k] - r["mmlt"]) / sqrt(se[k]^2 + se["mmlt"]^2))
          b = sprintf("%+.4f (%+.1f)", r[k] - r["mctls"], (r[k] - r["mctls"]) / sqrt(se[k]^2 + se["mctls"]^2))
        }
        printf "| %s | %.4f ± %.4f | %.0f | %s | %s |\n", k, r[k], se[k], mps[k], a, b
      }
      print ""
    }' "$f"
done
