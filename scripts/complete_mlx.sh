#!/usr/bin/env bash
# Completes a meshlabserver script: MeshLab 2020.09's meshlabserver aborts unless a script
# lists every parameter of every filter in order. Write only the parameters you change,
# then:  scripts/complete_mlx.sh short.mlx full.mlx   (needs a build: scripts/test.sh or demo.sh)
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${CADLOD_BUILD_DIR:-$ROOT/build}"
[ $# -eq 2 ] || { echo "usage: scripts/complete_mlx.sh IN.mlx OUT.mlx" >&2; exit 2; }
tool="$BUILD/tests/e2e/cadlod_mlx_complete"
[ -x "$tool" ] || { echo "no $tool: build first (scripts/test.sh)" >&2; exit 1; }
xvfb-run -a "$tool" "$BUILD/stage/lib/x86_64-linux-gnu/meshlab/plugins" "$1" "$2" 2> >(grep -v -e "Plugins Dir" -e "Serious error" >&2)
