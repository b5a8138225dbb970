# Sourced by the scripts that write figure files through tools that do not always report a full
# disk (gnuplot and oiiotool exit 0 with a PNG cut short): the one place that checks such a file
# and puts it in place.
#
# whole FILE: FILE ends as a complete PNG (its IEND chunk) or PDF (%%EOF) does; other types pass.
whole() {
  case $1 in
    *.png) [ "$(tail -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 49454e44ae426082 ] ;;
    *.pdf) tail -c 32 "$1" | grep -q '%%EOF' ;;
    *) true ;;
  esac
}

# write_via NAME OUT TMP COMMAND [ARG...]: COMMAND writes TMP (beside OUT); TMP is checked, synced
# and renamed to OUT. On any failure TMP is removed, one line "NAME: OUT: cannot write (REASON)"
# goes to stderr and the shell exits with status 1. COMMAND's messages are kept back until then.
write_via() {
  # names of their own: a caller's EXIT trap that removes "$tmp" must still see its own variable
  local wv_name=$1 wv_out=$2 wv_tmp=$3 wv_why wv_st=0 wv_left
  shift 3
  # `|| wv_st=$?`: a failing substitution must not end a caller running under set -e before the
  # temporary is removed and the line printed
  wv_why=$( { "$@" && { whole "$wv_tmp" || { echo "the file came out truncated"; false; }; } && sync "$wv_tmp" &&
              mv -f "$wv_tmp" "$wv_out"; } 2>&1 ) || wv_st=$?
  [ $wv_st = 0 ] && return 0
  rm -f "$wv_tmp"
  wv_why=$(printf '%s' "$wv_why" | tail -n 1) wv_why=${wv_why##*: }
  [ -f "$wv_out" ] && wv_left='; the previous file is left as it was' || wv_left=
  echo "$wv_name: $wv_out: cannot write (${wv_why:-exit status $wv_st})$wv_left" >&2
  exit 1
}
