#!/usr/bin/env bash
# MMLT paper §5 / Fig. 5 (make mmlt-ratio): per-technique contribution and sample-count images of one
# path length K, MMLT against PSSMLT, from `bin/render --technique-images K` (core/stats/tech_image.h).
# Renders seeds 1..SEEDS of both methods into OUTDIR, then writes
#   OUTDIR/tech.md                the shares per technique and the "follow" statistics, mean ± standard
#                                 error over seeds, then OUTDIR/claims.md: the verdicts on the paper's
#                                 claim (M-f; claims.csv beside it, bin/ch6_tech --claims). The follow
#                                 statistics (bin/ch6_tech) compare each run's sample counts with the
#                                 mean contribution images of all OTHER runs of both methods (MMLT's
#                                 own contribution images are its counts times a constant);
#   OUTDIR/technique-images.png   seed 1: rows MMLT contribution, MMLT samples, PSSMLT contribution,
#                                 PSSMLT samples; one column per technique, labelled (s, t).
# usage: ch6-tech.sh BINDIR SCENE K SEEDS OUTDIR [--scale quick|full|paper] [bin/render options...]
#   (BINDIR holds render, ch6_tech). The scales, this figure's only table of them: each run renders
#   8 s (quick), 60 s (full) or 120 s (paper); without --scale the options must give the budget.
set -euo pipefail
usage="usage: ch6-tech.sh BINDIR SCENE K SEEDS OUTDIR [--scale quick|full|paper] [bin/render options...]"
[ $# -ge 5 ] || { echo "$usage" >&2; exit 2; }
render=$1/render tool=$1/ch6_tech scene=$2 k=$3 seeds=$4 out=$5
shift 5
scale=custom
if [ "${1:-}" = --scale ]; then
  scale=$2
  case "${2:-}" in
    quick) budget=(--time 8) ;;
    full) budget=(--time 60) ;;
    paper) budget=(--time 120) ;;
    *) echo "ch6-tech: --scale must be quick, full or paper, got '${2:-}'" >&2; exit 2 ;;
  esac
  shift 2
  set -- "${budget[@]}" "$@"
fi
[ -x "$render" ] && [ -x "$tool" ] && [ -f "$scene" ] || { echo "ch6-tech: $render or $tool is not executable, or $scene not found" >&2; exit 2; }
[[ $k =~ ^[1-9][0-9]*$ && $seeds =~ ^[1-9][0-9]*$ ]] && [ "$seeds" -ge 2 ] ||
  { echo "ch6-tech: K must be a positive integer and SEEDS an integer >= 2 (standard errors), got '$k' '$seeds'" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
for m in mmlt pssmlt; do
  for s in $(seq 1 "$seeds"); do
    echo "ch6-tech: $m seed $s" >&2
    "$render" "$scene" --method "$m" --technique-images "$k" --seed "$s" --threads 2 --quiet --out "$out/$m-s$s" "$@" > "$out/$m-s$s.log" 2>&1 ||
      { echo "ch6-tech: render failed, see $out/$m-s$s.log" >&2; exit 1; }
  done
done

# Each run's sample counts against the mean contribution images of all other runs (both methods).
runs() { for s in $(seq 1 "$seeds"); do echo "$out/$1-s$s"; done; }
"$tool" --k "$k" --out "$out/follow-mmlt.csv" --ref $(runs mmlt) $(runs pssmlt) --run $(runs mmlt)
"$tool" --k "$k" --out "$out/follow-pssmlt.csv" --ref $(runs mmlt) $(runs pssmlt) --run $(runs pssmlt)
# The paper's claim on them (M-f), its verdicts from the tool: OUTDIR/claims.csv and claims.md.
"$tool" --k "$k" --claims "$out" --scale "$scale" --command "make mmlt-ratio SCALE=$scale" \
  --follow "$out/follow-mmlt.csv" "$out/follow-pssmlt.csv" > /dev/null

# Tables: per technique and per method, mean ± standard error over the seeds.
tmp="$out/.tech.md.tmp$$"
trap 'rm -f "$tmp"' EXIT # a failed write (a full disk) leaves no temporary
awk -F, -v k="$k" -v seeds="$seeds" '
  FNR == 1 { m = FILENAME; sub(/.*\//, "", m); sub(/-s[0-9]+\.tech\.csv$/, "", m) }
  FILENAME ~ /follow-/ { if (/^#/ || $1 == "run") next; m = FILENAME; sub(/.*follow-/, "", m); sub(/\.csv$/, "", m)
    tv[m, ++ntv[m]] = $2; r[m, ++nr[m]] = $3; next }
  /^# chain_samples / { v = $0; sub(/^# chain_samples /, "", v); ns[m] += v }
  /^# mutations / { v = $0; sub(/^# mutations /, "", v); nm[m] += v }
  /^[0-9]/ { t = $1; ss[m, t, ++n_ss[m, t]] = $5; cs[m, t, n_ss[m, t]] = $7; sv[t] = $2 }
  function mse(a, key, n,    i, s, q, mu) { s = 0; for (i = 1; i <= n; i++) s += a[key, i]; mu = s / n
    q = 0; for (i = 1; i <= n; i++) q += (a[key, i] - mu)^2; M = mu; SE = sqrt(q / (n - 1) / n) }
  function mse3(a, mm, t, n,    i, s, q, mu) { s = 0; for (i = 1; i <= n; i++) s += a[mm, t, i]; mu = s / n
    q = 0; for (i = 1; i <= n; i++) q += (a[mm, t, i] - mu)^2; M = mu; SE = sqrt(q / (n - 1) / n) }
  END {
    printf "Path length k = %d, %d seeds per method; shares in %% (mean ± standard error over seeds).\n\n", k, seeds
    printf "| technique (s, t) | MMLT samples | MMLT contribution | PSSMLT samples | PSSMLT contribution |\n| --- | ---: | ---: | ---: | ---: |\n"
    for (t = 1; t <= k + 1; t++) {
      printf "| (%d, %d) |", sv[t], t
      split("mmlt pssmlt", ms, " ")
      for (j = 1; j <= 2; j++) {
        mse3(ss, ms[j], t, n_ss[ms[j], t]); printf " %.1f ± %.1f |", 100 * M, 100 * SE
        mse3(cs, ms[j], t, n_ss[ms[j], t]); printf " %.1f ± %.1f |", 100 * M, 100 * SE
      }
      printf "\n"
    }
    printf "\nEach run'"'"'s sample counts against the mean contribution images of all other runs of both methods (leave one out; an MMLT run'"'"'s own contribution images are its counts times a constant):\n\n"
    printf "| method | tv: ½ Σ_t \\|sample share − contribution share\\| | r: 8×8-block share correlation | length-k chain samples per run | mutations per run |\n| --- | ---: | ---: | ---: | ---: |\n"
    for (j = 1; j <= 2; j++) {
      mm = ms[j]; mse(tv, mm, ntv[mm]); tvm[mm] = M; tvs[mm] = SE; mse(r, mm, nr[mm]); rm[mm] = M; rs[mm] = SE
      printf "| %s | %.4f ± %.4f | %.3f ± %.3f | %.0f | %.0f |\n", (mm == "mmlt" ? "MMLT" : "PSSMLT"), tvm[mm], tvs[mm], rm[mm], rs[mm], ns[mm] / ntv[mm], nm[mm] / ntv[mm]
    }
    printf "\n"
  }' $(for m in mmlt pssmlt; do for s in $(seq 1 "$seeds"); do echo "$out/$m-s$s.tech.csv"; done; done) "$out/follow-mmlt.csv" "$out/follow-pssmlt.csv" > "$tmp"
cat "$out/claims.md" >> "$tmp"
mv -f "$tmp" "$out/tech.md"

# The montage of seed 1.
args=()
for row in "mmlt tech MMLT contrib." "mmlt count MMLT samples" "pssmlt tech PSSMLT contrib." "pssmlt count PSSMLT samples"; do
  read -r m kind label <<<"$row"
  for t in $(seq 1 $((k + 1))); do args+=("$out/$m-s1.$kind-t$t.png" "$label ($((k + 1 - t)),$t)"); done
done
read -r W H < <(oiiotool --info "$out/mmlt-s1.png" | awk '{for (i = 1; i < NF; i++) if ($(i + 1) == "x") {sub(",", "", $(i + 2)); print $i, $(i + 2); exit}}')
bash "$here/ch4-montage.sh" "$out/technique-images.png" $((k + 1)) "${W}x${H}" "${args[@]}"
cat "$out/tech.md"
