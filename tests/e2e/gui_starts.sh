#!/usr/bin/env bash
# The staged MeshLab GUI starts on the test Xvfb with cadlod's plugins loaded, and no
# plugin fails to load. Usage: gui_starts.sh STAGED_MESHLAB DISPLAY_FILE
set -uo pipefail
. "$(dirname "$0")/gui_window.sh"
meshlab=$1
export DISPLAY=$(cat "$2")
xdotool getdisplaygeometry >/dev/null 2>&1 || { echo "FAIL: the test display $DISPLAY takes no clients"; exit 1; }
log=$(mktemp)
LD_PRELOAD="${CADLOD_SANITIZER_PRELOAD:-}" "$meshlab" >"$log" 2>&1 &
pid=$!
window=$(wait_for_window '^MeshLab' 150 $pid)
sleep 1
alive=0; kill -0 $pid 2>/dev/null && alive=1
kill $pid 2>/dev/null; wait $pid 2>/dev/null
status=0
[ -n "$window" ] || { echo "FAIL: no MeshLab window appeared"; status=1; }
[ $alive = 1 ] || { echo "FAIL: meshlab exited by itself"; status=1; }
grep -q "Current Plugins Dir is: $(dirname "$(dirname "$meshlab")")/lib/x86_64-linux-gnu/meshlab/plugins" "$log" \
  || { echo "FAIL: not using the staged plugin directory"; status=1; }
if grep -Ei "cannot load library|undefined symbol|Missing (class|requirements|preconditions|postcondition|Arity)" "$log"; then
  echo "FAIL: a plugin failed to load"; status=1
fi
[ $status = 0 ] && echo "MeshLab GUI window $window up, plugins loaded from the stage"
[ $status = 0 ] || cat "$log"
rm -f "$log"
exit $status
