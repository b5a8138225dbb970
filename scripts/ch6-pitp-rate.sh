#!/usr/bin/env bash
# make pitp-rate's answer, from bin/ch6_equal's summaries of PITP at technique-perturbation rates P
# (methods named pP, e.g. p0.05): per scene a Markdown table of relMSE, relMSE without the
# normalisation's part (every P of a seed shares its seed pass), its firefly-robust variants (median
# block relMSE, relMSE without the 0.1 % largest pixel errors) and the splotch statistics
# (block-relMSE spread, error share surviving an 8x8 blur, error correlation length) against P,
# mean ± standard error over seeds, the best P by each of the first three, and a plot per
# scene (scripts/ch6-pitp-rate.gp: DIR/SCENE/pitp-rate.png). The table goes to stdout and to
# DIR/pitp-rate.md.
# usage: ch6-pitp-rate.sh DIR SCENE...
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: ch6-pitp-rate.sh DIR SCENE..." >&2; exit 2; }
here=$(dirname "$0")
csvcol=$(cat "$here/csv-col.awk")
dir=$1
shift
table() {
  for scene in "$@"; do
    f=$dir/$scene/summary.csv
    [ -f "$f" ] || { echo "ch6-pitp-rate: $f not found" >&2; exit 2; }
    awk -F, -v scene="$scene" "$csvcol"'!/^#/ && get("method") ~ /^p[0-9.]+$/ {
        m[++n] = get("method"); P[n] = substr(m[n], 2) + 0; t = get("budget"); seeds = get("seeds")
        split("relmse relmse_scaled block_median_relmse trimmed_relmse block_spread blur8_share corr_length", q, " ")
        for (j = 1; j <= 7; j++) { v[n, j] = get(q[j]); s[n, j] = get(q[j] "_se") }
      }
      END {
        printf "**%s**, PITP at rate P, %s s per run, %d seeds; mean ± standard error over seeds\n\n", scene, t, seeds
        print "| P | relMSE | relMSE without the normalisation | median block relMSE | relMSE without top 0.1 % | block-relMSE spread (CV) | error share after 8x8 blur | error correlation length (px) |"
        print "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
        b1 = b2 = b3 = 1
        for (i = 1; i <= n; i++) {
          printf "| %g |", P[i]
          for (j = 1; j <= 7; j++) printf " %.4g ± %.2g |", v[i, j], s[i, j]
          printf "\n"
          if (v[i, 1] < v[b1, 1]) b1 = i
          if (v[i, 2] < v[b2, 2]) b2 = i
          if (v[i, 3] < v[b3, 3]) b3 = i
        }
        printf "\nbest P: %g by relMSE (%.4g ± %.2g), %g by relMSE without the normalisation (%.4g ± %.2g), %g by median block relMSE (%.4g ± %.2g)\n\n", P[b1], v[b1, 1], s[b1, 1], P[b2], v[b2, 2], s[b2, 2], P[b3], v[b3, 3], s[b3, 3]
      }' "$f"
  done
}
table "$@" | tee "$dir/pitp-rate.md"
for scene in "$@"; do
  bash "$here/plot.sh" "$here/ch6-pitp-rate.gp" "$dir/$scene/summary.csv" "$dir/$scene/pitp-rate" "name='$scene'"
done
echo "plots: $(printf "$dir/%s/pitp-rate.png " "$@")"
