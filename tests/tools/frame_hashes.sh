#!/usr/bin/env bash
# Prints one SHA-256 per rendered frame for the bundled tiny, default and forest scenarios in
# every representation, lighting family and splat kind, plus the reference rendering. Used to
# show that a refactoring changes no pixel: run it before and after, then diff the two lists.
#
#   tests/tools/frame_hashes.sh [path/to/sylva] > before.txt
#   ... change the code, rebuild ...
#   tests/tools/frame_hashes.sh [path/to/sylva] > after.txt && diff before.txt after.txt
#
# The frames are small (160x90) and few (3), so the whole list takes a few minutes on 2 cores.
# Hashes are of the decoded pixels (oiiotool --printinfo would include metadata), so only the
# image counts.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
sylva="${1:-$here/build/bin/sylva}"
frames="${FRAMES:-3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

run() {  # label, then play options
  local label="$1"; shift
  rm -rf "$work/out"
  if ! "$sylva" play --headless --frames "$frames" --width 160 --height 90 --threads 2 \
       --out "$work/out" "$@" >"$work/log" 2>&1; then
    echo "frame_hashes: '$label' failed:" >&2; cat "$work/log" >&2; exit 1
  fi
  for f in "$work"/out/frame_*.png; do
    # Pixels only: PNG metadata (software version, time) must not count as a change.
    printf '%s %s %s\n' "$label" "$(basename "$f")" \
      "$(python3 -c 'import sys,zlib,hashlib
from pathlib import Path
d = Path(sys.argv[1]).read_bytes()
# Concatenate the IDAT chunks and inflate them: the raw scanlines.
i, idat = 8, b""
while i < len(d):
    n = int.from_bytes(d[i:i+4], "big"); t = d[i+4:i+8]
    if t == b"IDAT": idat += d[i+8:i+8+n]
    i += 12 + n
print(hashlib.sha256(zlib.decompress(idat)).hexdigest())' "$f")"
  done
}

for scenario in tiny default forest; do
  for representation in mesh_levels points_lines billboard_clouds; do
    for lighting in normal_mapped pre_lit sh; do
      run "$scenario/$representation/$lighting" "$scenario" \
        --representation "$representation" --lighting "$lighting"
    done
  done
  run "$scenario/points_lines/opaque" "$scenario" --representation points_lines --splats opaque
  run "$scenario/reference" "$scenario" --reference
  echo "frame_hashes: $scenario done" >&2
done
