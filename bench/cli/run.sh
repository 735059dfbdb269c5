#!/usr/bin/env bash
# cadlod convert against the meshlabserver route, and cadlod's thread scaling.
#   bench/cli/run.sh [SIZE_MB]      (generated assembly size, default 8)
# Needs a plugins build in build/ (scripts/test.sh): build/cli/cadlod and the staged
# build/stage/bin/meshlabserver. Like for like: both build the paper's level list
# "50 60 70 80 90" from mm input (docs/examples/cad_mm_to_flt.mlx); the default screen-space
# chain (--lod auto) is timed too, for reference. Wall times, best of 3; prints a Markdown
# table for docs/benchmarks.md.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
BUILD="${CADLOD_BUILD_DIR:-$ROOT/build}"
size_mb=${1:-8}
cadlod="$BUILD/cli/cadlod" server="$BUILD/stage/bin/meshlabserver"
[ -x "$cadlod" ] && [ -x "$server" ] || { echo "build first: scripts/test.sh" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

g++ -O2 -std=c++17 -o "$work/gen_cad_vrml" "$ROOT/bench/vrml/gen_cad_vrml.cpp"
"$work/gen_cad_vrml" "$work/generated.wrl" "$size_mb" >/dev/null
inputs=("$ROOT/docs/sample/cad_assembly.wrl.gz" "$work/generated.wrl")

# Best wall time of 3 runs of "$@" (ms); each run writes a fresh output.
best_ms() {
  local best=0 t0 ms
  for _ in 1 2 3; do
    rm -f "$work"/*.flt
    t0=$(date +%s%N)
    "$@" >"$work/log" 2>&1 || { cat "$work/log" >&2; return 1; }
    ms=$(( ($(date +%s%N) - t0) / 1000000 ))
    if [ "$best" -eq 0 ] || [ "$ms" -lt "$best" ]; then best=$ms; fi
  done
  echo "$best"
}

faces() { "$cadlod" info "$1" 2>/dev/null | awk '/^triangles/{print $2}'; }

echo "| input | triangles | meshlabserver, list (ms) | cadlod, list (ms) | cadlod --lod auto (ms) | auto, 1 thread (ms) | auto, 2 threads (ms) | speed-up |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for in in "${inputs[@]}"; do
  out="$work/out.flt"
  ms_server=$(best_ms xvfb-run -a timeout 1800 "$server" -i "$in" -s "$ROOT/docs/examples/cad_mm_to_flt.mlx" -o "$out")
  ms_list=$(best_ms env -u DISPLAY "$cadlod" convert "$in" -o "$out" --unit mm --lod "50 60 70 80 90" -q)
  ms_auto=$(best_ms env -u DISPLAY "$cadlod" convert "$in" -o "$out" --unit mm -q)
  ms_t1=$(best_ms env -u DISPLAY "$cadlod" convert "$in" -o "$out" --unit mm -q --threads 1)
  ms_t2=$(best_ms env -u DISPLAY "$cadlod" convert "$in" -o "$out" --unit mm -q --threads 2)
  "$cadlod" convert "$in" -o "$out" --unit mm -q --lod 90 --force >/dev/null 2>&1
  speedup=$(awk -v a="$ms_t1" -v b="$ms_t2" 'BEGIN { printf "%.2f", a / b }')
  echo "| $(basename "$in") | $(faces "$out") | $ms_server | $ms_list | $ms_auto | $ms_t1 | $ms_t2 | **$speedup** |"
done
echo
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load $(cut -d' ' -f1-3 /proc/loadavg)"
