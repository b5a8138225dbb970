#!/usr/bin/env bash
# scripts/check-layering.sh on a tiny tree of its own, run by `make lint`: it must pass a tree whose
# includes follow the order, and fail, naming file, line and folder, on an upward include, an include
# of experiments/ and a folder missing from the order. A check that never fails checks nothing.
set -euo pipefail
script="$(cd "$(dirname "$0")/../.." && pwd)/scripts/check-layering.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "check-layering-test: $*" >&2; exit 1; }

mkdir -p "$tmp/core/low" "$tmp/core/high" "$tmp/experiments/common"
printf '# core\n\nLayering order: low high\n' > "$tmp/core/README.md"
printf '#include "low/a.h"\n#include <stdio.h>\n' > "$tmp/core/low/a.c"
printf '#include "low/a.h"\n#include "high/b.h"\n' > "$tmp/core/high/b.c"
bash "$script" "$tmp" > "$tmp/out" 2>&1 || fail "a tree in order was refused: $(cat "$tmp/out")"

# expect FILE CONTENT LINE: the check fails and prints LINE
expect() {
    printf '%s\n' "$2" > "$tmp/$1"
    if bash "$script" "$tmp" > "$tmp/out" 2>&1; then fail "accepted $1: $2"; fi
    grep -qxF "$3" "$tmp/out" || fail "for $1 expected '$3', got: $(cat "$tmp/out")"
    rm "$tmp/$1"
}
expect core/low/up.c $'#include "low/a.h"\n#include "high/b.h"' 'core/low/up.c:2: includes high/, listed after low/'
expect core/low/up.h '#include "high/b.h"' 'core/low/up.h:1: includes high/, listed after low/'
expect core/high/exp.c '#include "common/opts.h"' \
    'core/high/exp.c:1: includes common/, which is experiments/ (the core never includes it)'
mkdir -p "$tmp/core/new"
expect core/new/n.c '#include "low/a.h"' 'core/new/n.c:1: folder new/ is not in the layering order of core/README.md'
rmdir "$tmp/core/new"
printf '# core\n' > "$tmp/core/README.md"
if bash "$script" "$tmp" > /dev/null 2>&1; then fail "a README without the order line was accepted"; fi
echo "check-layering-test: 6 cases pass"
