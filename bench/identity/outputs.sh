#!/usr/bin/env bash
# Every output issue 62 holds byte-identical across a restructure, made with the binaries of
# one build dir (configured with -DCADLOD_BUILD_BENCH=ON, targets cadlod corpus_bench
# chain_bench stage):
#   bench/identity/outputs.sh [--quick] [--no-bench] [--corpus DIR] BUILD_DIR OUT_DIR
# --no-bench: only the conversions and the .mlx route (a build without the bench targets).
# --quick: the corpus bench's --quick subset (6 parts, 75/95 %) and the chain bench on the
# demo, the bench assembly/board and three corpus VRML parts, instead of everything.
# Inputs are copied from this checkout into OUT_DIR/inputs and every command runs in OUT_DIR
# with relative paths, so two builds see the same files under the same names (the reports
# carry the paths). Compare two OUT_DIRs with bench/identity/compare.sh. CADLOD_CONVERT_ARGS
# adds options to every `cadlod convert` (e.g. "--instances expand" to compare a build that
# keeps instances with one from before them).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
quick=0 bench=1
corpus="${CADLOD_CORPUS:-$ROOT/.cache/cad-corpus}"
while [ $# -gt 2 ]; do
  case "$1" in
    --quick) quick=1; shift ;;
    --no-bench) bench=0; shift ;;
    --corpus) corpus="$2"; shift 2 ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
  esac
done
[ $# -eq 2 ] || { echo "usage: $0 [--quick] [--no-bench] [--corpus DIR] BUILD_DIR OUT_DIR" >&2; exit 2; }
build="$(realpath "$1")"
out="$2"
corpus="$(realpath "$corpus")"
[ -f "$corpus/manifest.txt" ] || bash "$ROOT/scripts/make_cad_corpus.sh" "$corpus"
exes=(cli/cadlod stage/bin/meshlabserver)
[ "$bench" = 1 ] && exes+=(bench/simplify/corpus_bench bench/lod/chain_bench)
for exe in "${exes[@]}"; do
  [ -x "$build/$exe" ] || { echo "missing $build/$exe (build cadlod corpus_bench chain_bench stage)" >&2; exit 1; }
done
mkdir -p "$out/inputs" "$out/chains"
cd "$out"
cp "$ROOT/docs/sample/cad_assembly.wrl.gz" "$ROOT/docs/sample/shaft.wrl" "$corpus/wrl/relay_fujitsu.wrl" \
   "$ROOT"/docs/examples/*.mlx inputs/
cadlod="$build/cli/cadlod"
step() { printf '== %-8s %s\n' "$1" "$(date -u +%T)"; }
exec 3>&1  # the timings go here, past the commands' redirections to their logs
timed() { local t0=$SECONDS; "$@"; echo "   $(( SECONDS - t0 )) s" >&3; }
read -r -a convert_args <<< "${CADLOD_CONVERT_ARGS:-}"

step convert
# The demo as scripts/demo.sh runs it, then convert --report on three inputs.
timed env -u DISPLAY "$cadlod" convert "${convert_args[@]}" inputs/cad_assembly.wrl.gz -o demo.flt --unit mm --report demo.json -q --force > demo.log 2>&1
timed env -u DISPLAY "$cadlod" convert "${convert_args[@]}" inputs/cad_assembly.wrl.gz -o paper.flt --unit mm --lod "50 60 70 80 90" \
  --report paper.json -q --force > paper.log 2>&1
timed env -u DISPLAY "$cadlod" convert "${convert_args[@]}" inputs/shaft.wrl -o shaft.flt --report shaft.json -q --force > shaft.log 2>&1
timed env -u DISPLAY "$cadlod" convert "${convert_args[@]}" inputs/relay_fujitsu.wrl -o relay.flt --unit mm --report relay.json -q --force \
  > relay.log 2>&1

step mlx
# The .mlx route: the staged meshlabserver with this build's plugins.
for mlx in inputs/*.mlx; do
  name="$(basename "$mlx" .mlx)"
  input=inputs/shaft.wrl
  [ "$name" = cad_mm_to_flt ] && input=inputs/cad_assembly.wrl.gz
  timed env QT_LOGGING_RULES='*.debug=false' timeout 1200 xvfb-run -a "$build/stage/bin/meshlabserver" \
    -i "$input" -s "$mlx" -o "mlx_$name.flt" > "mlx_$name.log" 2>&1
done

[ "$bench" = 1 ] || { step done; exit 0; }
step chains
wrl=(inputs/cad_assembly.wrl.gz)
if [ "$quick" = 1 ]; then
  wrl+=("$corpus/wrl/relay_fujitsu.wrl" "$corpus/wrl/lqfp64.wrl" "$corpus/wrl/buzzer_12mm.wrl")
else
  mapfile -t -O 1 wrl < <(find "$corpus/wrl" -name '*.wrl' | sort)
fi
timed "$build/bench/lod/chain_bench" --assembly-segments 256 --levels --plot chains "${wrl[@]}" > chains.md 2> chains.log

step corpus
# cadlod's rows only (no peers): --tools cadlod; --raw holds every row's figures.
args=(--corpus "$corpus" --tools cadlod --raw corpus.raw.md)
[ "$quick" = 1 ] && args+=(--quick)
timed "$build/bench/simplify/corpus_bench" "${args[@]}" > corpus.md 2> corpus.log
step done
