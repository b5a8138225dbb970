#!/usr/bin/env bash
# Markdown table of the non-zero fractions in bin/ch6_equal summaries (make mmlt-ratio).
# usage: ch6-ratio.sh SUMMARY.csv...   (the row of each method at the largest budget)
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: ch6-ratio.sh SUMMARY.csv..." >&2; exit 2; }
echo "| scene | method | non-zero per proposal | non-zero per connection | non-zero, large steps | mutations/s |"
echo "| --- | --- | ---: | ---: | ---: | ---: |"
csvcol=$(cat "$(dirname "$0")/csv-col.awk")
for f in "$@"; do
  [ -f "$f" ] || { echo "ch6-ratio: $f not found" >&2; exit 2; }
  awk -F, "$csvcol"'!/^#/ { k = get("method")
      if (get("budget") + 0 >= max[k] + 0) {
        max[k] = get("budget")
        row[k] = sprintf("| %s | %s | %.2f %% ± %.2f | %.2f %% ± %.2f | %.2f %% ± %.2f | %.0f |", get("scene"), k,
          100 * get("nonzero"), 100 * get("nonzero_se"), 100 * get("nonzero_per_connection"),
          100 * get("nonzero_per_connection_se"), 100 * get("large_nonzero"), 100 * get("large_nonzero_se"), get("mutations_per_s"))
      }
      if (!seen[k]++) order[++n] = k }
    END { for (i = 1; i <= n; i++) print row[order[i]] }' "$f"
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
  awk -F, -v scene="$scene" "$csvcol"'!/^#/ && get("claim") ~ /^\(4\)/ {
      printf "- %s, %s: MMLT %.2f %% ± %.2f (%s): **%s**%s\n", scene, get("statistic"), 100 * get("value"), 100 * get("se"),
        get("z_by_method"), get("verdict"),
        ((get("verdict") == "undecided" && get("seeds_needed") > 0) ? sprintf(" (%d seeds would decide it)", get("seeds_needed")) : "") }' "$c"
done
