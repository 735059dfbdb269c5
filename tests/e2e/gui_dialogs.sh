#!/usr/bin/env bash
# Every help text of cadlod's dialogs shows whole in the staged MeshLab GUI: the VRML and
# OpenFlight open options, the three filter dialogs and the OpenFlight save options, each
# with its help shown (MeshLab's Help button or box). The probe measures each word-wrapped
# label: the height its text needs at its width must fit in what the label, its parents and
# the screen show of it.
# Usage: gui_dialogs.sh STAGED_MESHLAB DISPLAY_FILE PROBE_LIB
set -uo pipefail
here=$(dirname "$0")
. "$here/gui_probe.sh"
meshlab=$1 probe=$3
export DISPLAY=$(cat "$2")
dir=$(mktemp -d)
write_sample_part "$dir/part.wrl"
run_probe "$meshlab" "$probe" dialogs "$dir" "$dir/part.wrl"
rc=$?
status=0
[ $rc = 0 ] || { echo "FAIL: MeshLab with the probe exited with $rc"; status=1; }
for dialog in "VRML open options" "Simplification: CAD Quadric Edge Collapse (compactness)" \
              "Generate CAD LOD Set" "Simplification Report" "OpenFlight save options" \
              "OpenFlight open options"; do
  grep -q "^inspected $dialog: [1-9]" "$dir/facts.txt" || { echo "FAIL: $dialog not inspected"; status=1; }
done
if grep "^clipped" "$dir/facts.txt"; then echo "FAIL: help texts cut off (above)"; status=1; fi
[ $status = 0 ] && grep "^inspected" "$dir/facts.txt" && echo "every help text shows whole"
[ $status = 0 ] || { cat "$dir/facts.txt"; tail -20 "$dir/meshlab.log"; }
rm -rf "$dir"
exit $status
