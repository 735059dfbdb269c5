#!/usr/bin/env bash
# Instanced assemblies side by side (docs/benchmarks.md, "Assemblies"):
#   bench/assemblies/run.sh BUILD_DIR WORK_DIR [ASSEMBLY...]    (default: cabinet_q cabinet plant)
# For each assembly made by make_assemblies.py (into WORK_DIR, if missing), in one run:
#   keep      cadlod convert (instances kept, the default)
#   alone     every distinct part file converted alone, one after the other (the reference)
#   expand    cadlod convert --instances expand            (CADLOD_EXPAND=all for every assembly;
#             by default only cabinet_q: expanding the others takes many minutes and GB)
#   osg       OSG's own writer on the expanded model (osgconv of the unsimplified PLY)
# and prints time, peak memory, .flt size and OSG load time with the ratios to keep.
set -euo pipefail
BUILD="$(cd "$1" && pwd)"; WORK="$2"; shift 2
ASSEMBLIES=("${@:-cabinet_q cabinet plant}")
[ $# -gt 0 ] || ASSEMBLIES=(cabinet_q cabinet plant)
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
CADLOD="$BUILD/cli/cadlod"; STATS="$BUILD/tests/openflight/osg_assembly_stats"
mkdir -p "$WORK"; WORK="$(cd "$WORK" && pwd)"
[ -f "$WORK/cabinet/cabinet.wrl" ] || python3 "$HERE/make_assemblies.py" "$WORK" >/dev/null

# measure NAME CMD...: wall seconds and peak RSS (MB) of CMD, appended to $WORK/times.txt
measure() {
  local name="$1"; shift
  /usr/bin/time -f "$name %e %M" -a -o "$WORK/times.txt" "$@" >/dev/null 2>"$WORK/$name.log" ||
    { echo "$name failed: $(tail -2 "$WORK/$name.log")"; return 1; }
}
field() { awk -v n="$1" '$1 == n { print $'"$2"' }' "$WORK/times.txt" | tail -1; }
osg_load() { "$STATS" "$1" "$2" | awk '$1 == "load_seconds" { print $2 }'; }
size_mb() { awk -v b="$(stat -c %s "$1")" 'BEGIN { printf "%.1f", b / 1e6 }'; }

printf "%-10s %-7s %9s %9s %9s %9s  %s\n" assembly run seconds peak_MB flt_MB osg_load notes
for a in "${ASSEMBLIES[@]}"; do
  dir="$WORK/$a"; out="$WORK/out/$a"; mkdir -p "$out/alone"
  : > "$WORK/times.txt"
  measure "$a.keep" "$CADLOD" convert "$dir/$a.wrl" -o "$out/keep.flt" --unit 0.1in --force -q --report "$out/keep.json"
  start=$(date +%s.%N); alone_bytes=0; alone_peak=0
  for p in "$dir"/parts/*.wrl; do
    measure "$a.part" "$CADLOD" convert "$p" -o "$out/alone/$(basename "$p" .wrl).flt" --unit 0.1in --force -q
    alone_peak=$(( $(field "$a.part" 3) > alone_peak ? $(field "$a.part" 3) : alone_peak ))
    alone_bytes=$(( alone_bytes + $(stat -c %s "$out/alone/$(basename "$p" .wrl).flt") ))
  done
  alone_s=$(echo "$(date +%s.%N) - $start" | bc)
  placements=$(python3 -c "import json; print(json.load(open('$out/keep.json'))['output']['placements'])")
  keep_s=$(field "$a.keep" 2); keep_mb=$(( $(field "$a.keep" 3) / 1024 ))
  keep_size=$(stat -c %s "$out/keep.flt")
  printf "%-10s %-7s %9.1f %9d %9s %9s  %s placements; size target %.1f MB\n" "$a" keep "$keep_s" "$keep_mb" \
    "$(size_mb "$out/keep.flt")" "$(osg_load "$out/keep.flt" keep)" "$placements" \
    "$(echo "(1.5 * $alone_bytes + 200 * $placements) / 1000000" | bc -l)"
  printf "%-10s %-7s %9.1f %9d %9.1f %9s  keep/alone: time %.2f, size %.2f\n" "$a" alone "$alone_s" \
    "$((alone_peak / 1024))" "$(echo "$alone_bytes / 1000000" | bc -l)" - \
    "$(echo "$keep_s / $alone_s" | bc -l)" "$(echo "$keep_size / $alone_bytes" | bc -l)"
  if [ "$a" = cabinet_q ] || [ "${CADLOD_EXPAND:-}" = all ]; then
    measure "$a.expand" "$CADLOD" convert "$dir/$a.wrl" -o "$out/expand.flt" --unit 0.1in --instances expand --force -q
    printf "%-10s %-7s %9.1f %9d %9s %9s  expand/keep: time %.1f, memory %.1f, size %.1f\n" "$a" expand \
      "$(field "$a.expand" 2)" "$(( $(field "$a.expand" 3) / 1024 ))" "$(size_mb "$out/expand.flt")" \
      "$(osg_load "$out/expand.flt" expand)" "$(echo "$(field "$a.expand" 2) / $keep_s" | bc -l)" \
      "$(echo "$(field "$a.expand" 3) / $(field "$a.keep" 3)" | bc -l)" \
      "$(echo "$(stat -c %s "$out/expand.flt") / $keep_size" | bc -l)"
    measure "$a.ply" "$CADLOD" simplify "$dir/$a.wrl" -o "$out/expanded.ply" --unit 0.1in --reduction 0 --force -q
    measure "$a.osg" osgconv "$out/expanded.ply" "$out/osg.flt"
    printf "%-10s %-7s %9.1f %9d %9s %9s  osg/keep: size %.1f (level 0 only)\n" "$a" osg "$(field "$a.osg" 2)" \
      "$(( $(field "$a.osg" 3) / 1024 ))" "$(size_mb "$out/osg.flt")" "$(osg_load "$out/osg.flt" "")" \
      "$(echo "$(stat -c %s "$out/osg.flt") / $keep_size" | bc -l)"
  fi
done
