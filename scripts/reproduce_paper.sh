#!/usr/bin/env bash
# Reproduces the two experiments of the paper (Tang et al. 2015, §5) on the bundled samples
# and regenerates docs/paper-reproduction.md with its pictures (docs/img/paper-*.png):
#  - Experiment 1 (Fig. 6): docs/sample/shaft.wrl reduced by 90 % with MeshLab's stock
#    "Quadric Edge Collapse Decimation" (defaults) and with cadlod's CAD Quadric Edge
#    Collapse (defaults): shaded and wireframe pictures, compactness histograms and
#    numbers, symmetric Hausdorff distance to the original.
#  - Experiment 2 (Table 1): docs/sample/cad_assembly.wrl.gz as an LOD set at
#    0/50/60/70/80/90 % reduction: triangles, .flt size, OpenSceneGraph load time and frame
#    rate of every level alone and of the whole LOD set, as ratios against level 0 next to
#    the paper's.
# Everything runs through the staged meshlabserver with cadlod's plugins; rendering is
# OpenSceneGraph (bench/paper/osg_render) on a private Xvfb (Mesa software GL).
#
#   scripts/reproduce_paper.sh
# Environment: CADLOD_BUILD_DIR (default build/; configured with -DCADLOD_BUILD_BENCH=ON),
# PAPER_FRAMES (frames per frame-rate run, default 300), PAPER_RUNS (runs per figure,
# median kept, default 5).
# Writes only docs/img/paper-*.png, docs/paper-reproduction.md and $CADLOD_BUILD_DIR/paper-reproduction/.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${CADLOD_BUILD_DIR:-$ROOT/build}"
WORK="$BUILD/paper-reproduction"
IMG="$ROOT/docs/img"
DOC="$ROOT/docs/paper-reproduction.md"
FRAMES="${PAPER_FRAMES:-300}"
RUNS="${PAPER_RUNS:-5}"
SHAFT="$ROOT/docs/sample/shaft.wrl"
ASSEMBLY="$ROOT/docs/sample/cad_assembly.wrl.gz"
LEVELS="50 60 70 80 90"

STOCK_FILTER="Simplification: Quadric Edge Collapse Decimation"
CAD_FILTER="Simplification: CAD Quadric Edge Collapse (compactness)"
LOD_FILTER="Generate CAD LOD Set"
# Filter scripts list only what differs from the defaults; complete_mlx fills in every other
# parameter (meshlabserver 2020.09 aborts otherwise). The CAD simplification filter's stop
# criterion, for when the plugin has that filter (the face-count criterion off):
CAD_REDUCTION_PARAMS='<Param type="RichInt" name="targetFaces" value="0"/><Param type="RichFloat" name="reductionPerc" value="%s"/>'


say() { printf '[paper] %s\n' "$*" >&2; }
die() { printf '[paper] ERROR: %s\n' "$*" >&2; exit 1; }

# ---------------------------------------------------------------- set-up
build_tools() {
  local generator=()
  [ -f "$BUILD/CMakeCache.txt" ] || generator=(-G Ninja)
  say "configuring and building in $BUILD (stage, osg_render, paper_measure, cadlod_mlx_complete)"
  cmake -S "$ROOT" -B "$BUILD" "${generator[@]}" -DCADLOD_BUILD_BENCH=ON -DCADLOD_BUILD_TESTS=ON \
    >"$WORK/build.log" 2>&1 || die "cmake configure failed, see $WORK/build.log"
  cmake --build "$BUILD" --target stage osg_render paper_measure cadlod_mlx_complete -j2 >>"$WORK/build.log" 2>&1 ||
    die "build failed, see $WORK/build.log"
  MLS="$BUILD/stage/bin/meshlabserver"
  MLX_COMPLETE="$(find "$BUILD/tests" -name cadlod_mlx_complete -type f -perm -u+x | head -1)"
  [ -n "$MLX_COMPLETE" ] || die "cadlod_mlx_complete was not built"
  RENDER="$BUILD/bench/paper/osg_render"
  MEASURE="$BUILD/bench/paper/paper_measure"
}

XVFB_PID=""
stop_xvfb() { [ -n "$XVFB_PID" ] && kill "$XVFB_PID" 2>/dev/null; true; }
start_xvfb() {
  : >"$WORK/display"
  Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$WORK/display" >"$WORK/xvfb.log" 2>&1 &
  XVFB_PID=$!
  trap stop_xvfb EXIT
  for _ in $(seq 50); do
    [ -s "$WORK/display" ] && break
    sleep 0.1
  done
  [ -s "$WORK/display" ] || die "Xvfb did not start (see $WORK/xvfb.log)"
  export DISPLAY=":$(tr -d '\n' <"$WORK/display")"
  say "Xvfb on $DISPLAY"
}

# meshlabserver ARGS...: a timeout, because a dialog would block it for ever; no qDebug,
# which would echo every log line into the log a second time ("LOG: ...").
mls() {
  echo "== meshlabserver $*" >>"$WORK/meshlabserver.log"
  QT_LOGGING_RULES='*.debug=false' timeout 900 "$MLS" "$@" >>"$WORK/meshlabserver.log" 2>&1
}

# complete_mlx IN OUT: IN with every parameter the staged plugins define (defaults for
# those IN leaves out); false when IN names a filter or parameter the plugins lack.
complete_mlx() {
  "$MLX_COMPLETE" "$BUILD/stage/lib/x86_64-linux-gnu/meshlab/plugins" "$1" "$2" >>"$WORK/meshlabserver.log" 2>&1
}

# single_filter_mlx OUT FILTER [PARAM_XML]: a completed one-filter script
single_filter_mlx() {
  local out="$1" filter="$2" param="${3:-}"
  printf '<!DOCTYPE FilterScript>\n<FilterScript>\n <filter name="%s">\n  %s\n </filter>\n</FilterScript>\n' \
    "$filter" "$param" >"$out.partial"
  complete_mlx "$out.partial" "$out"
}

has_filter() { grep -qF "section f" "$WORK/filters.txt" && grep -qF " $1 " "$WORK/filters.txt"; }

# val KEY FILE: the value after "KEY " in a key-value output
val() { awk -v k="$1" '$1 == k { print $2; exit }' "$2"; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b > 0) ? a / b : 0 }'; }

# ---------------------------------------------------------------- experiment 1
# stock_qem IN OUT: MeshLab's QEM with its defaults, 90 %
stock_qem() {
  complete_mlx "$ROOT/bench/paper/stock_qem_90.mlx" "$WORK/stock_qem_90.mlx" &&
    mls -i "$1" -s "$WORK/stock_qem_90.mlx" -o "$2" -m vn fc && [ -s "$2" ] ||
    die "MeshLab's stock QEM failed on $1 (see $WORK/meshlabserver.log)"
}

# cadlod_simplify IN OUT PERCENT PLY: cadlod with its defaults at PERCENT % reduction, by the
# CAD simplification filter when the plugin has it, else the LOD-set filter with that one
# level, else (on PLY, the same mesh as IN) the simplifier core. Sets CAD_ROUTE.
cadlod_simplify() {
  local in="$1" out="$2" pct="$3" ply="$4" script="$WORK/cadlod_$3.mlx"
  rm -f "$out"
  # shellcheck disable=SC2059
  if has_filter "$CAD_FILTER" && single_filter_mlx "$script" "$CAD_FILTER" "$(printf "$CAD_REDUCTION_PARAMS" "$pct")"; then
    mls -i "$in" -s "$script" -o "$out" -m vn fc &&
      CAD_ROUTE="MeshLab filter \"$CAD_FILTER\" (defaults but the stop criterion: reduction %)" || rm -f "$out"
  fi
  if [ ! -s "$out" ] && has_filter "$LOD_FILTER" &&
    single_filter_mlx "$script" "$LOD_FILTER" "<Param type=\"RichEnum\" name=\"levelMode\" enum_cardinality=\"2\" value=\"1\" enum_val0=\"By screen-space error (VR)\" enum_val1=\"Level list (the paper)\"/><Param type=\"RichString\" name=\"levels\" value=\"$pct\"/>"; then
    mls -i "$in" -s "$script" -o "$out" -l 1 -m vn fc &&
      CAD_ROUTE="MeshLab filter \"$LOD_FILTER\" with one level (defaults but the levels), as the plugin has no \"$CAD_FILTER\"" ||
      rm -f "$out"
  fi
  if [ ! -s "$out" ]; then
    "$MEASURE" simplify "$ply" "$out" "$pct" >"$out.log" || die "cadlod's simplifier failed on $ply"
    CAD_ROUTE="cadlod's simplifier core with its defaults (bench/paper/paper_measure), as no MeshLab filter of cadlod could do it"
  fi
}

# measure_mesh MESH [REFERENCE]: compactness (+ histogram) and the distance to REFERENCE
measure_mesh() {
  local mesh="$1" base="${1%.ply}"
  "$MEASURE" compactness "$mesh" "$base.hist" 20 >"$base.compactness" || die "cannot measure $mesh"
  if [ -n "${2:-}" ]; then
    "$MEASURE" hausdorff "$2" "$mesh" >"$base.hausdorff" || die "Hausdorff distance of $mesh failed"
  fi
}

experiment1() {
  local e="$WORK/exp1" m
  mkdir -p "$e"
  rm -f "$e"/*.ply
  say "experiment 1: shaft, 90 % reduction"
  mls -i "$SHAFT" -o "$e/original.ply" -m vn fc && [ -s "$e/original.ply" ] || die "meshlabserver cannot read $SHAFT"
  stock_qem "$SHAFT" "$e/stock.ply"
  cadlod_simplify "$SHAFT" "$e/cadlod.ply" 90 "$e/original.ply"
  say "cadlod route: $CAD_ROUTE"
  measure_mesh "$e/original.ply"
  for m in stock cadlod; do measure_mesh "$e/$m.ply" "$e/original.ply"; done
  fig6_pictures "$e"
  fig6_histogram "$e"
}

# Shaded: the whole shaft from the side; wireframe: a close-up of the step from the
# 14 mm to the 18 mm section (PNG8 with few colours keeps the dense wireframes small).
fig6_pictures() {
  local e="$1" m common=(--size 800x600 --crease 30 --up x)
  local shaded=(--azimuth -15 --elevation 25 --distance 2.0)
  local wire=(--wire --azimuth -35 --elevation 30 --distance 0.2 --focus 0.79,0.91,0.35)
  for m in original stock cadlod; do
    "$RENDER" "$e/$m.ply" --shot "$e/$m-shaded.png" "${common[@]}" "${shaded[@]}" >"$e/$m.shot" 2>>"$WORK/render.log" &&
      "$RENDER" "$e/$m.ply" --shot "$e/$m-wire.png" "${common[@]}" "${wire[@]}" >>"$e/$m.shot" 2>>"$WORK/render.log" ||
      die "osg_render cannot draw $m (see $WORK/render.log)"
  done
  local kind format
  for kind in shaded wire; do
    format=(-depth 8 "$IMG/paper-fig6-$kind.png")
    [ "$kind" = wire ] && format=(-colors 32 "PNG8:$IMG/paper-fig6-$kind.png")
    montage -font DejaVu-Sans -pointsize 14 \
      -label "(a) original, $(val faces "$e/original.compactness") triangles" "$e/original-$kind.png" \
      -label "(b) MeshLab QEM, $(val faces "$e/stock.compactness")" "$e/stock-$kind.png" \
      -label "(c) cadlod, $(val faces "$e/cadlod.compactness")" "$e/cadlod-$kind.png" \
      -tile 3x1 -geometry 400x300+4+2 "${format[@]}"
  done
}

fig6_histogram() {
  local e="$1"
  gnuplot <<GP
set terminal pngcairo size 720,400 font "DejaVu Sans,10"
set output "$IMG/paper-fig6-compactness.png"
set title "Triangle compactness, shaft and its 90 % reductions"
set xlabel "compactness 4√3·A / (l0²+l1²+l2²)  (1 = equilateral)"
set ylabel "share of triangles"
set xrange [0:1]
set yrange [0:*]
set key right top
set style fill transparent solid 0.35 noborder
set boxwidth 0.05
plot "$e/original.hist" using 1:2 with boxes lc rgb "#606060" title "original", \
     "$e/stock.hist" using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb "#d04020" title "MeshLab QEM", \
     "$e/cadlod.hist" using 1:2 with linespoints lw 2 pt 5 ps 0.6 lc rgb "#2060c0" title "cadlod"
GP
}

# ---------------------------------------------------------------- experiment 2
experiment2() {
  local e="$WORK/exp2" k pct
  mkdir -p "$e"
  rm -f "$e"/level*.ply "$e"/level*.flt "$e/lodset.flt"
  say "experiment 2: the assembly at 0 $LEVELS %"
  mls -i "$ASSEMBLY" -o "$e/level0.ply" -m vn fc && [ -s "$e/level0.ply" ] || die "meshlabserver cannot read $ASSEMBLY"
  k=0
  for pct in $LEVELS; do
    k=$((k + 1))
    cadlod_simplify "$ASSEMBLY" "$e/level$k.ply" "$pct" "$e/level0.ply"
  done
  local n=$k
  LEVEL_ROUTE="$CAD_ROUTE"
  say "levels: $LEVEL_ROUTE"
  for k in $(seq 0 "$n"); do
    measure_mesh "$e/level$k.ply"
    mls -i "$e/level$k.ply" -o "$e/level$k.flt" && [ -s "$e/level$k.flt" ] ||
      die "cadlod's OpenFlight exporter failed on level $k"
  done
  whole_lod_set "$e"

  say "rendering the whole LOD set (camera path near to far)"
  measure_model "$e/lodset.flt" "$e/set" ""
  PATH_NEAR=$(val path_near "$e/set.run1")
  PATH_FAR=$(val path_far "$e/set.run1")
  for k in $(seq 0 "$n"); do
    say "rendering level $k alone"
    measure_model "$e/level$k.flt" "$e/level$k" "--near $PATH_NEAR --far $PATH_FAR"
  done
}

# The whole set as one .flt: the LOD-set filter, saved by cadlod's exporter; if that
# fails, the same builder core through paper_measure. Sets SET_ROUTE.
whole_lod_set() {
  local e="$1" failure=""
  if has_filter "$LOD_FILTER" && complete_mlx "$ROOT/bench/paper/lod_set_paper.mlx" "$WORK/lod_set_paper.mlx"; then
    mls -i "$ASSEMBLY" -s "$WORK/lod_set_paper.mlx" -o "$e/lodset.flt" -l 0 || true
    if [ -s "$e/lodset.flt" ]; then
      SET_ROUTE="MeshLab filter \"$LOD_FILTER\" (levels $LEVELS, other parameters default), saved by cadlod's OpenFlight exporter"
      return
    fi
    failure=$(awk -v start="$(grep -n -F -- "-s $WORK/lod_set_paper.mlx" "$WORK/meshlabserver.log" | tail -1 | cut -d: -f1)" \
      'NR > start && /cannot write|[Ff]ailed/ { print; exit }' "$WORK/meshlabserver.log")
  fi
  mkdir -p "$e/set-core"
  "$MEASURE" lodset "$e/level0.ply" "$e/set-core" "$LEVELS" >"$e/set-core/lodset.log" || die "LOD-set fallback failed"
  cp "$e/set-core/lodset.flt" "$e/lodset.flt"
  SET_ROUTE="cadlod's LOD-set builder core with its defaults (bench/paper/paper_measure), written by cadlod's OpenFlight core (one part per level), because ${failure:-the plugin has no \"$LOD_FILTER\"}"
}

# measure_model FILE PREFIX "EXTRA ARGS": PREFIX.load (median load s, MB), PREFIX.runN, PREFIX.fps
measure_model() {
  local file="$1" prefix="$2" extra="$3" i
  for i in $(seq 5); do
    "$RENDER" "$file" --no-render >"$prefix.load$i" 2>>"$WORK/render.log" || die "OpenSceneGraph cannot load $file"
  done
  for i in $(seq 5); do val load_seconds "$prefix.load$i"; done | median >"$prefix.load"
  for i in $(seq "$RUNS"); do
    # shellcheck disable=SC2086
    "$RENDER" "$file" --frames "$FRAMES" $extra >"$prefix.run$i" 2>>"$WORK/render.log" ||
      die "osg_render failed on $file"
  done
  for i in $(seq "$RUNS"); do val fps "$prefix.run$i"; done | median >"$prefix.fps"
  for i in $(seq "$RUNS"); do val fps_cpu "$prefix.run$i"; done | median >"$prefix.fpscpu"
}

# ---------------------------------------------------------------- report
PAPER_TRI=(47512 23189 8852 6189 4339 4672)
PAPER_FPS=(66 79 83 95 102 117)
PAPER_LOAD=(0.53 0.47 0.31 0.26 0.19 0.11)
PAPER_MB=(6.4 3.7 2.3 2.0 1.3 0.75)

compactness_row() {  # name file-prefix
  local c="$2.compactness"
  printf '| %s | %s | %s | %s | %s | %s | %s |' "$1" "$(val faces "$c")" "$(val zero_area_faces "$c")" \
    "$(val mean "$c")" "$(val p5 "$c")" \
    "$(awk -v v="$(val below01 "$c")" 'BEGIN { printf "%.2f %%", 100 * v }')" \
    "$(awk -v v="$(val below03 "$c")" 'BEGIN { printf "%.2f %%", 100 * v }')"
  if [ -f "$2.hausdorff" ]; then
    printf ' %s (%s %%) | %s (%s %%) |\n' "$(val max "$2.hausdorff")" "$(val max_pct_diag "$2.hausdorff")" \
      "$(val mean "$2.hausdorff")" "$(val mean_pct_diag "$2.hausdorff")"
  else
    printf ' – | – |\n'
  fi
}

# What share of the faces a method removed, against the 90 % asked for.
reduction_note() {  # name mesh-prefix original-prefix
  awk -v name="$1" -v f="$(val faces "$2.compactness")" -v f0="$(val faces "$3.compactness")" \
    'BEGIN { printf "%s removed %.1f %% of %d faces (%d left, target %d).", name, 100 * (1 - f / f0), f0, f, int(f0 / 10 + 0.5) }'
}

# One sentence comparing the two 90 % reductions.
fig6_summary() {
  local e="$1"
  awk -v cm="$(val mean "$e/cadlod.compactness")" -v sm="$(val mean "$e/stock.compactness")" \
      -v cs="$(val below01 "$e/cadlod.compactness")" -v ss="$(val below01 "$e/stock.compactness")" \
      -v ch="$(val max "$e/cadlod.hausdorff")" -v sh="$(val max "$e/stock.hausdorff")" \
      'BEGIN { printf "cadlod against MeshLab QEM: mean compactness %.3f against %.3f (x%.2f), slivers below 0.1 %.1f %% against %.1f %%, largest distance to the original %.3g against %.3g mm (x%.2f).", cm, sm, (sm > 0) ? cm / sm : 0, 100 * cs, 100 * ss, ch, sh, (sh > 0) ? ch / sh : 0 }'
}

table1() {
  local e="$WORK/exp2" k=0 pct t0 f0 c0 l0 s0
  t0=$(val faces "$e/level0.compactness"); f0=$(cat "$e/level0.fps"); c0=$(cat "$e/level0.fpscpu")
  l0=$(cat "$e/level0.load"); s0=$(stat -c %s "$e/level0.flt")
  echo "| reduction | triangles | .flt bytes | load s | fps | fps by CPU time | triangles ratio (paper) | fps ratio (paper) | fps-by-CPU ratio | load ratio (paper) | size ratio (paper) |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  for pct in 0 $LEVELS; do
    local t f c l s
    t=$(val faces "$e/level$k.compactness"); f=$(cat "$e/level$k.fps"); c=$(cat "$e/level$k.fpscpu")
    l=$(cat "$e/level$k.load"); s=$(stat -c %s "$e/level$k.flt")
    printf '| %s %% | %s | %s | %.4f | %.1f | %.1f | %s (%s) | %s (%s) | %s | %s (%s) | %s (%s) |\n' "$pct" "$t" "$s" "$l" "$f" "$c" \
      "$(ratio "$t" "$t0")" "$(ratio "${PAPER_TRI[$k]}" "${PAPER_TRI[0]}")" \
      "$(ratio "$f" "$f0")" "$(ratio "${PAPER_FPS[$k]}" "${PAPER_FPS[0]}")" "$(ratio "$c" "$c0")" \
      "$(ratio "$l" "$l0")" "$(ratio "${PAPER_LOAD[$k]}" "${PAPER_LOAD[0]}")" \
      "$(ratio "$s" "$s0")" "$(ratio "${PAPER_MB[$k]}" "${PAPER_MB[0]}")"
    k=$((k + 1))
  done
  local st sf sc sl ss
  st=$(awk '$1 == "level" { s += $4 } END { print s }' "$e/set.load1")
  sf=$(cat "$e/set.fps"); sc=$(cat "$e/set.fpscpu"); sl=$(cat "$e/set.load"); ss=$(stat -c %s "$e/lodset.flt")
  printf '| whole LOD set, switching | %s | %s | %.4f | %.1f | %.1f | %s | %s | %s | %s | %s |\n' "$st" "$ss" "$sl" "$sf" "$sc" \
    "$(ratio "$st" "$t0")" "$(ratio "$sf" "$f0")" "$(ratio "$sc" "$c0")" "$(ratio "$sl" "$l0")" "$(ratio "$ss" "$s0")"
}

lod_ranges() {
  local e="$WORK/exp2"
  echo "| level | triangles (as OpenSceneGraph draws them) | visible from | to | frames of the path |"
  echo "|---|---|---|---|---|"
  local k
  for k in $(awk '$1 == "level" { print $2 }' "$e/set.load1"); do
    awk -v k="$k" '$1 == "level" && $2 == k { printf "| %s | %s | %s | %s |", $2, $4, $6, $7 }' "$e/set.load1"
    awk -v k="$k" '$1 == "frames_at_level" && $2 == k { printf " %s |\n", $3 }' "$e/set.run1"
  done
}

# Where the set's levels switch, against the size of the model and the camera path.
set_note() {
  local e="$WORK/exp2"
  awk -v near="$PATH_NEAR" -v far="$PATH_FAR" '
    $1 == "level" { n++; last_out = $6 }
    $1 == "radius" { r = $2 }
    END { printf "The set has %d levels; the coarsest is shown from %g model units on (the bounding radius is %g, the camera path runs from %.0f to %.0f).", n, last_out, r, near, far }' \
    "$e/set.load1"
}

write_doc() {
  local e1="$WORK/exp1" e2="$WORK/exp2" cpu renderer
  cpu=$(awk -F: '/model name/ { sub(/^ +/, "", $2); print $2; exit }' /proc/cpuinfo)
  renderer=$(awk '$1 == "gl_renderer" { $1 = ""; sub(/^ /, ""); print; exit }' "$e2/set.run1")
  {
    cat <<EOF
# Reproducing the paper's experiments

Generated by \`scripts/reproduce_paper.sh\` on $(date -u +%Y-%m-%d) (do not edit: run the
script again). It repeats the two experiments of Tang et al., "Geometry Modeling For Virtual
Reality Based on CAD Data" (2015), §5, on the samples bundled in \`docs/sample/\`
(generated by \`scripts/make_sample_assembly.py\`), not on the paper's shaft and cockpit.

Machine: $(nproc) cores ($cpu), Debian 12, MeshLab 2020.09 (staged meshlabserver with
cadlod's plugins), OpenSceneGraph $(dpkg-query -W -f='${Version}' libopenscenegraph-dev 2>/dev/null) under Xvfb with
Mesa's software renderer (\`$renderer\`). Frame rates are software-rendering figures on a
machine shared with other jobs: compare the **ratios** against level 0 with the paper's, not
the absolute numbers (the paper used Vega Prime on a GPU).

## Experiment 1 (Fig. 6): QEM vs the compactness-aware QEM, shaft reduced by 90 %

Input \`docs/sample/shaft.wrl\` as cadlod's importer reads it; both methods are asked to
remove 90 % of its faces: MeshLab's stock "$STOCK_FILTER" with its defaults and
TargetPerc = 0.1; cadlod: $CAD_ROUTE.
Pictures: OpenSceneGraph, per-vertex normals recomputed with a 30° crease angle for all
three meshes, one matte material; the wireframe is a close-up of the step from the 14 mm
to the 18 mm section.

![shaded](img/paper-fig6-shaded.png)

![wireframe](img/paper-fig6-wire.png)

| mesh | triangles | of which zero-area | compactness mean | p5 | below 0.1 | below 0.3 | Hausdorff max to the original (% diag) | mean (% diag) |
|---|---|---|---|---|---|---|---|---|
$(compactness_row original "$e1/original")
$(compactness_row "MeshLab QEM" "$e1/stock")
$(compactness_row cadlod "$e1/cadlod")

$(reduction_note "MeshLab QEM" "$e1/stock" "$e1/original")
$(reduction_note cadlod "$e1/cadlod" "$e1/original")
$(fig6_summary "$e1")

Compactness is Guéziec's 4√3·A/(l0²+l1²+l2²) (1 = equilateral); the Hausdorff distance is
symmetric, sampled on every vertex plus as many area-uniform points per side as the input
has faces (\`filter_cadlod/core/hausdorff.h\`), in model units (mm), as a share of the
bounding-box diagonal in brackets.

![compactness histogram](img/paper-fig6-compactness.png)

## Experiment 2 (Table 1): the assembly at 0/50/60/70/80/90 % reduction

Input \`docs/sample/cad_assembly.wrl.gz\` (level 0). Each level is made from the original at
its reduction by $LEVEL_ROUTE, and written alone as its own \`.flt\` by cadlod's OpenFlight
exporter (meshlabserver, PLY to \`.flt\`; parts become Objects by face color). The whole LOD
set: $SET_ROUTE.
Load time: OpenSceneGraph \`readNodeFile\` wall clock (plugin preloaded), median of 5 fresh
processes. Frame rate: \`osg_render\`, ${FRAMES} frames in a 640×480 window along one orbit whose
distance grows geometrically from $(printf %.0f "$PATH_NEAR") to $(printf %.0f "$PATH_FAR") model units (the whole
set's levels seen along it are listed below), the same path for every file, median of $RUNS runs;
"fps by CPU time" divides the frames by the CPU time of the rendering process (Mesa draws in
its threads), which a busy machine disturbs less than the wall clock. Triangles are the faces
of each level's mesh; the whole set's are those of all its levels.
Ratios are against level 0; the paper's ratios are in brackets (paper Table 1: triangles
47512/23189/8852/6189/4339/4672, fps 66/79/83/95/102/117, load 0.53/0.47/0.31/0.26/0.19/0.11 s,
6.4/3.7/2.3/2.0/1.3/0.75 MB).

$(table1)

LOD ranges of the whole set as OpenSceneGraph reads them, and how many frames of the camera
path each level was the visible one:

$(lod_ranges)

$(set_note)

## Notes

- The paper's numbers come from Vega Prime on a GPU with its own assembly; these come from
  OpenSceneGraph on Mesa's software renderer with a generated sample, so only the direction
  and rough size of the ratios can be compared. A software renderer spends most of a frame
  on vertices, so its frame rate follows the triangle count more closely than a GPU's.
- Load times of files this small are a few milliseconds; they are medians of fresh
  processes with the file in the page cache.
- The whole-set row is not in the paper: it is the single \`.flt\` a simulator would load,
  with the switch distances the LOD-set filter derived from each level's error (1 pixel at
  1080 pixels and 45°, its defaults).
- Tools: \`bench/paper/osg_render\` (load, memory, frame rate along the path, \`--level K\` to
  show one level of a set, \`--shot\` pictures) and \`bench/paper/paper_measure\` (compactness,
  Hausdorff distance, and core fallbacks when a filter is missing from the plugin).

## Reproduce

\`\`\`
CADLOD_BENCH_DEPS=1 bash scripts/bootstrap.sh   # gnuplot-nox, among others
scripts/reproduce_paper.sh                       # CADLOD_BUILD_DIR, PAPER_FRAMES, PAPER_RUNS
\`\`\`
Intermediate files (meshes, .flt, raw outputs, logs) stay in \`\$CADLOD_BUILD_DIR/paper-reproduction/\`.
EOF
  } >"$DOC"
}

main() {
  mkdir -p "$WORK" "$IMG"
  : >"$WORK/meshlabserver.log"
  : >"$WORK/render.log"
  build_tools
  start_xvfb
  timeout 120 "$MLS" -d "$WORK/filters.txt" >/dev/null 2>&1 || true
  [ -s "$WORK/filters.txt" ] || die "meshlabserver cannot list its filters (see $WORK/filters.txt)"
  experiment1
  experiment2
  write_doc
  say "wrote $DOC and $IMG/paper-fig6-*.png"
}

main "$@"
