#!/usr/bin/env bash
# Table 1 with the camera inside (docs/benchmarks.md; issue 64 item 5):
#   bench/assemblies/table1_inside.sh BUILD_DIR WORK_DIR [ASSEMBLY...]   (default: demo cabinet_q)
# For each assembly (the bundled demo, or one made by make_assemblies.py into WORK_DIR):
# converts it as one node (--instances expand: one LOD chain for the whole model) and as
# HLOD (the default, --hlod auto); renders both with bench/paper/osg_render on a private Xvfb
# (Mesa software GL) along the inside path (view_error's 4x4x2 grid, 300 frames, 640x480),
# median of 3 runs; and measures the error on screen on that path with bench/view_error.
# Both files and both tools lay the path in the one-node file's box: OSG's own box of the HLOD
# file is larger (it bounds rotated parts by their turned boxes).
# A .flt newer than its input and than cadlod is reused (cabinet_q takes minutes to convert).
set -euo pipefail
BUILD="$(cd "$1" && pwd)"; WORK="$2"; shift 2
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ASSEMBLIES=("$@"); [ $# -gt 0 ] || ASSEMBLIES=(demo cabinet_q)
CADLOD="$BUILD/cli/cadlod"; RENDER="$BUILD/bench/paper/osg_render"; VIEW="$BUILD/bench/view_error/view_error"
FRAMES=300; RUNS=3
mkdir -p "$WORK/table1"; WORK="$(cd "$WORK" && pwd)"; OUT="$WORK/table1"

input_of() { [ "$1" = demo ] && echo "$HERE/../../docs/sample/cad_assembly.wrl.gz" || echo "$WORK/$1/$1.wrl"; }
unit_of() { [ "$1" = demo ] && echo mm || echo 0.1in; }
label_of() { [ "$1" = expand ] && echo "one node" || echo HLOD; }
key() { awk -v k="$1" '$1 == k { print $2; exit }' "$2"; }
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }'; }

# A private X server, as scripts/paper does: the frame rates are Mesa's, not a desktop's.
start_xvfb() {
  : >"$OUT/display"
  Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$OUT/display" >"$OUT/xvfb.log" 2>&1 &
  XVFB_PID=$!
  trap 'kill "$XVFB_PID" 2>/dev/null || true' EXIT
  for _ in $(seq 50); do [ -s "$OUT/display" ] && break; sleep 0.1; done
  [ -s "$OUT/display" ] || { echo "Xvfb did not start (see $OUT/xvfb.log)" >&2; exit 1; }
  DISPLAY=":$(tr -d '\n' <"$OUT/display")"; export DISPLAY
}

convert() {  # ASSEMBLY RUN
  local in out args
  in="$(input_of "$1")"; out="$OUT/$1.$2.flt"
  if [ "$2" = expand ]; then args=(--instances expand); else args=(--hlod auto); fi
  [ "$out" -nt "$in" ] && [ "$out" -nt "$CADLOD" ] && return
  "$CADLOD" convert "$in" -o "$out" --unit "$(unit_of "$1")" "${args[@]}" --force -q 2>"$OUT/$1.$2.log"
}

render() {  # ASSEMBLY RUN BOX: RUNS timed runs; prints "triangles fps fps_cpu" (medians)
  local base="$OUT/$1.$2"
  for i in $(seq "$RUNS"); do
    "$RENDER" "$base.flt" --path inside --box "$3" --frames "$FRAMES" --size 640x480 >"$base.render$i.txt" \
      2>>"$base.render.log"
  done
  echo "$(key path_mean_triangles "$base.render1.txt")" \
    "$(for i in $(seq "$RUNS"); do key fps "$base.render$i.txt"; done | median)" \
    "$(for i in $(seq "$RUNS"); do key fps_cpu "$base.render$i.txt"; done | median)"
}

# "worst mean drawables" on the inside path, from view_error's line for FILE.
inside_error() { awk -v f="$1" '$1 == f && $2 == "inside" { print $4, $6, $10 }' "$2"; }

for a in "${ASSEMBLIES[@]}"; do
  [ -f "$(input_of "$a")" ] || python3 "$HERE/make_assemblies.py" "$WORK" >/dev/null
done
start_xvfb
echo "| model | run | mean triangles per frame | ratio HLOD / one node | fps | fps by CPU time | ratio (by CPU) | worst px inside | mean px inside | mean drawables |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for a in "${ASSEMBLIES[@]}"; do
  convert "$a" expand; convert "$a" hlod
  box=$("$RENDER" "$OUT/$a.expand.flt" --path inside --no-render | awk '$1 == "box" { print $2 }')
  "$VIEW" --box "$box" "$OUT/$a.expand.flt" "$OUT/$a.hlod.flt" >"$OUT/$a.view_error.txt"
  for r in expand hlod; do render "$a" "$r" "$box" >"$OUT/$a.$r.figures"; done
  read -r tri0 _ cpu0 <"$OUT/$a.expand.figures"
  for r in expand hlod; do
    read -r tri fps cpu <"$OUT/$a.$r.figures"
    inside_error "$OUT/$a.$r.flt" "$OUT/$a.view_error.txt" >"$OUT/$a.$r.error"
    read -r worst mean drawables <"$OUT/$a.$r.error"
    echo "| $a | $(label_of $r) | $tri | $(ratio "$tri" "$tri0") | $fps | $cpu | $(ratio "$cpu" "$cpu0") |" \
      "$worst | $mean | $drawables |"
  done
done
