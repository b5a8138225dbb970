#!/usr/bin/env bash
# The core's layering, checked: a folder of core/ may include only itself and the folders listed
# before it, and nothing of experiments/. The order is the one core/README.md states on its line
#   Layering order: base io sampling sampler ...
# so the README and the check cannot drift apart. Every `#include "FOLDER/..."` of
# core/*/*.{c,h,cpp} is read; each violation is one line
#   core/scene/x.c:9: includes bsdf/, listed after scene/
# and the exit status is 1 (2 when the order cannot be read). An include of a folder that is not
# in the order is a violation too: a new folder must be placed in it.
#
#   scripts/check-layering.sh [ROOT]    ROOT: the repository root (default: this script's parent)
set -euo pipefail
root=${1:-"$(dirname "$0")/.."}
readme="$root/core/README.md"
order=$(sed -n 's/^Layering order: *//p' "$readme" 2>/dev/null | head -n 1)
if [ -z "$order" ]; then
    echo "check-layering: $readme: no 'Layering order: ...' line" >&2
    exit 2
fi
shopt -s nullglob
cd "$root"
files=(core/*/*.c core/*/*.h core/*/*.cpp)
[ ${#files[@]} -gt 0 ] || exit 0
# The experiments' folders, as their includes name them (`-Iexperiments`: "common/opts.h").
exp=""
for d in experiments/*/; do exp="$exp $(basename "$d")"; done
# grep prints FILE:LINE:TEXT; awk knows each folder's rank and compares.
{ grep -n '^[[:space:]]*#[[:space:]]*include[[:space:]]*"' "${files[@]}" || true; } | awk -v order="$order" -v expdirs="$exp" '
    BEGIN {
        n = split(order, f, " "); for (i = 1; i <= n; i++) rank[f[i]] = i
        n = split(expdirs, f, " "); for (i = 1; i <= n; i++) isexp[f[i]] = 1
        isexp["experiments"] = 1
    }
    {
        file = $0; sub(/:.*/, "", file)
        rest = substr($0, length(file) + 2); line = rest; sub(/:.*/, "", line)
        split(file, part, "/"); own = part[2]
        if (!match(rest, /"[^"\/]+\//)) next
        inc = substr(rest, RSTART + 1, RLENGTH - 2)
        if (inc in isexp) {
            printf "%s:%s: includes %s/, which is experiments/ (the core never includes it)\n", file, line, inc
            bad++
        } else if (!(own in rank)) {
            printf "%s:%s: folder %s/ is not in the layering order of core/README.md\n", file, line, own
            bad++
        } else if (!(inc in rank)) {
            printf "%s:%s: includes %s/, which is not in the layering order of core/README.md\n", file, line, inc
            bad++
        } else if (rank[inc] > rank[own]) {
            printf "%s:%s: includes %s/, listed after %s/\n", file, line, inc, own
            bad++
        }
    }
    END { exit bad ? 1 : 0 }'
