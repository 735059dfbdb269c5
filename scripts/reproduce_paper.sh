#!/usr/bin/env bash
# Reproduces the two experiments of the paper (Tang et al. 2015, §5) on the bundled samples
# and regenerates docs/paper-reproduction.md with its pictures (docs/img/paper-*.png):
#  - Experiment 1 (Fig. 6): docs/sample/shaft.wrl reduced by 90 % with MeshLab's stock
#    "Quadric Edge Collapse Decimation" (defaults) and with cadlod's CAD Quadric Edge
#    Collapse (defaults): shaded and wireframe pictures, compactness histograms and
#    numbers, symmetric Hausdorff distance to the original, and the shading-error measure
#    (bench/shading) with its difference images.
#  - Experiment 2 (Table 1): docs/sample/cad_assembly.wrl.gz at 0/50/60/70/80/90 %
#    reduction: triangles, .flt size, OpenSceneGraph load time and frame rate of every level
#    alone, as ratios against level 0 next to the paper's; then two whole LOD sets, the
#    paper's list and the screen-space chain, along one camera path that backs away across
#    every switch distance: triangles drawn per frame and per level (bench/lod_path) and
#    frame rate.
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
  say "configuring and building in $BUILD (stage, osg_render, paper_measure, shading_compare, cadlod_mlx_complete)"
  cmake -S "$ROOT" -B "$BUILD" "${generator[@]}" -DCADLOD_BUILD_BENCH=ON -DCADLOD_BUILD_TESTS=ON \
    >"$WORK/build.log" 2>&1 || die "cmake configure failed, see $WORK/build.log"
  cmake --build "$BUILD" --target stage osg_render paper_measure shading_compare cadlod_mlx_complete -j2 >>"$WORK/build.log" 2>&1 ||
    die "build failed, see $WORK/build.log"
  MLS="$BUILD/stage/bin/meshlabserver"
  MLX_COMPLETE="$(find "$BUILD/tests" -name cadlod_mlx_complete -type f -perm -u+x | head -1)"
  [ -n "$MLX_COMPLETE" ] || die "cadlod_mlx_complete was not built"
  RENDER="$BUILD/bench/paper/osg_render"
  MEASURE="$BUILD/bench/paper/paper_measure"
  SHADING="$BUILD/bench/shading/shading_compare"
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
share() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f %%", (b > 0) ? 100 * a / b : 0 }'; }

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
  fig6_shading "$e"
}

# The shading-error measure (docs/shading_measure.md) of both reductions against the
# original, and their difference images: the difference panel of each of the 12 views.
fig6_shading() {
  local e="$1" m v
  for m in stock cadlod; do
    rm -f "$e/shading-$m-"view*.png
    "$SHADING" "$e/original.ply" "$e/$m.ply" --images "$e/shading-$m-" >"$e/$m.shading" ||
      die "shading_compare failed on $m"
    for v in "$e/shading-$m-"view*.png; do
      convert "$v" -crop 256x256+512+0 +repage "${v%.png}-diff.png"
    done
  done
  for m in stock cadlod; do
    montage "$e/shading-$m-"view*-diff.png -tile 6x2 -geometry 256x256+1+1 -background '#404040' \
      -depth 8 "$IMG/paper-fig6-shading-$m.png"
  done
  montage -font DejaVu-Sans -pointsize 14 -background white \
    -label "MeshLab QEM: $(shading_figures "$e/stock.shading")" "$e/shading-stock-view00.png" \
    -label "cadlod: $(shading_figures "$e/cadlod.shading")" "$e/shading-cadlod-view00.png" \
    -tile 1x2 -geometry +2+4 "$e/shading-view00.png"
  convert "$e/shading-view00.png" -depth 8 "$IMG/paper-fig6-shading-view00.png"
}

# shading_figures FILE: "V % visible, mean |ΔI| M" from shading_compare's summary line
shading_figures() {
  printf '%s %%%% of pixels differ visibly, mean |ΔI| %s' "$(shading_value visible "$1")" "$(shading_value mean "$1")"
}

# shading_value visible|silhouette|mean FILE: one figure of shading_compare's summary line
# ("visible difference V % of covered pixels (silhouette S %), mean |dI| M; ...")
shading_value() {
  awk -v what="$1" '/^visible difference/ {
      line = $0
      if (what == "visible") { sub(/^visible difference /, "", line); sub(/ %.*/, "", line) }
      if (what == "silhouette") { sub(/.*\(silhouette /, "", line); sub(/ %.*/, "", line) }
      if (what == "mean") { sub(/.*mean \|dI\| /, "", line); sub(/;.*/, "", line) }
      print line; exit }' "$2"
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
  local e="$WORK/exp2" k pct set
  mkdir -p "$e"
  rm -f "$e"/level*.ply "$e"/level*.flt "$e"/paper.flt "$e"/chain.flt
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
  paper_lod_set "$e"
  chain_lod_set "$e"
  common_path "$e"
  for set in paper chain; do
    say "rendering the $set LOD set along the path"
    measure_model "$e/$set.flt" "$e/$set" "--near $PATH_NEAR --far $PATH_FAR"
  done
  for k in $(seq 0 "$n"); do
    say "rendering level $k alone"
    measure_model "$e/level$k.flt" "$e/level$k" "--near $PATH_NEAR --far $PATH_FAR"
  done
}

# lod_set_filter MLX OUT: the LOD-set filter run by the script MLX on the assembly, all
# its levels saved as one .flt by cadlod's OpenFlight exporter; false (with the reason in
# FAILURE) when that does not work.
lod_set_filter() {
  local mlx="$1" out="$2" completed="$WORK/$(basename "$1")"
  FAILURE="the plugin has no \"$LOD_FILTER\""
  has_filter "$LOD_FILTER" && complete_mlx "$mlx" "$completed" || return 1
  mls -i "$ASSEMBLY" -s "$completed" -o "$out" -l 0 || true
  [ -s "$out" ] && return 0
  FAILURE=$(awk -v start="$(grep -n -F -- "-s $completed" "$WORK/meshlabserver.log" | tail -1 | cut -d: -f1)" \
    'NR > start && /cannot write|[Ff]ailed/ { print; exit }' "$WORK/meshlabserver.log")
  return 1
}

# The paper's list as one .flt: the LOD-set filter with levelMode 1; if that fails, the
# same builder core through paper_measure. Sets PAPER_SET_ROUTE.
paper_lod_set() {
  local e="$1"
  if lod_set_filter "$ROOT/bench/paper/lod_set_paper.mlx" "$e/paper.flt"; then
    PAPER_SET_ROUTE="MeshLab filter \"$LOD_FILTER\" with the level list $LEVELS (levelMode 1, other parameters default)"
    return
  fi
  mkdir -p "$e/set-core"
  "$MEASURE" lodset "$e/level0.ply" "$e/set-core" "$LEVELS" >"$e/set-core/lodset.log" || die "LOD-set fallback failed"
  cp "$e/set-core/lodset.flt" "$e/paper.flt"
  PAPER_SET_ROUTE="cadlod's LOD-set builder core with the levels $LEVELS (bench/paper/paper_measure), written by cadlod's OpenFlight core (one part per level), because ${FAILURE:-the filter failed}"
}

# The screen-space chain, the LOD-set filter's default. Sets CHAIN_SET_ROUTE.
chain_lod_set() {
  lod_set_filter "$ROOT/bench/paper/lod_set_chain.mlx" "$1/chain.flt" ||
    die "the LOD-set filter's screen-space chain failed: $FAILURE"
  CHAIN_SET_ROUTE="MeshLab filter \"$LOD_FILTER\" with its defaults (screen-space chain: 1 px of measured error at 1080 px and 45°, distance ratio 2)"
}

# One camera path for every file: the union of the two sets' own paths over all their
# levels (osg_render's default), so that both are measured on the same frames.
common_path() {
  local e="$1" set
  for set in paper chain; do
    "$RENDER" "$e/$set.flt" --no-render --frames "$FRAMES" >"$e/$set.path" 2>>"$WORK/render.log" ||
      die "OpenSceneGraph cannot load $e/$set.flt"
  done
  PATH_NEAR=$(awk '$1 == "path_near" { print $2 }' "$e/paper.path" "$e/chain.path" | sort -g | head -1)
  PATH_FAR=$(awk '$1 == "path_far" { print $2 }' "$e/paper.path" "$e/chain.path" | sort -g | tail -1)
  say "camera path from $PATH_NEAR to $PATH_FAR model units"
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
}

# Fig. 6 shading: the measure beside compactness and Hausdorff, per mesh.
shading_row() {  # name file-prefix
  printf '| %s | %s | %s %% | %s %% | %s | %s %% | %s |\n' "$1" "$(val faces "$2.compactness")" \
    "$(shading_value visible "$2.shading")" "$(shading_value silhouette "$2.shading")" "$(shading_value mean "$2.shading")" \
    "$(val max_pct_diag "$2.hausdorff")" "$(val mean "$2.compactness")"
}

# The visible share of every view, both reductions side by side.
shading_views() {
  local e="$WORK/exp1"
  echo "| view | 0 | 1 | 2 | 3 | 4 | 5 | 6 | 7 | 8 | 9 | 10 | 11 |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  local m name
  for m in stock cadlod; do
    name="MeshLab QEM"; [ "$m" = cadlod ] && name=cadlod
    awk -v name="$name" '$1 ~ /^[0-9]+$/ && NF == 6 { row = row sprintf(" %.2f |", $5) } END { printf "| %s, visible %% |%s\n", name, row }' "$e/$m.shading"
  done
}

# A model along the common path: triangles in the file, mean drawn per frame, frame rate.
path_row() {  # name prefix file levels
  local t0 o0 f0 c0
  t0=$(val path_mean_triangles "$WORK/exp2/level0.run1"); f0=$(cat "$WORK/exp2/level0.fps"); c0=$(cat "$WORK/exp2/level0.fpscpu")
  o0=$(val path_outside_mean_triangles "$WORK/exp2/level0.run1")
  printf '| %s | %s | %s | %s | %s | %s | %s | %.1f | %.1f | %s | %s |\n' "$1" "$4" "$(val triangles "$2.run1")" \
    "$(val path_mean_triangles "$2.run1")" "$(share "$(val path_mean_triangles "$2.run1")" "$t0")" \
    "$(val path_outside_mean_triangles "$2.run1")" "$(share "$(val path_outside_mean_triangles "$2.run1")" "$o0")" \
    "$(cat "$2.fps")" "$(cat "$2.fpscpu")" "$(ratio "$(cat "$2.fps")" "$f0")" "$(ratio "$(cat "$2.fpscpu")" "$c0")"
}

path_table() {
  local e="$WORK/exp2"
  echo "| model | LOD levels | triangles in the file | mean triangles drawn per frame | share of level 0 alone | the same, camera outside the bounding sphere | share | fps | fps by CPU time | fps ratio | fps-by-CPU ratio |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
  path_row "level 0 alone (no LOD)" "$e/level0" "$e/level0.flt" "–"
  path_row "the paper's list ($LEVELS %)" "$e/paper" "$e/paper.flt" "$(val lod_levels "$e/paper.run1")"
  path_row "screen-space chain (default)" "$e/chain" "$e/chain.flt" "$(val lod_levels "$e/chain.run1")"
}

# Every level of a set: its range, and the frames of the path that drew it.
set_levels() {  # prefix
  echo "| level | triangles | drawn from | to (mm) | frames of the path that drew it | first–last frame | camera distance of those frames (mm) |"
  echo "|---|---|---|---|---|---|---|"
  awk '$1 == "level" { tri[$2] = $4; from[$2] = $6; to[$2] = $7; n = $2 + 1 }
       $1 == "path_level" { frames[$2] = $4; first[$2] = $6; last[$2] = $8; d0[$2] = $10; d1[$2] = $12 }
       END { for (k = 0; k < n; k++)
               printf "| %d | %s | %.4g | %s | %d | %s | %s |\n", k, tri[k], from[k], (to[k] + 0 >= 1e29) ? "never" : sprintf("%.4g", to[k]),
                 frames[k], frames[k] ? first[k] "–" last[k] : "–", frames[k] ? sprintf("%.4g – %.4g", d0[k], d1[k]) : "–" }' "$1.run1"
}

# Where the path runs, against the size of the model and the first switch of each set.
path_note() {
  local e="$WORK/exp2"
  awk -v near="$PATH_NEAR" -v far="$PATH_FAR" -v frames="$FRAMES" '
    $1 == "radius" { r = $2 }
    $1 == "level" && $2 == 1 { first[FILENAME ~ /chain/ ? "chain" : "paper"] = $6 }
    END { printf "The path: %d frames; the camera orbits the assembly once while it backs away, log-spaced, from %.3g mm to %.4g mm from the centre. The bounding radius is %.4g mm: the whole assembly fills the 45° view from %.3g mm. The path starts closer, at half the first switch distance, because both sets switch level 0 out already at %.3g mm (the paper'"'"'s list) and %.3g mm (the chain), inside the assembly. It ends 1.25 times beyond the last switch between levels of either set.", frames, near, far, r, r / 0.41421356, first["paper"], first["chain"] }' \
    "$e/paper.run1" "$e/chain.run1"
}

write_doc() {
  local e1="$WORK/exp1" e2="$WORK/exp2" cpu renderer
  cpu=$(awk -F: '/model name/ { sub(/^ +/, "", $2); print $2; exit }' /proc/cpuinfo)
  renderer=$(awk '$1 == "gl_renderer" { $1 = ""; sub(/^ /, ""); print; exit }' "$e2/chain.run1")
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
has faces (\`lib/measure/hausdorff.h\`), in model units (mm), as a share of the
bounding-box diagonal in brackets.

![compactness histogram](img/paper-fig6-compactness.png)

### Shading, as a viewer sees it

The paper's claim for Fig. 6 is about lighting uniformity and visual effect. Measured with
cadlod's shading-error measure (\`bench/shading\`, \`shading_compare\`, described in
[shading_measure.md](shading_measure.md)): both results and the original rendered the same way
from 12 directions on a sphere (orthographic, framing the original's bounding sphere, 256×256
pixels each), per-pixel shading of area-weighted vertex normals split at 30° creases, computed
the same way for all three meshes. A pixel differs visibly when its intensity is off by more
than 8/255 or only one of the two images covers it (silhouette); below about 0.2 % of the
pixels nobody sees a difference. Mean |ΔI| is on the 0–255 scale over the pixels either image
covers.

| mesh | triangles | visible shading difference (% of covered pixels) | of which silhouette | mean \|ΔI\| | Hausdorff max (% diag) | compactness mean |
|---|---|---|---|---|---|---|
$(shading_row "MeshLab QEM" "$e1/stock")
$(shading_row cadlod "$e1/cadlod")

Per view (the share of covered pixels that differ visibly, %):

$(shading_views)

The first view, original | result | difference, for both (difference: red where only one
image covers the pixel, yellow where the intensity differs visibly, grey below the threshold,
brighter with |ΔI|):

![shading difference, view 0](img/paper-fig6-shading-view00.png)

The difference images of all 12 views (full size, views 0–5 above 6–11), MeshLab QEM:

![shading difference of MeshLab QEM, 12 views](img/paper-fig6-shading-stock.png)

cadlod:

![shading difference of cadlod, 12 views](img/paper-fig6-shading-cadlod.png)

## Experiment 2 (Table 1): the assembly at 0/50/60/70/80/90 % reduction

Input \`docs/sample/cad_assembly.wrl.gz\` (level 0, in millimetres). Each level is made from the
original at its reduction by $LEVEL_ROUTE, and written alone as its own \`.flt\` by cadlod's
OpenFlight exporter (meshlabserver, PLY to \`.flt\`; parts become Objects by face color).
Load time: OpenSceneGraph \`readNodeFile\` wall clock (plugin preloaded), median of 5 fresh
processes. Frame rate: \`osg_render\`, ${FRAMES} frames in a 640×480 window along the camera path
below (the same for every file), median of $RUNS runs; "fps by CPU time" divides the frames by
the CPU time of the rendering process (Mesa draws in its threads), which a busy machine
disturbs less than the wall clock. Triangles are the faces of each level's mesh.
Ratios are against level 0; the paper's ratios are in brackets (paper Table 1: triangles
47512/23189/8852/6189/4339/4672, fps 66/79/83/95/102/117, load 0.53/0.47/0.31/0.26/0.19/0.11 s,
6.4/3.7/2.3/2.0/1.3/0.75 MB).

$(table1)

### The LOD sets along a camera path over every level

A simulator loads one \`.flt\` with all levels and lets its LOD nodes pick one by the
distance. Two sets of the same assembly:

- **the paper's list**: $PAPER_SET_ROUTE;
- **the screen-space chain**: $CHAIN_SET_ROUTE.

Both keep the file's millimetres; \`cadlod convert docs/sample/cad_assembly.wrl.gz --lod auto\`
(or \`--lod "$LEVELS"\`) without \`--unit\` gives the same levels. With \`--unit mm\` the
command scales to metres in the importer, before simplifying, and its chain differs a little
(the README says why).

$(path_note)

Triangles drawn are those the LOD nodes select in each frame: \`bench/lod_path\` walks the
scene from the frame's eye with OpenSceneGraph's own \`osg::LOD\` selection (as the viewer's
cull does, LOD scale 1) and counts the triangles under the chosen children; view-frustum
culling is not applied, so a frame counts every triangle selected, in view or not
(\`tests/openflight/test_lod_path.cpp\` checks it on a three-level \`.flt\` with known ranges).
They do not depend on the machine; the frame rates do. Ratios are against level 0 alone on
the same path. "Camera outside the bounding sphere" keeps only the $(val path_outside_frames "$e2/chain.run1") frames from
$(printf %.0f "$(val radius "$e2/chain.run1")") mm out, what a viewer who is not inside the assembly gets.

$(path_table)

The paper's list, level by level (\`.flt\` ranges as OpenSceneGraph reads them, in mm):

$(set_levels "$e2/paper")

The screen-space chain, level by level:

$(set_levels "$e2/chain")

## Notes

- The paper's numbers come from Vega Prime on a GPU with its own assembly; these come from
  OpenSceneGraph on Mesa's software renderer with a generated sample, so only the direction
  and rough size of the ratios can be compared. A software renderer spends most of a frame
  on vertices, so its frame rate follows the triangle count more closely than a GPU's.
- Load times of files this small are a few milliseconds; they are medians of fresh
  processes with the file in the page cache.
- The path rows are not in the paper (it gives each level alone). Both sets switch from
  each level's measured error at 1 pixel, 1080 pixels and 45°; the paper's list spends its
  levels within a few centimetres of the centre, where a viewer is inside the assembly,
  and draws its 90 % level from there on until the assembly is about one pixel high. The camera
  backs away log-spaced, so each factor of distance gets the same number of frames: the
  mean triangles per frame weigh every distance band alike, not the time a viewer spends in it.
- Frame rate under Xvfb and Mesa's llvmpipe on 2 shared cores is what it is: it includes
  the software rasteriser's per-pixel cost, which is the same for every level when the
  assembly fills the window; the triangle counts are the robust figure.
- Tools: \`bench/paper/osg_render\` (load, memory, frame rate and triangles drawn along the
  path, \`--level K\` to show one level of a set, \`--shot\` pictures), \`bench/paper/paper_measure\`
  (compactness, Hausdorff distance, and core fallbacks when a filter is missing from the
  plugin) and \`bench/shading/shading_compare\` (the shading-error measure).

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
