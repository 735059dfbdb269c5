#!/usr/bin/env bash
# Smoke test of osg_render (ctest, xvfb fixture): a two-triangle PLY and a two-level LOD set
# written by paper_measure load, count and render, the default camera path draws both
# levels, the inside path draws and times its frames, a picture is written, and a level
# or path that does not exist is refused.
#   osg_render_smoke.sh OSG_RENDER PAPER_MEASURE DISPLAY_FILE SCRATCH_DIR
set -euo pipefail
render=$1 measure=$2 display_file=$3 dir=$4
DISPLAY=$(cat "$display_file")
export DISPLAY
mkdir -p "$dir"
fail() { echo "FAIL: $*" >&2; exit 1; }
val() { awk -v k="$1" '$1 == k { print $2; exit }' "$2"; }

# A square of 2 x 8 triangles, so the LOD builder has something to remove.
{
  echo "ply"; echo "format ascii 1.0"; echo "element vertex 15"
  echo "property float x"; echo "property float y"; echo "property float z"
  echo "element face 16"; echo "property list uchar int vertex_indices"; echo "end_header"
  for y in 0 1 2; do for x in 0 1 2 3 4; do echo "$x $y 0"; done; done
  for y in 0 1; do for x in 0 1 2 3; do
    a=$((y * 5 + x)); echo "3 $a $((a + 1)) $((a + 6))"; echo "3 $a $((a + 6)) $((a + 5))"
  done; done
} >"$dir/square.ply"

"$render" "$dir/square.ply" --frames 10 --size 64x48 >"$dir/plain.out"
[ "$(val triangles "$dir/plain.out")" = 16 ] || fail "expected 16 triangles: $(cat "$dir/plain.out")"
[ "$(val lod_levels "$dir/plain.out")" = 0 ] || fail "a PLY has no LOD levels"
awk '$1 == "fps" && $2 > 0 { ok = 1 } END { exit !ok }' "$dir/plain.out" || fail "no frame rate"

"$render" "$dir/square.ply" --shot "$dir/square.png" --wire --size 64x48 >/dev/null
[ -s "$dir/square.png" ] || fail "no picture written"

"$measure" lodset "$dir/square.ply" "$dir" "50" >/dev/null
"$render" "$dir/lodset.flt" --frames 10 --size 64x48 >"$dir/set.out"
[ "$(val lod_levels "$dir/set.out")" = 2 ] || fail "expected 2 LOD levels: $(cat "$dir/set.out")"
awk '$1 == "level" && $2 == 1 && $4 < 16 && $4 > 0 { ok = 1 } END { exit !ok }' "$dir/set.out" ||
  fail "level 1 should have fewer triangles than level 0: $(cat "$dir/set.out")"
awk '$1 == "path_level" && $4 > 0 { n++ } END { exit n != 2 }' "$dir/set.out" ||
  fail "the default camera path should draw both levels: $(grep path_ "$dir/set.out")"
"$render" "$dir/lodset.flt" --level 1 --frames 10 --size 64x48 >/dev/null || fail "--level 1 refused"
"$render" "$dir/lodset.flt" --path inside --frames 10 --size 64x48 >"$dir/inside.out"
awk '$1 == "path_kind" && $2 == "inside" { k = 1 } $1 == "path_mean_triangles" && $2 > 0 { t = 1 }
     $1 == "fps_cpu" && $2 > 0 { f = 1 } END { exit !(k && t && f) }' "$dir/inside.out" ||
  fail "the inside path should draw and time frames: $(cat "$dir/inside.out")"
if "$render" "$dir/lodset.flt" --path around --no-render >/dev/null 2>&1; then fail "--path around accepted"; fi
if "$render" "$dir/lodset.flt" --level 2 --no-render >/dev/null 2>&1; then fail "--level 2 accepted"; fi
echo "osg_render smoke test passed"
