#!/usr/bin/env bash
# Builds the bench (build-bench/) and runs corpus_bench on the CAD corpus, making the corpus
# first when it is missing (scripts/make_cad_corpus.sh).
#   bench/simplify/run_corpus.sh [OUT.md] [corpus_bench options...]
#   bench/simplify/run_corpus.sh out/corpus_quick.md --quick      # tuning loop, a few minutes
# Writes the per-reduction tables to OUT.md (default out/corpus_bench.md) and every tool's
# rows to OUT.raw.md.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="${1:-$ROOT/out/corpus_bench.md}"
[ $# -gt 0 ] && shift
mkdir -p "$(dirname "$out")"
corpus="$ROOT/.cache/cad-corpus"
if [ ! -f "$corpus/manifest.txt" ]; then
  bash "$ROOT/scripts/make_cad_corpus.sh" "$corpus"
fi
build="${CADLOD_BENCH_BUILD_DIR:-$ROOT/build-bench}"
cmake -S "$ROOT" -B "$build" -G Ninja -DCADLOD_BUILD_BENCH=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" -j 2 --target corpus_bench
start=$(date +%s)
{
  echo "Command: bench/simplify/run_corpus.sh $(basename "$out") $*"
  echo "Simplifier at $(git -C "$ROOT" rev-parse --short HEAD)$(git -C "$ROOT" diff --quiet HEAD -- filter_cadlod || echo ' (modified)'), $(date -u +%Y-%m-%d)."
  echo
  "$build/bench/simplify/corpus_bench" --corpus "$corpus" --raw "${out%.md}.raw.md" "$@"
} > "$out"
echo "== $out ($(( $(date +%s) - start )) s)"
