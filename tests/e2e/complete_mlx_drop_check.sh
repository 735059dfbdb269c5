#!/usr/bin/env bash
# scripts/complete_mlx.sh --drop-unknown brings a complete script of an older version up to
# date: a parameter the filter no longer has is dropped, with a warning naming the filter
# and the parameter; without the option it stays an error (a typo must not pass).
# Usage: complete_mlx_drop_check.sh BUILD_DIR DISPLAY_FILE
set -uo pipefail
export CADLOD_BUILD_DIR=$1
export DISPLAY=$(cat "$2")
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$here/../.."
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; cat "$dir/stderr"; exit 1; }
# The shipped LOD-set script, as if an older version had written it with one more parameter.
sed 's|^\( *\)<Param type="RichInt" name="samples" value="0"/>|&\n\1<Param type="RichBool" name="keepSeams" value="true"/>|' \
  "$root/docs/examples/cad_to_flt.mlx" >"$dir/old.mlx"
grep -q 'name="keepSeams"' "$dir/old.mlx" || fail "could not make the old script"

status=0
bash "$root/scripts/complete_mlx.sh" "$dir/old.mlx" "$dir/refused.mlx" 2>"$dir/stderr" || status=$?
[ $status -ne 0 ] || fail "without --drop-unknown a parameter the filter lacks was accepted"
[ ! -e "$dir/refused.mlx" ] || fail "a refused script was written"
grep -q -- "--drop-unknown" "$dir/stderr" || fail "the error does not point to --drop-unknown"

status=0
bash "$root/scripts/complete_mlx.sh" --drop-unknown "$dir/old.mlx" "$dir/new.mlx" 2>"$dir/stderr" || status=$?
[ $status -eq 0 ] || fail "--drop-unknown failed (exit $status)"
grep -q 'warning: filter "Generate CAD LOD Set" has no parameter "keepSeams": dropped' "$dir/stderr" ||
  fail "no warning naming the filter and the parameter"
grep -q 'name="keepSeams"' "$dir/new.mlx" && fail "the dropped parameter is still in the script"
for p in levelMode samples featurePenalty; do
  grep -q "name=\"$p\"" "$dir/new.mlx" || fail "parameter $p was lost"
done
grep -q 'name="levelMode"[^>]*value="0"\|value="0"[^>]*name="levelMode"' "$dir/new.mlx" || fail "a given value was not kept"
cat "$dir/stderr"
echo "the parameter the filter no longer has is dropped, with a warning"
