#!/usr/bin/env bash
# OpenFlight benchmark: write time, bytes per triangle, OpenSceneGraph load time and
# peak memory of cadlod's .flt (Mesh records, Face records) vs OpenSceneGraph's own FLT
# writer (osgconv x.ply x.flt) on the same geometry, for one mesh and for an LOD set.
#   bench/openflight/run.sh [BUILD_DIR] [TRIANGLES] [LODSET_TRIANGLES]
# BUILD_DIR must be configured with -DCADLOD_BUILD_BENCH=ON (the script builds flt_bench).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="${1:-$here/../../build-bench}"
tris="${2:-1000000}"
lodtris="${3:-500000}"
cmake --build "$build" --target flt_bench -j2 >/dev/null
tool="$build/bench/openflight/flt_bench"
work="$(mktemp -d "${TMPDIR:-/tmp}/cadlod-flt-bench.XXXXXX")"
trap 'rm -rf "$work"' EXIT

field() { sed -n "s/.*\b$1 \([0-9.]*\).*/\1/p" <<<"$2"; }
# load FILE -> "seconds peakMB lodNodes triangles" using OpenSceneGraph in a fresh process
load() {
  local out
  out=$(/usr/bin/time -f "peak_kb %M" "$tool" load "$1" 2>&1)
  echo "$(field load_seconds "$out") $(( $(field peak_kb "$out") / 1024 )) $(field lod_nodes "$out") $(field triangles "$out")"
}
row() {  # name write_s bytes tris file
  read -r ls mb lods seen <<<"$(load "$5")"
  printf "| %-34s | %8s | %10s | %6.1f | %8s | %7s | %4s | %9s |\n" "$1" "$2" "$3" \
    "$(echo "$3 / $4" | bc -l)" "$ls" "$mb" "$lods" "$seen"
}
header() {
  echo
  echo "$1"; echo
  echo "| writer                             | write s  | bytes      | B/tri  | OSG load s | OSG MB | LODs | OSG tris  |"
  echo "|------------------------------------|----------|------------|--------|----------|---------|------|-----------|"
}

header "One mesh, about $tris triangles (4 parts)"
"$tool" ply "$tris" "$work/mesh.ply" >/dev/null
for mode in Mesh Face; do
  arg=$([ "$mode" = Mesh ] && echo meshes || echo faces)
  out=$("$tool" ours "$tris" "$work/ours_$mode.flt" "$arg")
  row "cadlod ($mode records)" "$(field write_seconds "$out")" "$(field bytes "$out")" \
      "$(field triangles "$out")" "$work/ours_$mode.flt"
  n=$(field triangles "$out")
done
start=$(date +%s.%N)
osgconv "$work/mesh.ply" "$work/osg.flt" >/dev/null 2>&1
secs=$(echo "$(date +%s.%N) - $start" | bc -l)
row "OpenSceneGraph (osgconv ply->flt)" "$(printf %.3f "$secs")" "$(stat -c %s "$work/osg.flt")" "$n" "$work/osg.flt"

header "LOD set: 4 levels, $lodtris triangles at level 0, halving"
out=$("$tool" ours-lodset "$lodtris" "$work/ours_set.flt")
row "cadlod (Mesh records)" "$(field write_seconds "$out")" "$(field bytes "$out")" \
    "$(field triangles "$out")" "$work/ours_set.flt"
out=$("$tool" osg-lodset "$lodtris" "$work/osg_set.flt")
row "OpenSceneGraph FLT writer" "$(field write_seconds "$out")" "$(field bytes "$out")" \
    "$(field triangles "$out")" "$work/osg_set.flt"
