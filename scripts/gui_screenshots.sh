#!/usr/bin/env bash
# Screenshots of the staged MeshLab GUI with cadlod's plugins, for docs/ (user guide).
# Needs a build (scripts/test.sh or scripts/demo.sh). Runs its own Xvfb; writes only
# docs/img/gui-*.png and a scratch directory under the build.
#   scripts/gui_screenshots.sh [BUILD_DIR]
# The clicks are at fixed positions of MeshLab 2020.09's default window (853x725, no
# window manager); if MeshLab's layout changes, the pictures show it.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="$(realpath "${1:-$ROOT/build}")"
STAGE="$BUILD/stage"
OUT="$ROOT/docs/img"
WORK="$BUILD/gui-screenshots"
[ -x "$STAGE/bin/meshlab" ] || { echo "no staged meshlab in $BUILD: build first (scripts/test.sh)" >&2; exit 1; }
mkdir -p "$OUT" "$WORK"
SHAFT="$ROOT/docs/sample/shaft.wrl"

Xvfb -displayfd 3 -screen 0 1280x900x24 -nolisten tcp -noreset 3>"$WORK/display" >/dev/null 2>&1 &
XVFB=$!
trap 'pkill -f "$STAGE/bin/meshlab " 2>/dev/null || true; kill $XVFB 2>/dev/null || true' EXIT
for _ in $(seq 300); do [ -s "$WORK/display" ] && break; sleep 0.1; done  # a loaded machine takes seconds
[ -s "$WORK/display" ] || { echo "Xvfb did not start" >&2; exit 1; }
export DISPLAY=":$(tr -d '[:space:]' < "$WORK/display")"

shot() { import -window root -crop 853x725+0+0 +repage "$OUT/gui-$1.png"; echo "wrote docs/img/gui-$1.png"; }
click() { xdotool mousemove "$1" "$2" click 1; sleep "${3:-1}"; }
start_meshlab() {
  pkill -f "$STAGE/bin/meshlab " 2>/dev/null || true
  "$STAGE/bin/meshlab" "$@" >"$WORK/meshlab.log" 2>&1 &
  for _ in $(seq 100); do xdotool search --onlyvisible --name MeshLab >/dev/null 2>&1 && break; sleep 0.2; done
  sleep 4
}
open_submenu() {  # Filters > submenu at height $1
  click 120 10; xdotool mousemove 240 "$1"; sleep 0.5; xdotool mousemove 300 "$1"; sleep 1
}

# 1. Opening a CAD VRML: cadlod's import options (unit scale mm -> m, merging, up axis, KiCad units, normals).
start_meshlab "$SHAFT"
xdotool mousemove 470 169 click --repeat 3 1; xdotool type "0.001"; sleep 0.5
shot open-options
click 399 360 3
# 2. Filters > Remeshing lists the CAD Quadric Edge Collapse and Generate CAD LOD Set.
open_submenu 161
import -window root -crop 1280x900+0+0 +repage "$OUT/gui-remeshing-menu.png"; echo "wrote docs/img/gui-remeshing-menu.png"
# 3. The LOD-set dialog, then its result: one layer per level and the level table in the log.
click 430 237 2
shot lod-set-dialog
click 309 625 20  # Apply
shot lod-set-layers
click 108 625  # Close

# 4. Filters > Quality Measure and Computations > Compute Triangle Compactness.
open_submenu 261
import -window root -crop 980x900+0+0 +repage "$OUT/filters-menu-compactness.png"; echo "wrote docs/img/filters-menu-compactness.png"
xdotool key Escape Escape

# 5. Compactness as color (red: slivers, towards blue: compact): the shaft as exported, after
#    cadlod's 90 % reduction, and after MeshLab's stock Quadric Edge Collapse at 90 %.
color='<filter name="Compute Triangle Compactness"/>
 <filter name="Colorize by face Quality"><Param name="minVal" value="0"/><Param name="maxVal" value="1"/></filter>
 <filter name="Transform: Rotate"><Param name="rotAxis" value="1"/><Param name="angle" value="90"/></filter>'
move() { echo "<filter name=\"Transform: Translate, Center, set Origin\"><Param name=\"axisY\" value=\"$1\"/></filter>"; }
echo "<FilterScript>$color</FilterScript>" > "$WORK/before.mlx"
echo "<FilterScript><filter name=\"Simplification: CAD Quadric Edge Collapse (compactness)\"><Param name=\"targetFaces\" value=\"0\"/><Param name=\"reductionPerc\" value=\"90\"/></filter>$color $(move -45)</FilterScript>" > "$WORK/cadlod.mlx"
echo "<FilterScript><filter name=\"Simplification: Quadric Edge Collapse Decimation\"><Param name=\"TargetFaceNum\" value=\"0\"/><Param name=\"TargetPerc\" value=\"0.1\"/></filter>$color $(move -90)</FilterScript>" > "$WORK/stock.mlx"
for name in before cadlod stock; do
  "$BUILD/tests/e2e/cadlod_mlx_complete" "$STAGE/lib/x86_64-linux-gnu/meshlab/plugins" "$WORK/$name.mlx" "$WORK/$name.full.mlx" 2>/dev/null
  timeout 300 "$STAGE/bin/meshlabserver" -i "$SHAFT" -s "$WORK/$name.full.mlx" -o "$WORK/$name.ply" -m fc >"$WORK/$name.log" 2>&1
done
start_meshlab "$WORK/before.ply" "$WORK/cadlod.ply" "$WORK/stock.ply"
xdotool mousemove 217 380; for _ in 1 2; do xdotool click 4; sleep 0.3; done; sleep 1
shot compactness-colors
