#!/usr/bin/env bash
# Golden outputs: records what the tools of a build directory produce on a fixed set of small,
# count-budgeted runs, so that a refactor can be shown to leave every output bit-identical.
#
#   scripts/golden.sh record  BIN_DIR OUT_DIR   run everything with BIN_DIR's tools, store into OUT_DIR
#   scripts/golden.sh compare BIN_DIR OUT_DIR   run everything again into a temporary directory and
#                                               compare with OUT_DIR: one line per output, `same` or
#                                               `DIFFERS`, then `N same, M differ`; exit status 1 if
#                                               any differ (the temporary directory is then kept)
#
# Run it from a repository root: the scenes are ./scenes/*/scene.json, the check_stats inputs
# ./results/baselines/ (record only: they are copied into OUT_DIR/inputs/, and compare reads them
# from there). Every run happens in its own directory under a temporary work directory, with a
# `scenes` symlink to ./scenes, so the paths the tools print are the same wherever the repository
# lives, nothing is written into the repository, and no cached reference (results/reference/) is
# ever reused: every reference is rendered by the build under test. GOLDEN_ONLY=REGEX restricts
# both modes to the runs whose name matches (for chasing a difference); GOLDEN_KEEP=1 keeps the
# work directory.
#
# OUT_DIR holds
#   hashes.txt        one line per image (EXR and PNG): run/file, size, channels, type, SHA-1 of the
#                     pixel data (oiiotool --hash). Files are never hashed as bytes: EXRs written
#                     through OpenImageIO (before 2026-12-06) carried a DateTime attribute, so a
#                     record of either writer compares with the other.
#   text/RUN/...      every CSV, Markdown table, reference key and check_stats verdict, with the
#                     timing removed (below)
#   exit-status.txt   each run's exit status (compared, one output per run)
#   commands.txt      what ran (informational: compare warns when it differs, it is not an output)
#   timing.txt        seconds per run (informational, never compared)
#   inputs/           check_stats's input CSVs (a copy of results/baselines/ at record time)
#
# Timing removed from the text outputs (everything else in them is compared):
#   comment lines `# commit ...`, `# seconds ...`, `# seed_seconds ...`, `# mutations_per_second ...`, `# samples_per_second ...`;
#   `commit=...` and `seconds=...` in table1_cmlt's metadata line, `Wall time X s` in table1.md;
#   CSV columns whose name is or contains seconds/secs/time/wall as a word, or per_s/per_second
#   (render: none; fig4_3 runs: seconds; fig4_5: seconds; fig5_6: mutations_per_second;
#   table1_cmlt: steps_per_s, seconds; ch6_equal: seconds, mutations_per_s, mutations_per_s_se);
#   Markdown table columns headed mutations/s or steps/s (ch6_equal's table).
#
# Covered: bin/render on every scene x pt, bdpt, pssmlt, mmlt, pitp (--spp 2 --threads 2 --seed 7
# --resolution 48x32; --seed-paths 2000 for the MCMC methods only: pt and bdpt warn about it), the
# MCMC option variants on every scene, more variants on ajar, cornell-box and window; fig4_1,
# fig4_2, fig4_3, fig4_5, fig5_5, fig5_6, fig6_1, table1_cmlt (all mutation/sample budgeted; the
# slower ones at reduced sizes, see the runs below), ch6_tech, ch6_equal, ch6_assets, check_stats.
#
# Excluded, and why:
#   bench                wall-clock throughput (samples/s, rays/s, peak memory): nothing in it reproduces.
#   table1_cmlt --bench  the same: steps per second only.
#   fig4_6               its three renders are budgeted by wall time (--seconds; no count option), so
#                        mmlt-large/mctls/hybrid.{exr,png}, fig4.6-runs.csv, claims.{csv,md} and
#                        the seconds, mutations and relmse columns of fig4.6.csv are removed; recorded: its BDPT reference (sample
#                        budgeted: reference.{exr,png}, results/reference/ajar-bdpt-4.exr), the
#                        method column and the metadata of fig4.6.csv, the exit status.
#   ch6_equal            budgets every render by CPU or wall time (--cpu-time, --time); it is
#                        run through --render with a wrapper that drops both, and --render-args
#                        gives the runs --spp 2, so every run (and the tool's statistics) is count
#                        budgeted; only the timing columns above are removed. (The budgets, 0.5 and
#                        1 "s", are then labels of identical runs.)
#   render --checkpoint/--resume  where a run is interrupted is a matter of wall time; the
#                        bit-identical resume is tests/test_checkpoint.c's subject.
#   stdout/stderr of the tools (progress, summary lines with seconds) are not recorded, except
#                        check_stats's verdict table (its stdout).
#
# Non-zero exits that are part of the record: r.wall.mmlt-tech3 (2: the wall's paths are at most 2
# segments long, so render refuses --technique-images 3), check.table1 (1: quick vs paper stats,
# missing rows on purpose), check.bad-column (2: a column that does not exist, on purpose).
set -euo pipefail
export LC_ALL=C
unset SCALE PSS_EMBREE_ISA

prog=golden
die() { echo "$prog: $*" >&2; exit 2; }
usage() {
  echo "usage: scripts/golden.sh record|compare BIN_DIR OUT_DIR   (run from a repository root)" >&2
  exit 2
}

[ $# -eq 3 ] || usage
mode=$1
[[ $mode == record || $mode == compare ]] || usage
[ -d "$2" ] || die "$2: no such directory"
BIN=$(cd "$2" && pwd)
OUT=$3
REPO=$PWD
TOOLS=(render fig4_1 fig4_2 fig4_3 fig4_5 fig4_6 fig5_5 fig5_6 fig6_1 table1_cmlt ch6_tech ch6_equal ch6_assets check_stats)
for t in "${TOOLS[@]}"; do [ -x "$BIN/$t" ] || die "$BIN/$t is not executable"; done
compgen -G "scenes/*/scene.json" >/dev/null || die "no scenes/*/scene.json here: run from a repository root"
command -v oiiotool >/dev/null || die "oiiotool not found (openimageio-tools)"

# ---- running ----------------------------------------------------------------------------------

W=""        # work directory of the current recording
INPUTS=""   # check_stats inputs (a copy of results/baselines/)

selected() { [[ -z ${GOLDEN_ONLY:-} || $1 =~ $GOLDEN_ONLY ]]; }

# run NAME CMD...: CMD (a command or one of the functions below) in the run's own directory.
run() {
  local name=$1 d rc=0
  shift
  selected "$name" || return 0
  d=$W/runs/$name
  [ ! -e "$d" ] || die "run name $name used twice"
  mkdir -p "$d"
  ln -s "$REPO/scenes" "$d/scenes"
  printf '%s\t%s\n' "$name" "${*//$BIN/\$BIN}" >>"$W/commands.txt"
  local t0=$EPOCHREALTIME
  (cd "$d" && "$@") >"$d/.stdout" 2>"$d/.stderr" || rc=$?
  printf '%s %s\n' "$name" "$rc" >>"$W/status.txt"
  awk -v n="$name" -v a="$t0" -v b="$EPOCHREALTIME" 'BEGIN { printf "%s %.2f\n", n, b - a }' >>"$W/timing.txt"
  if [ "$rc" -ne 0 ] && [[ $name != check.* ]]; then
    echo "$prog: warning: $name exited with status $rc: $(tail -n 1 "$d/.stderr")" >&2
  fi
  return 0
}

# rr NAME SCENE METHOD [options]: bin/render at the common small budget; --spp, --threads,
# --resolution and --seed in the options replace the common ones.
rr() {
  local name=$1 scene=$2 method=$3
  shift 3
  local spp=2 threads=2 res=48x32 seed=7 extra=()
  while [ $# -gt 0 ]; do
    case $1 in
      --spp) spp=$2; shift 2 ;;
      --threads) threads=$2; shift 2 ;;
      --resolution) res=$2; shift 2 ;;
      --seed) seed=$2; shift 2 ;;
      *) extra+=("$1"); shift ;;
    esac
  done
  local mcmc=()
  [[ $method == pt || $method == bdpt ]] || mcmc=(--seed-paths 2000)
  run "r.$scene.$name" "$BIN/render" "scenes/$scene/scene.json" --method "$method" --spp "$spp" \
    --threads "$threads" --seed "$seed" --resolution "$res" --quiet "${mcmc[@]}" "${extra[@]}" --out out
}

# fig4_6: keep the BDPT reference and fig4.6.csv's method column, drop the wall-time renders.
fig4_6_run() {
  local rc=0
  # fig4_6 creates results/reference/ but not results/ (in a checkout results/ exists): as there
  mkdir -p results
  "$BIN/fig4_6" --scale quick --seconds 0.05 --reference-spp 4 --seed 1 --threads 2 --out out || rc=$?
  # every file made from the wall-time renders: their images, the per-run table and the claims on them
  rm -f out/mmlt-large.* out/mctls.* out/mctls-recompute.* out/hybrid.* out/fig4.6-runs.csv out/claims.csv out/claims.md
  if [ -f out/fig4.6.csv ]; then
    awk -F, '/^#/ { print; next } { print $1 }' out/fig4.6.csv >out/fig4.6.csv.tmp && mv out/fig4.6.csv.tmp out/fig4.6.csv
  fi
  return $rc
}

# ch6_equal through a renderer that drops --time and --cpu-time (ch6_equal's default budget; the runs get
# --spp from --render-args).
ch6_equal_run() {
  mkdir -p wrap
  cat >wrap/render <<EOF
#!/usr/bin/env bash
args=()
while [ \$# -gt 0 ]; do
  if [ "\$1" = --time ] || [ "\$1" = --cpu-time ]; then shift 2; continue; fi
  args+=("\$1"); shift
done
exec "$BIN/render" "\${args[@]}"
EOF
  chmod +x wrap/render
  "$BIN/ch6_equal" --scene "scenes/$1/scene.json" --out out --render wrap/render "${@:3}" \
    --methods "pssmlt,mmlt,pitp,mctls=--method mmlt --large-step mctls,nosuch=--method nosuch" \
    --seeds 2 --time 1 --resolution 48x32 --reference-spp 8 --min-length "$2" --block 8 --threads 2 \
    --render-args "--p-large 0.1 --spp 2 --seed-paths 2000" >/dev/null
}

# ch6_tech on --technique-images 3 renders of ajar, two seeds of MMLT and of PSSMLT.
ch6_tech_run() {
  local m s p ref=() runs=()
  for m in mmlt pssmlt; do
    for s in 1 2; do
      p=$m-s$s
      "$BIN/render" scenes/ajar/scene.json --method $m --technique-images 3 --spp 2 --seed $s --threads 2 \
        --resolution 48x32 --seed-paths 2000 --quiet --out $p >/dev/null || return 1
      ref+=($p)
      runs+=($p)
    done
  done
  "$BIN/ch6_tech" --k 3 --block 8 --out follow-all.csv --ref "${ref[@]}" --run "${runs[@]}" &&
    "$BIN/ch6_tech" --k 3 --out follow-mmlt.csv --ref mmlt-s1 mmlt-s2 --run pssmlt-s1 pssmlt-s2 mmlt-s1
}

ch6_assets_run() {
  "$BIN/ch6_assets" --sky sky.exr --sun 0.25,0.55,0.8 --size 64x32 &&
    "$BIN/ch6_assets" --sky sky2.exr --sun 0.2,0.9,0.3 &&
    "$BIN/ch6_assets" --wood wood.png --size 48x40 &&
    "$BIN/ch6_assets" --wood wood2.png
}

# check_stats BASELINE CURRENT [options]: inputs relative to $INPUTS (or a path in the run
# directory); its verdict table to verdict.txt (stdout) and check.md (--out).
check_run() {
  local a=$1 b=$2
  shift 2
  if [ -f "$a" ]; then cp "$a" base.csv.in; else cp "$INPUTS/$a" base.csv.in; fi
  if [ -f "$b" ]; then cp "$b" cur.csv.in; else cp "$INPUTS/$b" cur.csv.in; fi
  "$BIN/check_stats" "$@" --out check.md base.csv.in cur.csv.in >verdict.txt 2>stderr.txt
}
check() {
  local name=$1
  shift
  if [ -n "$INPUTS" ]; then
    run "check.$name" check_run "$@"
  else
    selected "check.$name" && echo "$prog: warning: no results/baselines: check.$name skipped" >&2
    return 0
  fi
}

scenes_list() { local s; for s in scenes/*/scene.json; do s=${s#scenes/}; echo "${s%/scene.json}"; done; }

all_runs() {
  local s m
  # bin/render: every scene with every method, the MCMC variants on every scene
  for s in $(scenes_list); do
    for m in pt bdpt pssmlt mmlt pitp; do rr "$m" "$s" "$m"; done
    rr mmlt-mctls "$s" mmlt --large-step mctls
    rr mmlt-hybrid "$s" mmlt --large-step hybrid
    rr mmlt-controlled "$s" mmlt --small-step controlled
    rr mmlt-angle "$s" mmlt --angle-stats
    rr mmlt-tech3 "$s" mmlt --technique-images 3
    rr pssmlt-cdc-rap "$s" pssmlt --cdc --rap
    rr pitp-controlled "$s" pitp --small-step controlled
  done
  # more options on three scenes
  for s in ajar cornell-box window; do
    [ -f "scenes/$s/scene.json" ] || { echo "$prog: warning: no scenes/$s: its variants skipped" >&2; continue; }
    rr pssmlt-tech3 "$s" pssmlt --technique-images 3
    rr pssmlt-maxh "$s" pssmlt --max-heuristic
    rr pssmlt-gauss "$s" pssmlt --kernel gaussian --sigma 0.03
    rr pssmlt-rapres "$s" pssmlt --rap --rap-resolution --p-large 0.3
    rr mmlt-uniform "$s" mmlt --uniform-lengths --p-large 0.3
    rr mmlt-hybrid3 "$s" mmlt --large-step hybrid --hybrid-length 3
    rr mmlt-root "$s" mmlt --small-step root
    rr mmlt-kernel "$s" mmlt --kernel gaussian --max-length 5
    rr pitp-angle "$s" pitp --angle-stats
    rr pt-len "$s" pt --min-length 2 --max-length 4
    rr bdpt-min3 "$s" bdpt --min-length 3
    rr bdpt-spp5 "$s" bdpt --spp 5 --seed 3
    rr pt-t1 "$s" pt --threads 1
    rr mmlt-t1 "$s" mmlt --threads 1
    rr mmlt-odd "$s" mmlt --resolution 37x23 --spp 3
  done

  # figure tools, count budgeted, fixed seeds, 2 threads (quick scale, reduced where it is slow)
  run fig4_1 "$BIN/fig4_1" --scale quick --seed 1 --threads 2 --out out
  run fig4_2 "$BIN/fig4_2" --scale quick --mpp 2 --seeds 2 --reference-spp 8 --seed 1 --threads 2 --out out
  run fig4_3 "$BIN/fig4_3" --scale quick --seeds 3 --spp 16 --reference-spp 128 --seed 1 --threads 2 --out out
  run fig4_5 "$BIN/fig4_5" --scale quick --mutations 1000000 --seed 1 --threads 2 --out out
  run fig4_6 fig4_6_run
  run fig5_5 "$BIN/fig5_5" --scale quick --resolution 80x60 --mpp 16 --seeds 3 --seed 1 --threads 2 --out out
  run fig5_6 "$BIN/fig5_6" --scale quick --resolution 64x48 --mpp 16 --seeds 3 --seed 1 --threads 2 --out out
  run fig6_1 "$BIN/fig6_1" --scale quick --mutations 2000000 --seed 1 --threads 2 --out out
  run table1_cmlt "$BIN/table1_cmlt" --scale quick --budgets 128k,512k --seeds 3 --res 64 --ref-spp 1024 \
    --seed 1 --threads 2 --commit golden --out out
  run ch6_tech ch6_tech_run
  run ch6_equal.ajar ch6_equal_run ajar 3 --t0 0.5
  run ch6_equal.cornell-box ch6_equal_run cornell-box 1
  run ch6_assets ch6_assets_run

  # check_stats, as the check-* targets call it, on the committed baselines and replicates
  check fig4.5 fig4.5/fig4.5.csv fig4.5/replicate-seed2.csv --key method,length --mean mean_accept --se stderr --alpha 0.01
  check fig4.5-golden fig4.5/fig4.5.csv ../fig4_5/out/fig4.5.csv --key method,length --mean mean_accept --se stderr --alpha 0.01
  check fig4.1 fig4.1/fig4.1.csv fig4.1/replicate-seed101.csv --key variant,quantity --mean mean --se se --count seeds --alpha 0.01
  check fig4.2 fig4.2/fig4.2.csv fig4.2/replicate-seed101.csv --key config,quantity --mean mean --se se --count seeds --alpha 0.01
  check fig4.3 fig4.3/fig4.3.csv fig4.3/replicate-seed101.csv --key method,quantity --mean mean --se se --count seeds --alpha 0.01
  check fig6.1 fig6.1/fig6.1.csv fig6.1/fig6.1.csv --key method,length,technique_changed --mean mean_accept --se run_se --count runs --alpha 0.01
  check fig5.5 fig5.5/fig5.5.csv fig5.5/fig5.5.csv --key kind,region --mean mean --se stderr --count seeds --alpha 0.01
  check fig5.6 fig5.6/fig5.6.csv fig5.6/fig5.6.csv --key kind --mean relmse --se stderr --count seeds --alpha 0.05
  check table1 table1-cmlt/stats-quick.csv table1-cmlt/stats-paper.csv --key algorithm,n --mean rmse_mean --se rmse_se --count seeds --alpha 0.01
  check table1-normal table1-cmlt/stats-quick.csv table1-cmlt/stats-quick.csv --key algorithm,n --mean rmse_mean --se rmse_se
  check bad-column fig4.5/fig4.5.csv fig4.5/fig4.5.csv --key method,length --mean no_such_column
}

# ---- collecting -------------------------------------------------------------------------------

COLRE='(^|_)(seconds|secs|time|wall)(_|$)|per_s(_|$)|per_second'

strip_csv() {
  awk -F, -v re="$COLRE" '
    /^#/ {
      if ($0 ~ /^# (commit|seconds|seed_seconds|mutations_per_second|samples_per_second)( |$)/) next
      gsub(/ (commit|seconds)=[^ ]*/, "")
      print; next
    }
    !hdr { hdr = 1; for (i = 1; i <= NF; i++) drop[i] = ($i ~ re) }
    {
      line = ""; n = 0
      for (i = 1; i <= NF; i++) if (!drop[i]) line = (n++ ? line "," : "") $i
      print line
    }' "$1"
}

strip_md() {
  awk -F'|' '
    {
      sub(/Wall time [0-9.]+ s/, "Wall time (stripped) s")
      sub(/^# commit .*/, "# commit (stripped)")
    }
    /^\|/ {
      if (!intable) {
        intable = 1; delete drop
        for (i = 1; i <= NF; i++) drop[i] = ($i ~ /mutations\/s|steps\/s/)
      }
      line = ""; n = 0
      for (i = 1; i <= NF; i++) if (!drop[i]) line = (n++ ? line "|" : "") $i
      print line; next
    }
    { intable = 0; print }' "$1"
}

# collect DEST: the work directory's outputs into DEST
collect() {
  local dest=$1 f
  mkdir -p "$dest/text"
  (
    cd "$W/runs"
    find . -type f \( -name '*.exr' -o -name '*.png' \) | sed 's|^\./||' | sort >"$W/images.list"
    : >"$W/hash.raw"
    if [ -s "$W/images.list" ]; then
      tr '\n' '\0' <"$W/images.list" | xargs -0 -n 200 oiiotool --info --hash >>"$W/hash.raw" 2>&1 || true
    fi
    # oiiotool prints "FILE : W x H, N channel, TYPE FORMAT" and then "    SHA-1: HEX"
    awk 'NR == FNR {
           if ($0 ~ /^[^ ].* : /) { f = $0; sub(/ +: .*/, "", f); info = $0; sub(/^[^:]* : +/, "", info); gsub(/ +/, " ", info) }
           else if ($1 == "SHA-1:" && f != "") { h[f] = info "\t" $2; f = "" }
           next }
         { print $0 "\t" (($0 in h) ? h[$0] : "unreadable\t-") }' "$W/hash.raw" "$W/images.list" >"$dest/hashes.txt"
    find . -type f \( -name '*.csv' -o -name '*.md' -o -name '*.key' -o -name '*.txt' \) | sed 's|^\./||' | sort |
      while IFS= read -r f; do
        mkdir -p "$dest/text/$(dirname "$f")"
        case $f in
          *.csv) strip_csv "$f" >"$dest/text/$f" ;;
          *.md) strip_md "$f" >"$dest/text/$f" ;;
          *) cp "$f" "$dest/text/$f" ;;
        esac
      done
  )
  sort "$W/status.txt" >"$dest/exit-status.txt"
  sort "$W/commands.txt" >"$dest/commands.txt"
  cp "$W/timing.txt" "$dest/timing.txt"
}

# record_into DEST INPUTS_SOURCE
record_into() {
  local dest=$1 src=$2 t0=$SECONDS
  W=$(mktemp -d "${TMPDIR:-/tmp}/golden-work.XXXXXX")
  mkdir -p "$W/runs" "$dest"
  : >"$W/status.txt"
  : >"$W/commands.txt"
  : >"$W/timing.txt"
  INPUTS=""
  if [ -d "$src" ]; then
    mkdir -p "$dest/inputs"
    cp -r "$src/." "$dest/inputs/"
    INPUTS=$(cd "$dest/inputs" && pwd)
  fi
  all_runs
  collect "$dest"
  local n_img n_txt n_runs
  n_runs=$(wc -l <"$dest/exit-status.txt")
  n_img=$(wc -l <"$dest/hashes.txt")
  n_txt=$(cd "$dest/text" && find . -type f | wc -l)
  echo "$prog: $n_runs runs, $n_img images, $n_txt text outputs in $((SECONDS - t0)) s" >&2
  if [ -z "${GOLDEN_KEEP:-}" ]; then rm -rf "$W"; else echo "$prog: work directory kept: $W" >&2; fi
}

# outputs DIR: "key<TAB>value" per output (value: image info + hash, a text file's sha256, an exit status)
outputs() {
  local d=$1
  {
    awk -F'\t' '{ print $1 "\t" $2 " " $3 }' "$d/hashes.txt"
    (cd "$d/text" && find . -type f | sed 's|^\./||' | sort | while IFS= read -r f; do
      printf '%s\t%s\n' "$f" "$(sha256sum <"$f" | cut -d' ' -f1)"
    done)
    awk '{ print $1 ":exit\t" $2 }' "$d/exit-status.txt"
  } | awk -F'\t' 'ENVIRON["GOLDEN_ONLY"] == "" { print; next } { r = $1; sub(/[\/:].*/, "", r); if (r ~ ENVIRON["GOLDEN_ONLY"]) print }' | sort -t $'\t' -k1,1
}

case $mode in
  record)
    if [ -e "$OUT" ] && [ -n "$(ls -A "$OUT" 2>/dev/null)" ]; then die "$OUT exists and is not empty; remove it first"; fi
    record_into "$OUT" "$REPO/results/baselines"
    echo "$prog: recorded $(cd "$OUT" && pwd)" >&2
    ;;
  compare)
    [ -f "$OUT/hashes.txt" ] && [ -f "$OUT/exit-status.txt" ] || die "$OUT: no golden outputs (hashes.txt, exit-status.txt)"
    T=$(mktemp -d "${TMPDIR:-/tmp}/golden-compare.XXXXXX")
    record_into "$T/new" "$OUT/inputs"
    if ! cmp -s <(awk -F'\t' 'ENVIRON["GOLDEN_ONLY"] == "" || $1 ~ ENVIRON["GOLDEN_ONLY"]' "$OUT/commands.txt") "$T/new/commands.txt"; then
      echo "$prog: warning: the runs differ from those recorded (commands.txt): another version of this script?" >&2
    fi
    outputs "$OUT" >"$T/old.list"
    outputs "$T/new" >"$T/new.list"
    join -t $'\t' -a1 -a2 -e '(missing)' -o 0,1.2,2.2 "$T/old.list" "$T/new.list" >"$T/joined"
    same=0 differ=0
    while IFS=$'\t' read -r key a b; do
      if [ "$a" = "$b" ]; then
        echo "same     $key"
        same=$((same + 1))
      else
        note=""
        [ "$a" = "(missing)" ] && note=" (new output)"
        [ "$b" = "(missing)" ] && note=" (not produced)"
        echo "DIFFERS  $key$note"
        differ=$((differ + 1))
      fi
    done <"$T/joined"
    echo "$same same, $differ differ"
    if [ "$differ" -gt 0 ]; then
      echo "$prog: kept $T (new outputs in $T/new; e.g. diff -r $OUT/text $T/new/text)" >&2
      exit 1
    fi
    rm -rf "$T"
    ;;
esac
