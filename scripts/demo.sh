#!/usr/bin/env bash
# The main job on the bundled sample: CAD VRML assembly in, OpenFlight LOD set out.
# Sets up (scripts/bootstrap.sh), builds, converts docs/sample/cad_assembly.wrl.gz with
# `cadlod convert` (no X server; mm input, screen-space LOD chain), checks the .flt with
# OpenSceneGraph, and prints a summary. Output goes to a new out/demo-<time>/ directory.
# The meshlabserver route (docs/examples/cad_mm_to_flt.mlx) is in README.md.
#   scripts/demo.sh [INPUT.wrl]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
INPUT="$(realpath "${1:-$ROOT/docs/sample/cad_assembly.wrl.gz}")"
BUILD="${CADLOD_BUILD_DIR:-$ROOT/build}"

bash "$ROOT/scripts/bootstrap.sh"
echo "== build ($BUILD)"
cmake -S "$ROOT" -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$BUILD" -j "$(nproc)" >/dev/null

OUT="$ROOT/out/demo-$(date +%Y%m%d-%H%M%S)"
mkdir -p "$OUT"
name="$(basename "$INPUT")"; name="${name%%.*}"
FLT="$OUT/$name.flt"
echo "== convert $INPUT"
start=$(date +%s%N)
LOG="$OUT/cadlod.log"
if ! env -u DISPLAY timeout 600 "$BUILD/cli/cadlod" convert "$INPUT" -o "$FLT" --unit mm \
      --report "$OUT/report.json" -q >"$LOG" 2>&1; then
  echo "conversion failed; see $LOG" >&2
  tail -n 20 "$LOG" >&2
  exit 1
fi
millis=$(( ($(date +%s%N) - start) / 1000000 ))

echo "== summary"
"$BUILD/cli/cadlod" info "$FLT" | sed 's/^/  /'
echo "  report: $OUT/report.json"
echo
echo "== OpenSceneGraph reads $FLT (switch ranges in meters)"
"$BUILD/tests/openflight/osg_assembly_stats" "$FLT" "$name" | sed 's/^/  /'
"$BUILD/tests/openflight/osg_flt_probe" "$FLT" > "$OUT/osg_probe.txt"
echo "  the first LOD nodes:"
grep -m 8 -E "^lod " "$OUT/osg_probe.txt" | sed 's/^/    /'
echo "  $(grep -c '^name ' "$OUT/osg_probe.txt") named nodes; parts: $(grep '^name ' "$OUT/osg_probe.txt" | sed 's/^name //' | grep -v -E -e '^lod[0-9]' -e 'LOD child' -e ' (chunk|proxy) [0-9]+$' | sort -u | tr '\n' ' ')"
printf '\ninput  %s (%s bytes)\noutput %s (%s bytes)\ntime   %d ms (load, LOD chain, export)\n' \
  "$INPUT" "$(stat -c %s "$INPUT")" "$FLT" "$(stat -c %s "$FLT")" "$millis"
