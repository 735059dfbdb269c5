#!/usr/bin/env bash
# Builds two revisions and checks that their outputs are byte-identical (timing aside):
#   bench/identity/check.sh [--quick] OLD_REV [NEW_REV]      (NEW_REV default HEAD)
# Each revision gets a detached worktree and a build dir outside the repo, under
# $CADLOD_IDENTITY_DIR (default ../identity-check beside the repo): WORKTREE/<sha>/ and
# WORKTREE/<sha>/build-identity/, kept and reused by the next run (ccache, CCACHE_BASEDIR
# = the parent of the repo). OLD_BUILD=DIR / NEW_BUILD=DIR use a build dir that exists instead.
# The outputs go to $CADLOD_IDENTITY_DIR/out-<sha>; the result table to stdout.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
opts=()
[ "${1:-}" = --quick ] && { opts+=(--quick); shift; }
[ $# -ge 1 ] || { echo "usage: $0 [--quick] OLD_REV [NEW_REV]" >&2; exit 2; }
work="${CADLOD_IDENTITY_DIR:-$(dirname "$ROOT")/identity-check}"
mkdir -p "$work"; work="$(cd "$work" && pwd)"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$(dirname "$ROOT")}"

build_rev() {  # REV [PREBUILT_DIR] -> prints the build dir
  local sha tree build
  sha="$(git -C "$ROOT" rev-parse --short=9 "$1^{commit}")"
  if [ -n "${2:-}" ]; then echo "$2"; return; fi
  tree="$work/$sha"
  [ -d "$tree" ] || git -C "$ROOT" worktree add --detach "$tree" "$sha" >&2
  # The MeshLab source (scripts/bootstrap.sh) is shared with this checkout.
  [ -e "$tree/.cache" ] || ln -s "$(realpath "$ROOT/.cache")" "$tree/.cache"
  build="$tree/build-identity"
  cmake -S "$tree" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCADLOD_BUILD_BENCH=ON \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache >&2
  ninja -C "$build" -j2 cadlod corpus_bench chain_bench stage >&2
  echo "$build"
}

old_sha="$(git -C "$ROOT" rev-parse --short=9 "$1^{commit}")"
new_sha="$(git -C "$ROOT" rev-parse --short=9 "${2:-HEAD}^{commit}")"
t0=$SECONDS
old_build="$(build_rev "$1" "${OLD_BUILD:-}")"
new_build="$(build_rev "${2:-HEAD}" "${NEW_BUILD:-}")"
echo "== built in $(( SECONDS - t0 )) s: $old_build, $new_build" >&2
# The corpus is made once beside the worktrees (make_cad_corpus.sh skips what exists).
export CADLOD_CORPUS="${CADLOD_CORPUS:-$work/cad-corpus}"
for side in "old $old_sha $old_build" "new $new_sha $new_build"; do
  read -r name sha build <<<"$side"
  rm -rf "$work/out-$sha"
  t1=$SECONDS
  bash "$ROOT/bench/identity/outputs.sh" "${opts[@]}" "$build" "$work/out-$sha" >&2
  echo "== $name outputs ($sha) in $(( SECONDS - t1 )) s: $work/out-$sha" >&2
done
echo "Outputs of $old_sha (old) against $new_sha (new)${opts:+ (${opts[*]})}:"
bash "$ROOT/bench/identity/compare.sh" "$work/out-$old_sha" "$work/out-$new_sha"
