#!/usr/bin/env bash
# Converts many CAD exports with `cadlod convert`, scheduled by GNU parallel:
#   scripts/batch_convert.sh [options] OUT_DIR FILE|DIR... [-- cadlod convert options]
# Every .wrl/.wrz/.vrml/.wrl.gz/.vrml.gz under the inputs (symbolic links followed) becomes
# OUT_DIR/<name>.flt, <name> being the file name without that extension only
# (PinHeader_1x01_P2.00mm_Vertical.wrl -> PinHeader_1x01_P2.00mm_Vertical.flt), with its
# JSON report in OUT_DIR/reports/<name>.json and its log in OUT_DIR/logs/<name>.log. Two
# inputs with the same <name> are a collision: both fail, neither is converted. An existing
# output is kept (SKIP). One status line per file (with its warning count; an input that lost
# geometry fails, or is PARTIAL with --allow-partial), a total, exit 1 if any file failed.
# Options:
#   -j JOBS            jobs per machine (GNU parallel -j; default: one per core)
#   -S SSHLOGIN        GNU parallel --sshlogin, repeatable (e.g. -S 8/node1 -S 8/node2 -S :);
#                      remote machines need cadlod on their PATH (or --cadlod) and the same
#                      paths (a shared file system)
#   --joblog FILE      GNU parallel job log (default OUT_DIR/joblog.txt)
#   --resume           skip the jobs the job log records as run (after an interruption)
#   --resume-failed    also retry the failed ones
#   -t SECONDS         per-file timeout (default 1800)
#   --cadlod PATH      the cadlod executable (default: $CADLOD, cadlod on PATH, or build/cli/cadlod)
# Default convert options: --default-unit mm (CAD exports; a KiCad StepUp file says 0.1 inch
# itself); anything after -- replaces them.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
usage() { sed -n '2,22p' "$0" >&2; exit 2; }

jobs=100% timeout_s=1800 joblog="" resume=() sshlogins=() cadlod="${CADLOD:-}"
positional=() convert_opts=(--default-unit mm)
while [ $# -gt 0 ]; do
  case "$1" in
    -j) jobs=$2; shift ;;
    -S|--sshlogin) sshlogins+=(--sshlogin "$2"); shift ;;
    --joblog) joblog=$2; shift ;;
    --resume) resume=(--resume) ;;
    --resume-failed) resume=(--resume-failed) ;;
    -t) timeout_s=$2; shift ;;
    --cadlod) cadlod=$2; shift ;;
    -h|--help) usage ;;
    --) shift; convert_opts=("$@"); break ;;
    -*) echo "batch_convert.sh: unknown option $1" >&2; usage ;;
    *) positional+=("$1") ;;
  esac
  shift
done
[ ${#positional[@]} -ge 2 ] || usage
command -v parallel >/dev/null || { echo "GNU parallel is missing: run scripts/bootstrap.sh" >&2; exit 1; }
if [ -z "$cadlod" ]; then
  cadlod=$(command -v cadlod || echo "${CADLOD_BUILD_DIR:-$ROOT/build}/cli/cadlod")
fi
[ -x "$cadlod" ] || { echo "no cadlod executable ($cadlod): build it (scripts/test.sh) or pass --cadlod" >&2; exit 1; }
cadlod=$(realpath "$cadlod")
out=$(realpath -m "${positional[0]}")
inputs=()
for i in "${positional[@]:1}"; do inputs+=("$(realpath -s "$i")"); done  # absolute, for remote jobs
joblog=${joblog:-$out/joblog.txt}
mkdir -p "$out/logs" "$out/reports"

# The output name: the file name without one known VRML extension, nothing else.
output_name() {
  local base lower
  base=$(basename "$1"); lower=${base,,}
  for ext in .wrl.gz .vrml.gz .wrl .wrz .vrml; do
    if [[ $lower == *"$ext" ]]; then echo "${base:0:${#base}-${#ext}}"; return; fi
  done
  echo "$base"
}

list=$(mktemp) names=$(mktemp)
trap 'rm -f "$list" "$names" "$list.run"' EXIT
find -L "${inputs[@]}" -type f \( -iname '*.wrl' -o -iname '*.wrz' -o -iname '*.vrml' -o -iname '*.wrl.gz' \
  -o -iname '*.vrml.gz' \) -print0 | sort -z > "$list"
total=$(tr -cd '\0' < "$list" | wc -c)
[ "$total" -gt 0 ] || { echo "no VRML files under: ${inputs[*]}" >&2; exit 1; }

# Collisions: inputs whose output names are equal fail before anything runs.
collisions=0
: > "$list.run"
while IFS= read -r -d '' f; do printf '%s\t%s\n' "$(output_name "$f")" "$f"; done < "$list" > "$names"
while IFS=$'\t' read -r name f; do
  if [ "$(cut -f1 "$names" | grep -cxF -- "$name")" -gt 1 ]; then
    echo "FAIL  $f (output name collision: $out/$name.flt has several inputs)"
    collisions=$((collisions + 1))
  else
    printf '%s\0' "$f" >> "$list.run"
  fi
done < "$names"

# One file: SKIP when its output exists, else cadlod convert (which writes through a
# temporary file: an interrupted job leaves no truncated .flt); a status line either way.
convert_one() {
  local in=$1 name flt log rc=0 start ms
  name=$(output_name "$in"); flt="$out/$name.flt"; log="$out/logs/$name.log"
  if [ -e "$flt" ]; then echo "SKIP  $in ($flt exists)"; return 0; fi
  rm -f "$out/.$name.flt.tmp-"* "$out/reports/.$name.json.tmp-"*  # left by a killed run
  start=$(date +%s%N)
  env -u DISPLAY timeout -k 10 "$timeout_s" "$cadlod" convert "$in" -o "$flt" --report "$out/reports/$name.json" \
    --force "${convert_opts[@]}" >"$log" 2>&1 || rc=$?
  ms=$(( ($(date +%s%N) - start) / 1000000 ))
  if [ $rc -eq 0 ] && [ -s "$flt" ]; then
    local report="$out/reports/$name.json" warnings status=OK
    warnings=$(grep -m1 -o '"warningCount": [0-9]*' "$report" | grep -o '[0-9]*$' || echo "?")
    grep -q '"complete": false' "$report" && status=PARTIAL
    echo "$status$(printf '%*s' $((6 - ${#status})) '')$in -> $flt (${ms} ms; $(grep -m1 -o '[0-9]* levels' "$log" || true); ${warnings} warning(s))"
    return 0
  fi
  local reason
  [ $rc -eq 124 ] && reason="timed out after ${timeout_s}s" || reason="exit $rc: $(grep -m1 'error' "$log" || tail -n 1 "$log")"
  echo "FAIL  $in ($reason; log $log)"
  return 1
}
convert_opts_str=$(printf '%q ' "${convert_opts[@]}")
export -f convert_one output_name
export out cadlod timeout_s convert_opts_str

status=0
if [ -s "$list.run" ]; then
  # convert_opts is an array: passed as a quoted string and re-split in the job's shell.
  parallel -0 --will-cite --line-buffer -j "$jobs" "${sshlogins[@]}" --joblog "$joblog" "${resume[@]}" \
    --env convert_one --env output_name --env out --env cadlod --env timeout_s --env convert_opts_str \
    'eval "convert_opts=($convert_opts_str)"; convert_one {}' :::: "$list.run" | tee -a "$out/status.txt" \
    || status=1
fi
converted=$(find "$out" -maxdepth 1 -name '*.flt' | wc -l)
echo "$total file(s): $converted output(s) in $out, $collisions collision(s), parallel status $status (details: $out/status.txt, $joblog)"
[ $status -eq 0 ] && [ $collisions -eq 0 ]
