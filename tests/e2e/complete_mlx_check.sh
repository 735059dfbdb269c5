#!/usr/bin/env bash
# scripts/complete_mlx.sh keeps the tool's error message when stderr is a file (issue 16,
# item 11: it was lost unless piped). Usage: complete_mlx_check.sh BUILD_DIR DISPLAY_FILE
set -uo pipefail
export CADLOD_BUILD_DIR=$1
export DISPLAY=$(cat "$2")
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cat >"$dir/short.mlx" <<'MLX'
<!DOCTYPE FilterScript>
<FilterScript>
 <filter name="Simplification: CAD Quadric Edge Collapse (compactness)">
  <Param name="reductionPercent" value="90" type="RichFloat"/>
 </filter>
</FilterScript>
MLX
status=0
bash "$here/../../scripts/complete_mlx.sh" "$dir/short.mlx" "$dir/full.mlx" 2>"$dir/stderr" || status=$?
cat "$dir/stderr"
[ $status -ne 0 ] || { echo "FAIL: a wrong parameter name was accepted"; exit 1; }
grep -q 'has no parameter "reductionPercent"' "$dir/stderr" || { echo "FAIL: the reason is lost"; exit 1; }
grep -q "reductionPerc" "$dir/stderr" || { echo "FAIL: the names it has are not listed"; exit 1; }
echo "the error message reaches a file"
