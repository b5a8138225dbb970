#!/usr/bin/env bash
# Markdown table of the non-zero fractions in bin/ch6_equal summaries (make mmlt-ratio).
# usage: ch6-ratio.sh SUMMARY.csv...   (the row of each method at the largest budget)
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: ch6-ratio.sh SUMMARY.csv..." >&2; exit 2; }
echo "| scene | method | non-zero, all proposals | non-zero, large steps | mutations/s |"
echo "| --- | --- | ---: | ---: | ---: |"
for f in "$@"; do
  [ -f "$f" ] || { echo "ch6-ratio: $f not found" >&2; exit 2; }
  awk -F, '!/^#/ && $1 != "scene" { if ($3 + 0 >= max[$2] + 0) { max[$2] = $3; row[$2] = $0 } if (!seen[$2]++) order[++n] = $2 }
    END { for (i = 1; i <= n; i++) { split(row[order[i]], c, ","); 
      printf "| %s | %s | %.2f %% ± %.2f | %.2f %% ± %.2f | %.0f |\n", c[1], c[2], 100 * c[11], 100 * c[12], 100 * c[13], 100 * c[14], c[9] } }' "$f"
done
echo
echo "MMLT paper §5 (door scene): 11.81 % of PSSMLT's samples and 29.75 % of MMLT's have non-zero contribution."
echo "Here (all proposals; z = difference / combined standard error over seeds):"
echo
for f in "$@"; do
  awk -F, '!/^#/ && $1 != "scene" { if ($3 + 0 >= max[$2] + 0) { max[$2] = $3; nz[$2] = $11; se[$2] = $12 } scene = $1 }
    END { if (!("mmlt" in nz) || !("pssmlt" in nz)) exit
      z = (nz["mmlt"] - nz["pssmlt"]) / sqrt(se["mmlt"]^2 + se["pssmlt"]^2)
      printf "- %s: MMLT %.2f %% vs PSSMLT %.2f %% (z = %.1f): **%s**\n", scene, 100 * nz["mmlt"], 100 * nz["pssmlt"], z,
        (z > 2) ? "holds" : (z > 0) ? "holds in the mean, not significantly" : "does not hold" }' "$f"
done
