#!/usr/bin/env bash
# Markdown table of the non-zero fractions in bin/ch6_equal summaries (make mmlt-ratio).
# usage: ch6-ratio.sh SUMMARY.csv...   (the row of each method at the largest budget)
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: ch6-ratio.sh SUMMARY.csv..." >&2; exit 2; }
echo "| scene | method | non-zero per proposal | non-zero per connection | non-zero, large steps | mutations/s |"
echo "| --- | --- | ---: | ---: | ---: | ---: |"
for f in "$@"; do
  [ -f "$f" ] || { echo "ch6-ratio: $f not found" >&2; exit 2; }
  awk -F, '!/^#/ && $1 != "scene" { if ($3 + 0 >= max[$2] + 0) { max[$2] = $3; row[$2] = $0 } if (!seen[$2]++) order[++n] = $2 }
    END { for (i = 1; i <= n; i++) { split(row[order[i]], c, ",");
      printf "| %s | %s | %.2f %% ± %.2f | %.2f %% ± %.2f | %.2f %% ± %.2f | %.0f |\n", c[1], c[2], 100 * c[11], 100 * c[12],
        100 * c[25], 100 * c[26], 100 * c[13], 100 * c[14], c[9] } }' "$f"
done
echo
echo "MMLT paper §5 (door scene): 11.81 % of PSSMLT's samples and 29.75 % of MMLT's have non-zero contribution."
echo "A PSSMLT proposal evaluates every connection of its subpaths and counts as non-zero when any of them is;"
echo "an MMLT proposal evaluates one. The verdicts, from each scene's claims.csv (bin/ch6_equal; z over seeds):"
echo
for f in "$@"; do
  c="$(dirname "$f")/claims.csv"
  [ -f "$c" ] || { echo "ch6-ratio: $c not found (rerun bin/ch6_equal)" >&2; exit 2; }
  scene=$(basename "$(dirname "$f")")
  # claim,statistic,method,value,se,z_by_method,z_min,verdict,seeds_needed: fields 2-10
  awk -F, -v scene="$scene" '!/^#/ && $1 != "source" && $2 ~ /^\(4\)/ {
      printf "- %s, %s: MMLT %.2f %% ± %.2f (%s): **%s**%s\n", scene, $3, 100 * $5, 100 * $6, $7, $9,
        (($9 == "undecided" && $10 > 0) ? sprintf(" (%d seeds would decide it)", $10) : "") }' "$c"
done
