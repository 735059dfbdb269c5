#!/usr/bin/env bash
# Regenerates docs/mlx-parameters.md (every cadlod filter's .mlx parameter names, types,
# defaults and meaning) from the built plugins. Needs a build (scripts/test.sh).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD="${CADLOD_BUILD_DIR:-$ROOT/build}"
tool="$BUILD/tests/e2e/cadlod_mlx_doc"
[ -x "$tool" ] || { echo "no $tool: build first (scripts/test.sh)" >&2; exit 1; }
xvfb-run -a "$tool" "$BUILD/stage/lib/x86_64-linux-gnu/meshlab/plugins" "$ROOT/docs/mlx-parameters.md"
echo "wrote $ROOT/docs/mlx-parameters.md"
