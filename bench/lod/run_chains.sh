#!/usr/bin/env bash
# Builds chain_bench (build-bench/) and runs it on the demo assembly, the generated bench
# assembly and board, the KiCad VRML exports of the CAD corpus (made by
# scripts/make_cad_corpus.sh when missing) and a populated board of 70 of them (177 parts,
# 298k triangles: bench/lod/make_board.py) and, from ../shared/corpus, an office with
# thousands of non-manifold edges; writes the table and one plot of triangles
# against distance per mesh (gnuplot, both chains).
# With --verify, each of cadlod's levels is also measured again independently (other
# random points, 20 per input face and at least a million per side): OUTDIR/verify.md gives
# the worst projected error found that way per mesh (about a quarter of an hour).
#   bench/lod/run_chains.sh [OUTDIR] [--verify]        (default out/chains)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="${1:-$ROOT/out/chains}"
mkdir -p "$out"
corpus="$ROOT/.cache/cad-corpus"
[ -f "$corpus/manifest.txt" ] || bash "$ROOT/scripts/make_cad_corpus.sh" "$corpus"
build="${CADLOD_BENCH_BUILD_DIR:-$ROOT/build-bench}"
cmake -S "$ROOT" -B "$build" -G Ninja -DCADLOD_BUILD_BENCH=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j 2 --target chain_bench
mapfile -t wrl < <(find "$corpus" -name '*.wrl' | sort)
python3 "$ROOT/bench/lod/make_board.py" "$corpus/wrl" 70 "$out/board70.wrl"
wrl+=("$out/board70.wrl")
# A third-party model with 2 494 non-manifold edges (an office modelled by hand), when the
# shared corpus is beside the project.
office="$ROOT/../shared/corpus/castle-demo-models/lights_materials/raytracer/office.wrl"
[ -f "$office" ] && wrl+=("$office")
{
  echo "Command: bench/lod/run_chains.sh; cadlod at $(git -C "$ROOT" rev-parse --short HEAD), $(date -u +%Y-%m-%d)."
  echo
  "$build/bench/lod/chain_bench" --assembly-segments 256 --plot "$out" \
    "$ROOT/docs/sample/cad_assembly.wrl.gz" "${wrl[@]}"
} | tee "$out/chains.md"
bash "$ROOT/bench/lod/plot_chains.sh" "$out"
if [ "${2:-}" = "--verify" ]; then
  "$build/bench/lod/chain_bench" --no-meshopt --verify --assembly-segments 256 \
    "$ROOT/docs/sample/cad_assembly.wrl.gz" "${wrl[@]}" | tee "$out/verify.md"
fi
