#!/usr/bin/env bash
# usage: to-file.sh NAME FILE COMMAND [ARG...]
# COMMAND's standard output into FILE through a temporary beside it, fsync'ed and renamed, so that
# FILE is the old one or the complete new one. When anything fails (a full disk, or COMMAND itself)
# the temporary is removed and the only message is one line, "NAME: FILE: cannot write (REASON)",
# REASON the end of the last message kept back, and the status is 1.
set -uo pipefail
name=$1 file=$2
shift 2
tmp="$(dirname "$file")/.tmp$$-$(basename "$file")"
trap 'rm -f "$tmp"' EXIT
# Messages go to a pipe (the command substitution), which a full disk cannot refuse.
why=$( { "$@" >"$tmp" && sync "$tmp" && mv -f "$tmp" "$file"; } 2>&1 )
st=$?
[ $st = 0 ] && { [ -z "$why" ] || printf '%s\n' "$why" >&2; exit 0; }
why=$(printf '%s' "$why" | tail -n 1) why=${why##*: }
[ -f "$file" ] && left='; the previous file is left as it was' || left=
echo "$name: $file: cannot write (${why:-exit status $st})$left" >&2
exit 1
