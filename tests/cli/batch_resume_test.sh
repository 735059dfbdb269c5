#!/usr/bin/env bash
# batch_convert.sh on GNU parallel with two job slots on the local "host" (-S 2/:, no ssh for ":"):
# the batch is killed (SIGKILL, whole process group) once two files are done, then resumed
# from its job log; every input must end up converted exactly once, each output readable
# by OpenSceneGraph, no stray temporary files counted as outputs. Also: names that differ
# only before the extension do not collide; a real collision fails the batch.
#   batch_resume_test.sh CADLOD OSG_FLT_PROBE SOURCE_DIR
set -euo pipefail
cadlod=$1 probe=$2 src=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
demo="$src/docs/sample/cad_assembly.wrl.gz"
vrml1="$src/../shared/corpus/castle-demo-models/vrml_1"
mkdir -p "$work/in/sub" "$work/elsewhere"
for pitch in 2.00 2.54; do ln -s "$demo" "$work/in/PinHeader_1x01_P${pitch}mm_Vertical.wrl.gz"; done
for i in 1 2 3 4; do ln -s "$demo" "$work/in/sub/part_$i.wrl.gz"; done
cp "$vrml1/cones.wrl" "$work/elsewhere/cones.wrl"
ln -s "$work/elsewhere" "$work/in/linked_dir"   # a symlinked input directory is followed
expected=(PinHeader_1x01_P2.00mm_Vertical PinHeader_1x01_P2.54mm_Vertical part_1 part_2 part_3 part_4 cones)
batch=("$src/scripts/batch_convert.sh" --cadlod "$cadlod" -S 2/:)
convert=(-- --unit mm --lod "80 95")

fail() { echo "FAIL: $*" >&2; exit 1; }

# 1. Start, kill the whole batch once two jobs are in the job log.
setsid "${batch[@]}" "$work/out" "$work/in" "${convert[@]}" > "$work/first.txt" 2>&1 &
pid=$!
jobs_done() { local n; n=$(grep -c $'\t:\t' "$work/out/joblog.txt" 2>/dev/null) || true; echo "${n:-0}"; }
until [ "$(jobs_done)" -ge 2 ] || ! kill -0 $pid 2>/dev/null; do
  sleep 0.2
done
kill -KILL -- -$pid 2>/dev/null || true
wait $pid 2>/dev/null || true
done_first=$(grep -c '^OK' "$work/first.txt" || true)
echo "first run: $done_first file(s) done before the kill"
[ "$done_first" -lt ${#expected[@]} ] || echo "note: the batch finished before it was killed"

# 2. Resume.
"${batch[@]}" --resume "$work/out" "$work/in" "${convert[@]}" > "$work/second.txt" 2>&1 || { cat "$work/second.txt"; fail "resumed batch failed"; }
cat "$work/second.txt"

# 3. Every output once, each readable, nothing else.
for name in "${expected[@]}"; do
  flt="$work/out/$name.flt"
  [ -s "$flt" ] || fail "$name.flt missing"
  "$probe" "$flt" noUnitsConversion > "$work/probe.txt" || fail "$name.flt unreadable by OpenSceneGraph"
  grep -q '^lod_children [1-9]' "$work/probe.txt" || fail "$name.flt has no LOD children"
  "$cadlod" info "$flt" > /dev/null || fail "$name.flt unreadable by cadlod"
done
count=$(find "$work/out" -maxdepth 1 -name '*.flt' | wc -l)
[ "$count" -eq ${#expected[@]} ] || fail "$count outputs, expected ${#expected[@]}"
# The resumed run converted the rest and skipped nothing it had to do again.
grep -q '^FAIL' "$work/second.txt" && fail "the resumed run has failures"

# 4. A collision (same name, two extensions) fails the batch and converts neither.
mkdir -p "$work/clash"
ln -s "$demo" "$work/clash/board.wrl.gz"
cp "$vrml1/cones.wrl" "$work/clash/board.wrl"
if "$src/scripts/batch_convert.sh" --cadlod "$cadlod" "$work/clash_out" "$work/clash" > "$work/clash.txt" 2>&1; then
  fail "a name collision did not fail the batch"
fi
grep -q 'collision' "$work/clash.txt" || fail "no collision message"
[ ! -e "$work/clash_out/board.flt" ] || fail "a colliding input was converted"
# 5. An input that lost geometry (cut short) fails the batch with its place in the file; with
#    --allow-partial it is converted and marked PARTIAL. Every OK line counts the warnings.
mkdir -p "$work/broken"
ln -s "$demo" "$work/broken/whole.wrl.gz"
zcat "$demo" > "$work/whole.wrl"
head -c $(( $(wc -c < "$work/whole.wrl") / 2 )) "$work/whole.wrl" > "$work/broken/cut.wrl"  # half of its parts
if "$src/scripts/batch_convert.sh" --cadlod "$cadlod" "$work/broken_out" "$work/broken" -- --unit mm --lod 90 \
    > "$work/broken.txt" 2>&1; then
  cat "$work/broken.txt"; fail "a truncated input did not fail the batch"
fi
grep -q '^FAIL  .*cut.wrl (exit 1: .*cut.wrl:[0-9]*:[0-9]*: syntax error' "$work/broken.txt" \
  || { cat "$work/broken.txt"; fail "no FAIL line with the place of the loss"; }
grep -q '^OK    .*whole.wrl.gz .*; 0 warning(s))' "$work/broken.txt" || { cat "$work/broken.txt"; fail "no warning count"; }
[ ! -e "$work/broken_out/cut.flt" ] || fail "a truncated input was converted"
"$src/scripts/batch_convert.sh" --cadlod "$cadlod" "$work/partial_out" "$work/broken" -- --unit mm --lod 90 \
  --allow-partial > "$work/partial.txt" 2>&1 || { cat "$work/partial.txt"; fail "--allow-partial failed the batch"; }
grep -q '^PARTIAL .*cut.wrl .*; 1 warning(s))' "$work/partial.txt" || { cat "$work/partial.txt"; fail "no PARTIAL line"; }
echo "batch resume test passed"
