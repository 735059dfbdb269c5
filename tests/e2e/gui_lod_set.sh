#!/usr/bin/env bash
# What the staged MeshLab GUI shows around "Generate CAD LOD Set" on a small part in
# metres, driven by the probe (gui_probe/gui_probe.cpp):
#  - after the VRML import the status bar no longer says "Reading VRML";
#  - Export Mesh As proposes the input's folder and base name, for the input and for a level;
#  - no scratch layer shows up while the set is built;
#  - level 0 is drawn, the other levels are hidden (in the document and in the view);
#  - layers are named "<base> LODk <distance>", level 0 included, and fit the layer panel;
#  - the Simplification Report's histogram bars start at one x in the log panel.
# Usage: gui_lod_set.sh STAGED_MESHLAB DISPLAY_FILE PROBE_LIB
set -uo pipefail
here=$(dirname "$0")
. "$here/gui_probe.sh"
meshlab=$1 probe=$3
export DISPLAY=$(cat "$2")
dir=$(mktemp -d)
write_sample_part "$dir/part.wrl"
run_probe "$meshlab" "$probe" lodset "$dir" "$dir/part.wrl"
rc=$?
facts="$dir/facts.txt"
status=0
fail() { echo "FAIL: $*"; status=1; }
[ $rc = 0 ] || fail "MeshLab with the probe exited with $rc"
grep -q "^status after open: .*Reading" "$facts" && fail "the status bar still says $(grep '^status after open' "$facts")"
grep -q "^status after open: " "$facts" || fail "no status bar seen after the import"
n=$(grep -c "^export proposes folder $dir | name part" "$facts")
[ "$n" = 2 ] || fail "Export Mesh As does not propose $dir/part… for the input and for a level"
grep "^seen while running: " "$facts" && fail "scratch layers showed in the document while the set was built"
layers=$(grep -c "^layer " "$facts")
[ "$layers" -ge 3 ] || fail "expected level 0 and at least two levels, got $layers layers"
grep -q "^layer [0-9]* | part LOD0 <[^|]* | visible 1 | drawn 1$" "$facts" || fail "level 0 is not named LOD0 and drawn"
grep -q "^panel part LOD0 <[0-9.]* mm \*\? |" "$facts" || fail "the layer panel does not show level 0 as 'part LOD0 <d mm'"
grep -q "^panel part LOD1 ≥[0-9.]* m\?m |" "$facts" || fail "the layer panel does not show level 1 as 'part LOD1 ≥d mm'"
# Labels end in a suffix the panel drops (it drops what follows a label's last '.').
hidden=$(grep -cE "^layer [0-9]+ \| part LOD[1-9][0-9]* (≥|>=)[0-9.]+ (mm|m)(\.flt)? \| visible 0 \| drawn 0$" "$facts")
[ "$hidden" = $((layers - 1)) ] || fail "levels 1.. are not all hidden and named 'part LODk ≥d unit'"
while IFS='|' read -r _ needs; do
  n=$(sed -E 's/.*needs ([0-9]+) px, column ([0-9]+) px.*/\1 \2/' <<<"$needs")
  read -r need have <<<"$n"
  [ "$need" -le "$have" ] || fail "layer name cut in the panel:$_ ($need px in $have px)"
done < <(grep "^panel .*LOD" "$facts")
# Every bar of the histogram starts at the same x as the first one.
starts=$(grep "^histogram " "$facts" | cut -d'|' -f1 | cut -d' ' -f2- | tr ' ' '\n' | grep . | sort -u)
[ -n "$starts" ] || fail "no histogram in the log panel"
[ "$(wc -l <<<"$starts")" -le 1 ] || fail "histogram bars start at different places: $(echo $starts)"
[ $status = 0 ] && echo "status bar, export name, layers, visibility and histogram as expected"
[ $status = 0 ] || { cat "$facts"; tail -20 "$dir/meshlab.log"; }
rm -rf "$dir"
exit $status
