#!/usr/bin/env bash
# Runs one fuzz target (make fuzz): TARGET SECONDS BUILD_DIR. The corpus grows in BUILD_DIR/corpus/TARGET
# from the seeds and the committed regression inputs (tests/data/fuzz/TARGET/); a failing input goes
# to BUILD_DIR/crash/TARGET/. Exit status 1 on any crash, sanitizer report, leak, timeout or OOM.
set -uo pipefail
t=$1 secs=$2 b=$3
# The longest input: a scene with its meshes and a texture, a checkpoint of a small render.
case $t in
  scene) len=16384 ;;
  checkpoint) len=32768 ;;
  obj | wo3) len=8192 ;;
  *) len=4096 ;;
esac
mkdir -p "$b/corpus/$t" "$b/crash/$t" "$b/log"
args=(-max_total_time="$secs" -timeout=1 -rss_limit_mb=512 -max_len="$len" -print_final_stats=1
      -artifact_prefix="$b/crash/$t/")
[ -f "tests/fuzz/$t.dict" ] && args+=(-dict="tests/fuzz/$t.dict")
dirs=("$b/corpus/$t")
for d in "$b/seeds/$t" "tests/data/fuzz/$t"; do [ -d "$d" ] && dirs+=("$d"); done
log="$b/log/$t.log"
# Input files on tmpfs where there is one: the checkpoint writer's fsync is then free. A smaller
# quarantine than ASan's 256 MB leaves the 512 MB limit to the code under test.
[ -d /dev/shm ] && [ -w /dev/shm ] && export TMPDIR=/dev/shm
export ASAN_OPTIONS=${ASAN_OPTIONS:-quarantine_size_mb=64}
"$b/fuzz-$t" "${args[@]}" "${dirs[@]}" > "$log" 2>&1
rc=$?
# The loader's warnings fill the log; the summary is libFuzzer's last status line and its stats.
done_line=$(grep -a '^#[0-9]*[[:space:]]*DONE' "$log" | tail -1)
execs=$(grep -a '^stat::number_of_executed_units' "$log" | tail -1 | awk '{print $2}')
echo "fuzz $t: ${secs}s, ${execs:-?} executions, ${done_line:-no final line} (log $log)"
if [ $rc -ne 0 ]; then
  grep -a -m1 -B2 -A30 'ERROR: \|runtime error\|==ERROR\|deadly signal\|timeout\|out-of-memory' "$log" | head -60 >&2
  echo "fuzz $t: FAILED (exit status $rc); the input is in $b/crash/$t/" >&2
  exit 1
fi
