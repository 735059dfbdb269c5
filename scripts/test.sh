#!/usr/bin/env bash
# Builds cadlod and runs every test: unit tests and end-to-end tests through the staged
# meshlabserver. Installs what it needs first (scripts/bootstrap.sh, idempotent).
#   scripts/test.sh              RelWithDebInfo build in build/
#   scripts/test.sh --sanitize   ASan+UBSan build in build-asan/
# Extra arguments after -- go to ctest (e.g. -- -R Compactness).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

sanitize=0
ctest_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --sanitize) sanitize=1 ;;
    --) shift; ctest_args=("$@"); break ;;
    *) echo "usage: scripts/test.sh [--sanitize] [-- ctest args]" >&2; exit 2 ;;
  esac
  shift
done

bash "$ROOT/scripts/bootstrap.sh"

if [ "$sanitize" = 1 ]; then
  build="${CADLOD_BUILD_DIR:-$ROOT/build-asan}"
  cmake_flags=(-DCADLOD_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo)
  # MeshLab's own libraries are not instrumented: ASan must be preloaded for meshlabserver.
  export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1"
else
  build="${CADLOD_BUILD_DIR:-$ROOT/build}"
  cmake_flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
fi

echo "== configure ($build)"
cmake -S "$ROOT" -B "$build" -G Ninja "${cmake_flags[@]}" >/dev/null
echo "== build"
cmake --build "$build" -j "$(nproc)"
echo "== test"
ctest --test-dir "$build" --output-on-failure -j 2 --timeout 900 "${ctest_args[@]}"
