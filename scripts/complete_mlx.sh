#!/usr/bin/env bash
# Completes a meshlabserver script: MeshLab 2020.09's meshlabserver aborts unless a script
# lists every parameter of every filter in order. Write only the parameters you change,
# then:  scripts/complete_mlx.sh short.mlx full.mlx   (needs a build: scripts/test.sh or demo.sh)
# An unknown parameter name is an error (a typo). To bring a script of an older version up to
# date, --drop-unknown drops the parameters a filter no longer has, each with a warning.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${CADLOD_BUILD_DIR:-$ROOT/build}"
options=()
[ "${1:-}" = "--drop-unknown" ] && { options+=("$1"); shift; }
[ $# -eq 2 ] || { echo "usage: scripts/complete_mlx.sh [--drop-unknown] IN.mlx OUT.mlx" >&2; exit 2; }
tool="$BUILD/tests/e2e/cadlod_mlx_complete"
[ -x "$tool" ] || { echo "no $tool: build first (scripts/test.sh)" >&2; exit 1; }
# MeshLab's plugin loader chatters on stderr; keep the tool's own message (an unknown
# filter or parameter lists the names there are, see docs/mlx-parameters.md). The filter
# runs after the tool has ended, not in a process substitution that the script's exit
# could cut short, so the message is printed whatever stderr is (terminal, file, pipe).
# An X display is needed (MeshLab's plugins need GL): the caller's, or a fresh Xvfb.
run="xvfb-run -a"
[ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1 && run=""
errors=$(mktemp)
trap 'rm -f "$errors"' EXIT
status=0
$run "$tool" "${options[@]}" "$BUILD/stage/lib/x86_64-linux-gnu/meshlab/plugins" "$1" "$2" 2>"$errors" || status=$?
grep -v -e "Plugins Dir" -e "Serious error" "$errors" >&2 || true
if [ $status -ne 0 ]; then
  grep -q "cadlod_mlx_complete:" "$errors" || echo "complete_mlx.sh: cadlod_mlx_complete failed (exit $status)" >&2
  echo "complete_mlx.sh: parameter names of every cadlod filter: docs/mlx-parameters.md" >&2
  echo "complete_mlx.sh: a script from an older version? --drop-unknown drops what its filters no longer have" >&2
fi
exit $status
