#!/usr/bin/env bash
# Screenshots of the staged MeshLab GUI (with cadlod's plugins) for docs/img/.
# Needs a build (scripts/test.sh or scripts/demo.sh). Runs its own Xvfb; touches nothing else.
#   scripts/gui_screenshots.sh [BUILD_DIR]
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${1:-$ROOT/build}"
MESHLAB="$BUILD/stage/bin/meshlab"
OUT="$ROOT/docs/img"
[ -x "$MESHLAB" ] || { echo "no staged meshlab in $BUILD: build first (scripts/test.sh)" >&2; exit 1; }
mkdir -p "$OUT"
work=$(mktemp -d)
trap 'kill $(jobs -p) 2>/dev/null || true; rm -rf "$work"' EXIT

Xvfb -displayfd 3 -screen 0 1280x900x24 -nolisten tcp 3>"$work/display" >/dev/null 2>&1 &
for _ in $(seq 50); do [ -s "$work/display" ] && break; sleep 0.1; done
export DISPLAY=":$(tr -d '[:space:]' < "$work/display")"

sample="${CADLOD_SCREENSHOT_MESH:-$ROOT/docs/sample/shaft.ply}"
[ -f "$sample" ] || sample=""
"$MESHLAB" $sample >"$work/meshlab.log" 2>&1 &
for _ in $(seq 100); do xdotool search --name MeshLab >/dev/null 2>&1 && break; sleep 0.2; done
sleep 3

shot() { import -window root -crop "$2" +repage "$OUT/$1.png"; echo "wrote docs/img/$1.png"; }

# Filters > Quality Measure and Computations > Compute Triangle Compactness
xdotool mousemove 120 10 click 1; sleep 1
xdotool mousemove 240 261; sleep 0.5; xdotool mousemove 300 261; sleep 1
shot filters-menu-compactness 980x900+0+0
xdotool key Escape Escape
