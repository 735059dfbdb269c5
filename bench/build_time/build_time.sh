#!/usr/bin/env bash
# The clean build time of one or more revisions, as CI builds them (scripts/test.sh's
# configuration, every target, -j of the machine's cores), each in a fresh worktree and
# build dir, without a compiler cache, one after the other:
#   bench/build_time/build_time.sh REV [REV...]
# Prints per revision the wall time and the CPU time (user + system) of the build step.
# Worktrees and build dirs go to $CADLOD_BUILD_TIME_DIR (default ../build-time), MeshLab's
# source is copied from this checkout's .cache (scripts/bootstrap.sh makes it).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
WORK="${CADLOD_BUILD_TIME_DIR:-$ROOT/../build-time}"
[ $# -ge 1 ] || { echo "usage: $0 REV [REV...]" >&2; exit 2; }
[ -d "$ROOT/.cache/meshlab-src" ] || { echo "run scripts/bootstrap.sh first" >&2; exit 1; }
mkdir -p "$WORK"
export CCACHE_DISABLE=1
printf '| revision | wall | CPU (user + sys) |\n|---|---|---|\n'
for rev in "$@"; do
  sha="$(git -C "$ROOT" rev-parse --short "$rev")"
  tree="$WORK/$sha"
  [ -d "$tree" ] || git -C "$ROOT" worktree add --detach "$tree" "$sha" >/dev/null 2>&1
  [ -d "$tree/.cache/meshlab-src" ] || { mkdir -p "$tree/.cache"; cp -a "$ROOT/.cache/meshlab-src" "$tree/.cache/"; }
  rm -rf "$tree/build"
  cmake -S "$tree" -B "$tree/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >"$WORK/$sha.configure.log" 2>&1
  TIMEFORMAT='%R %U %S'
  t="$( { time cmake --build "$tree/build" -j "$(nproc)" >"$WORK/$sha.build.log" 2>&1; } 2>&1 )"
  read -r wall user sys <<<"$t"
  awk -v r="$rev ($sha)" -v w="$wall" -v u="$user" -v s="$sys" \
    'BEGIN { printf "| %s | %d min %02d s | %d min %02d s |\n", r, w / 60, w % 60, (u + s) / 60, (u + s) % 60 }'
done
