#!/usr/bin/env bash
# Error x time against Tungsten 0.2.2 (issue 44): whole processes, one thread each, SEEDS seeds at SPP
# samples or mutations per pixel, on an ajar-like interior (scenes/ajar at 240x160, paths of up to 8
# segments) and on scenes/glass-marble (200x150, its own 8). Pairs: BDPT / bidirectional_path_tracer
# (ours with independent numbers and with --sampler sobol; Tungsten's default is its Sobol sampler;
# its adaptive sampling, on by default, is read by its path tracer only), PSSMLT / kelemen_mlt
# (ours as the thesis splats, and with --large-step-mis, Kelemen et al.'s weights, which kelemen_mlt
# uses), MMLT / multiplexed_mlt, PITP / reversible_jump_mlt;
# normalisation pools of about equal size: Tungsten's MMLT and reversible jump take 300 000 candidate
# connections (every (s, t) of its BDPT samples: some 10 000 samples), ours 10 000 seed paths (one
# state per length each; the default is 100 000), PSSMLT 10 000 BDPT samples on both sides. Time is the process's CPU time
# (user + system, /usr/bin/time), which a loaded machine inflates far less than wall time.
# relMSE per channel, (I - R)^2 / (R^2 + 0.01), against Tungsten's own BDPT at REF_SPP on 2 threads,
# cached in OUT. Efficiency = 1 / (mean relMSE x mean time). Needs `tungsten` on PATH
# (../shared/README.md builds it); without it, says so and exits 0.
# usage: bench-tungsten.sh BIN_DIR [OUT] (env: SEEDS=4 SPP=256 REF_SPP=8192 SCENES="ajar glass-marble"
#        PAIRS="bdpt bdpt-sobol pssmlt pssmlt-mis mmlt pitp"; a variant needs its base pair before it)
set -euo pipefail
[ $# -ge 1 ] || { echo "usage: bench-tungsten.sh BIN_DIR [OUT]" >&2; exit 2; }
bin=$1 out=${2:-results/bench-tungsten}
command -v tungsten >/dev/null || { echo "bench-tungsten: no tungsten on PATH: not measured"; exit 0; }
SEEDS=${SEEDS:-4} SPP=${SPP:-256} REF_SPP=${REF_SPP:-8192} SCENES=${SCENES:-"ajar glass-marble"}
PAIRS=${PAIRS:-"bdpt bdpt-sobol pssmlt pssmlt-mis mmlt pitp"}
mkdir -p "$out"

# scene_json SCENE INTEGRATOR_TYPE EXTRA SPP SEED NAME: a copy of the scene at the benchmark's size
# and bounces, with the integrator and renderer lines replaced (both scenes keep each on one line)
scene_json() {
  local src=scenes/$1/scene.json dst=$out/$6.json res bounces
  case $1 in
    ajar) res='240, 160' bounces=8 ;;
    glass-marble) res='200, 150' bounces=8 ;;
    *) echo "bench-tungsten: no settings for scene $1" >&2; exit 2 ;;
  esac
  sed -e "s|\"resolution\": \[[0-9]*, [0-9]*\]|\"resolution\": [$res]|" \
      -e "s|\"integrator\": {.*}|\"integrator\": {\"type\": \"$2\", \"min_bounces\": 0, \"max_bounces\": $bounces, \"enable_two_sided_shading\": true$3}|" \
      -e "s|\"renderer\": {.*}|\"renderer\": {\"spp\": $4, \"output_file\": \"$6.png\", \"hdr_output_file\": \"$6.pfm\"}|" \
      "$src" > "$dst"
  echo "$dst"
}

# cpu_of COMMAND...: runs it, prints its CPU seconds (user + system)
cpu_of() {
  local t; t=$(mktemp)
  /usr/bin/time -f "%U %S" -o "$t" "$@" >/dev/null 2>"$t.err" || { cat "$t.err" >&2; rm -f "$t" "$t.err"; return 1; }
  awk '{ print $1 + $2 }' "$t"; rm -f "$t" "$t.err"
}

# relmse IMAGE REF: mean over pixels and channels of (I - R)^2 / (R^2 + 0.01)
relmse() {
  oiiotool "$1" "$2" --sub --powc 2 "$2" --powc 2 --addc 0.01 --div --printstats 2>/dev/null |
    awk '/Stats Avg:/ { s = 0; n = 0; for (i = 3; i <= NF; i++) if ($i ~ /^[-+0-9.eE]+$/) { s += $i; n++ }
                        print s / n; exit }'
}

ours_args() {
  case $1 in
    bdpt) echo "--method bdpt" ;; bdpt-sobol) echo "--method bdpt --sampler sobol" ;;
    pssmlt) echo "--method pssmlt --seed-paths 10000" ;;
    pssmlt-mis) echo "--method pssmlt --seed-paths 10000 --large-step-mis" ;;
    mmlt) echo "--method mmlt --seed-paths 10000" ;; pitp) echo "--method pitp --seed-paths 10000" ;;
  esac
}
tungsten_type() {
  case $1 in
    bdpt) echo "bidirectional_path_tracer|" ;; pssmlt) echo "kelemen_mlt|, \"initial_sample_pool\": 10000" ;;
    mmlt) echo "multiplexed_mlt|, \"initial_sample_pool\": 300000" ;;
    pitp) echo "reversible_jump_mlt|, \"initial_sample_pool\": 300000" ;;
  esac
}

runs=$out/runs.csv # every run of this invocation: the medians below, and per-seed reading
echo "scene,pair,renderer,seed,relmse,cpu_s" > "$runs"
printf "| scene | pair | ours relMSE | Tungsten relMSE | ours CPU s | Tungsten CPU s | relMSE, ours / Tungsten | time, Tungsten / ours | efficiency, ours / Tungsten |\n"
printf "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n"
for scene in $SCENES; do
  ref=$out/$scene-ref.pfm
  if [ ! -s "$ref" ]; then
    j=$(scene_json "$scene" bidirectional_path_tracer "" "$REF_SPP" 1000 "$scene-ref")
    (cd "$out" && tungsten -t 2 -s 1000 "$(basename "$j")" >/dev/null 2>&1)
  fi
  for pair in $PAIRS; do
    base=${pair%-*} # a variant (-sobol, -mis) is compared with its base pair's Tungsten runs
    tp=$(tungsten_type "$base")
    o_err=0 o_t=0 t_err=0 t_t=0
    for s in $(seq 1 "$SEEDS"); do
      j=$(scene_json "$scene" bidirectional_path_tracer "" "$SPP" "$s" "$scene-$pair-ours-$s")
      # shellcheck disable=SC2046
      c=$(cpu_of "$bin/render" "$j" $(ours_args "$pair") --spp "$SPP" --seed "$s" --threads 1 --out "$out/$scene-$pair-ours-$s" --quiet)
      e=$(relmse "$out/$scene-$pair-ours-$s.exr" "$ref")
      echo "$scene,$pair,ours,$s,$e,$c" >> "$runs"
      o_err=$(awk -v a="$o_err" -v b="$e" 'BEGIN { print a + b }') o_t=$(awk -v a="$o_t" -v b="$c" 'BEGIN { print a + b }')
      [ "$pair" != "$base" ] && continue
      j=$(scene_json "$scene" "${tp%%|*}" "${tp#*|}" "$SPP" "$s" "$scene-$pair-tungsten-$s")
      c=$(cd "$out" && cpu_of tungsten -t 1 -s "$s" "$(basename "$j")")
      e=$(relmse "$out/$scene-$pair-tungsten-$s.pfm" "$ref")
      echo "$scene,$pair,tungsten,$s,$e,$c" >> "$runs"
      t_err=$(awk -v a="$t_err" -v b="$e" 'BEGIN { print a + b }') t_t=$(awk -v a="$t_t" -v b="$c" 'BEGIN { print a + b }')
    done
    if [ "$pair" != "$base" ]; then t_err=$b_t_err t_t=$b_t_t; else b_t_err=$t_err b_t_t=$t_t; fi
    awk -v sc="$scene" -v p="$pair" -v oe="$o_err" -v ot="$o_t" -v te="$t_err" -v tt="$t_t" -v n="$SEEDS" 'BEGIN {
      oe /= n; ot /= n; te /= n; tt /= n
      printf "| %s | %s | %.4g | %.4g | %.2f | %.2f | %.2f | %.2f | %.2f |\n", sc, p, oe, te, ot, tt, oe / te, tt / ot, (te * tt) / (oe * ot)
    }'
  done
done
# One stuck chain can decide an MCMC mean over a few seeds: the same efficiency on median relMSE
# (times stay means; a variant's Tungsten runs are its base pair's)
printf "\n| scene | pair | ours median relMSE | Tungsten median relMSE | efficiency on medians, ours / Tungsten |\n| --- | --- | ---: | ---: | ---: |\n"
# med|mean SCENE PAIR RENDERER: the median relMSE, the mean CPU seconds of those runs
med() { awk -F, -v sc="$1" -v p="$2" -v r="$3" '$1 == sc && $2 == p && $3 == r { print $5 }' "$runs" | sort -g |
  awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
mean() { awk -F, -v sc="$1" -v p="$2" -v r="$3" '$1 == sc && $2 == p && $3 == r { s += $6; n++ } END { print s / n }' "$runs"; }
for scene in $SCENES; do
  for pair in $PAIRS; do
    base=${pair%-*}
    awk -v sc="$scene" -v p="$pair" -v oe="$(med "$scene" "$pair" ours)" -v te="$(med "$scene" "$base" tungsten)" \
        -v ot="$(mean "$scene" "$pair" ours)" -v tt="$(mean "$scene" "$base" tungsten)" 'BEGIN { printf "| %s | %s | %.4g | %.4g | %.2f |\n", sc, p, oe, te, (te * tt) / (oe * ot) }'
  done
done
