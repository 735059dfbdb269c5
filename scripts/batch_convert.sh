#!/usr/bin/env bash
# Converts many CAD exports in parallel, one meshlabserver per file, each with a timeout:
#   scripts/batch_convert.sh [-j JOBS] [-s SCRIPT.mlx] [-t SECONDS] OUT_DIR FILE|DIR...
# Every .wrl/.wrz/.vrml/.wrl.gz found becomes OUT_DIR/<name>.flt (an existing output is
# never overwritten: that file is reported as skipped). Prints one status line per file
# and a total; exits 1 if any file failed. Default script: docs/examples/cad_mm_to_flt.mlx.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${CADLOD_BUILD_DIR:-$ROOT/build}"
jobs=$(nproc) script="$ROOT/docs/examples/cad_mm_to_flt.mlx" timeout_s=1800
while getopts "j:s:t:" opt; do
  case $opt in
    j) jobs=$OPTARG ;; s) script=$(realpath "$OPTARG") ;; t) timeout_s=$OPTARG ;;
    *) sed -n '2,7p' "$0" >&2; exit 2 ;;
  esac
done
shift $((OPTIND - 1))
[ $# -ge 2 ] || { sed -n '2,7p' "$0" >&2; exit 2; }
out=$(realpath -m "$1"); shift
server="$BUILD/stage/bin/meshlabserver"
[ -x "$server" ] || { echo "no staged meshlabserver in $BUILD: run scripts/demo.sh or scripts/test.sh first" >&2; exit 1; }
mkdir -p "$out/logs"

list=$(mktemp)
trap 'rm -f "$list"; kill $(jobs -p) 2>/dev/null || true' EXIT
find "$@" -type f \( -iname '*.wrl' -o -iname '*.wrz' -o -iname '*.vrml' -o -iname '*.wrl.gz' \) -print0 | sort -z > "$list"
total=$(tr -cd '\0' < "$list" | wc -c)
[ "$total" -gt 0 ] || { echo "no VRML files under: $*" >&2; exit 1; }

# One Xvfb for the whole batch: parallel xvfb-run calls race for display numbers.
display_file=$(mktemp)
Xvfb -displayfd 3 -screen 0 1024x768x24 -nolisten tcp -noreset 3>"$display_file" >/dev/null 2>&1 &
for _ in $(seq 50); do [ -s "$display_file" ] && break; sleep 0.1; done
export DISPLAY=":$(tr -d '[:space:]' < "$display_file")"; rm -f "$display_file"

convert_one() {
  local in=$1 base name flt log start rc
  base=$(basename "$in"); name=${base%%.*}
  flt="$out/$name.flt"; log="$out/logs/$name.log"
  if [ -e "$flt" ]; then echo "SKIP  $in ($flt exists)"; return 0; fi
  start=$(date +%s%N)
  rc=0
  timeout -k 10 "$timeout_s" "$server" -i "$in" -s "$script" -o "$flt" >"$log" 2>&1 || rc=$?
  local ms=$(( ($(date +%s%N) - start) / 1000000 ))
  if [ $rc -eq 0 ] && [ -s "$flt" ]; then
    echo "OK    $in -> $flt (${ms} ms; $(grep -m1 -o '[0-9]* LOD level(s)' "$log" || true))"
  else
    [ $rc -eq 124 ] && reason="timed out after ${timeout_s}s" || reason="exit $rc: $(grep -m1 -iE 'error|cannot|failed' "$log" || tail -n 1 "$log")"
    echo "FAIL  $in ($reason; log $log)"
    return 1
  fi
}
export -f convert_one
export out script server timeout_s

status=0
xargs -0 -P "$jobs" -I{} bash -c 'convert_one "$1"' _ {} < "$list" | tee "$out/status.txt" || status=1
failed=$(grep -c '^FAIL' "$out/status.txt" || true)
echo "$total file(s): $(grep -c '^OK' "$out/status.txt" || true) converted, $(grep -c '^SKIP' "$out/status.txt" || true) skipped, $failed failed"
[ "$failed" -eq 0 ] && [ $status -eq 0 ]
