#!/usr/bin/env bash
# Seed corpora for the fuzz targets (make fuzz-seeds): OUT_DIR RENDER CKPT_SEED. Scenes from scenes/,
# tests/data/ and the Tungsten conformance suite with their file names rewritten to the scene
# target's slots and their first small meshes appended; every small .obj and .wo3; the committed
# statistics CSVs; checkpoints of tiny renders; a few raw texel files.
set -euo pipefail
out=$1 render=$2 ckpt_seed=$3
rm -rf "$out"
mkdir -p "$out"/{scene,obj,wo3,checkpoint,stats_csv,texture}
sep=$'\n--8<--\n'
small() { [ "$(stat -c %s "$1")" -le "$2" ]; }
# A raw texel file (fuzz.h): w, h (16-bit little endian), channels, bits, then the floats.
raw_tex() { # W H NC BITS VALUE-BYTES
  printf "\\x$(printf %02x "$1")\\x00\\x$(printf %02x "$2")\\x00\\x$(printf %02x "$3")\\x$(printf %02x "$4")"
  for ((i = 0; i < $1 * $2 * $3; i++)); do printf "$5"; done
}
raw_tex 2 2 3 8 '\x00\x00\x00\x3f' > "$out/texture/grey-rgb8"
raw_tex 4 2 1 0 '\x00\x00\x80\x3f' > "$out/texture/one-channel"
raw_tex 1 1 4 16 '\x00\x00\x80\x3f' > "$out/texture/rgba16"
raw_tex 3 1 3 0 '\x00\x00\xc0\x7f' > "$out/texture/nan"
raw_tex 2 1 2 0 '\xff\xff\x7f\x7f' > "$out/texture/huge"
n=0
for f in scenes/*/*.json tests/data/*.json tests/data/bad/*.json tests/data/tungsten/*.json; do
  small "$f" 12000 || continue
  d=$(dirname "$f")
  obj=$(grep -o '"[^"]*\.obj"' "$f" | head -1 | tr -d '"' || true)
  wo3=$(grep -o '"[^"]*\.wo3"' "$f" | head -1 | tr -d '"' || true)
  {
    sed -E 's/"[^"]*\.obj"/"mesh.obj"/g; s/"[^"]*\.wo3"/"mesh.wo3"/g; s/"[^"]*\.(png|exr|hdr|jpg|pfm)"/"tex.raw"/g' "$f"
    printf '%s' "$sep"
    [ -n "$obj" ] && [ -f "$d/$obj" ] && small "$d/$obj" 4000 && cat "$d/$obj"
    printf '%s' "$sep"
    [ -n "$wo3" ] && [ -f "$d/$wo3" ] && small "$d/$wo3" 4000 && cat "$d/$wo3"
    printf '%s' "$sep"
    cat "$out/texture/grey-rgb8"
  } > "$out/scene/$(echo "$f" | tr / _)"
  n=$((n + 1))
done
for f in $(find scenes tests/data -name '*.obj' -size -64k); do cp "$f" "$out/obj/$(echo "$f" | tr / _)"; done
for f in $(find scenes tests/data -name '*.wo3' -size -64k); do cp "$f" "$out/wo3/$(echo "$f" | tr / _)"; done
for f in $(find results/baselines tests/data -name '*.csv' -size -16k); do cp "$f" "$out/stats_csv/$(echo "$f" | tr / _)"; done
# Checkpoints: what a tiny render of each kind leaves, as a file (odd first byte) and re-framed
# for the target's even way in (ckpt_seed).
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for m in pt bdpt mmlt pitp; do
  "$render" tests/data/furnace-64.json --method "$m" --resolution 4x4 --spp 256 --threads 2 --quiet \
    --checkpoint 0.001 --out "$tmp/$m" > /dev/null 2>&1 || true
  [ -f "$tmp/$m.ckpt" ] || continue
  small "$tmp/$m.ckpt" 32000 || continue
  { printf '\x01'; cat "$tmp/$m.ckpt"; } > "$out/checkpoint/$m-file"
  "$ckpt_seed" "$tmp/$m.ckpt" "$out/checkpoint/$m-payload"
done
echo "fuzz seeds: $n scenes, $(ls "$out/obj" | wc -l) .obj, $(ls "$out/wo3" | wc -l) .wo3, $(ls "$out/stats_csv" | wc -l) CSV, $(ls "$out/checkpoint" | wc -l) checkpoint seeds in $out"
