#!/usr/bin/env bash
# MeshLab's stock "Simplification: Quadric Edge Collapse Decimation" (defaults) through the
# staged meshlabserver, load/save time subtracted with a second run without the filter.
#   bench/simplify/meshlab_stock.sh BUILD_DIR MESH.ply [REDUCTION% ...]
# Meshes: simplify_bench --dump-ply DIR. Prints one Markdown row per reduction.
set -euo pipefail
BUILD="$1"; MESH="$2"; shift 2
REDUCTIONS=("${@:-50 90}")
SERVER="$BUILD/stage/bin/meshlabserver"
COMPLETE="$BUILD/tests/e2e/cadlod_mlx_complete"
PLUGINS="$BUILD/stage/lib/x86_64-linux-gnu/meshlab/plugins"
WORK="$(mktemp -d)"; trap 'rm -rf "$WORK"' EXIT
run() {  # prints "seconds peak_kb"
  /usr/bin/time -f "%e %M" -o "$WORK/time" timeout 1200 xvfb-run -a "$SERVER" "$@" >"$WORK/log" 2>&1
  cat "$WORK/time"
}
read -r base _ < <(run -i "$MESH" -o "$WORK/noop.ply")
faces_in=$(grep -a -m1 "element face" "$MESH" | awk '{print $3}')
for red in ${REDUCTIONS[@]}; do
  keep=$(awk -v r="$red" 'BEGIN{printf "%.4f", 1 - r/100}')
  cat >"$WORK/short.mlx" <<MLX
<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Simplification: Quadric Edge Collapse Decimation">
  <Param type="RichInt" name="TargetFaceNum" value="0"/>
  <Param type="RichFloat" name="TargetPerc" value="$keep"/>
 </filter>
</FilterScript>
MLX
  xvfb-run -a "$COMPLETE" "$PLUGINS" "$WORK/short.mlx" "$WORK/full.mlx" >/dev/null 2>&1
  read -r total peak < <(run -i "$MESH" -o "$WORK/out.ply" -s "$WORK/full.mlx")
  faces_out=$(grep -a -m1 "element face" "$WORK/out.ply" | awk '{print $3}')
  awk -v m="$(basename "$MESH" .ply)" -v r="$red" -v fi="$faces_in" -v fo="$faces_out" -v t="$total" -v b="$base" -v p="$peak" \
    'BEGIN{s=t-b; if(s<=0)s=0.001; printf "| %s | %s%% | meshlab (meshlabserver) | %d | %d | %.3f | %.0f | %.0f |\n", m, r, fi, fo, s, fi/s, p/1024}'
done
