#!/bin/bash
# VRML import benchmark: generated CAD-like VRML of about 5, 50 and 200 MB read by
#   cadlod core      (bench/vrml/vrml_core_bench: file -> neutral scene)
#   cadlod plugin    (staged meshlabserver -i: file -> MeshLab layer, end to end)
#   MeshLab io_x3d   (/usr/bin/meshlabserver -i with the system plugins only)
#   Coin3D           (tests/vrml/coin_count: SoDB::readAll + triangle generation)
# and prints one table (wall and CPU seconds, MB/s, triangles/s, peak RSS).
# Usage: bench/vrml/run.sh BUILD_DIR [SIZE_MB...]   (BUILD_DIR configured with
# -DCADLOD_BUILD_BENCH=ON and built). Needs Xvfb for meshlabserver; starts its own.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build="$(cd "${1:?usage: run.sh BUILD_DIR [SIZE_MB...]}" && pwd)"
shift
sizes=("${@:-5 50 200}")
[[ $# -eq 0 ]] && sizes=(5 50 200)
data="$build/bench-vrml-data"
mkdir -p "$data"
for s in "${sizes[@]}"; do
  [[ -f "$data/cad$s.wrl" ]] || "$build/bench/vrml/gen_cad_vrml" "$data/cad$s.wrl" "$s" >/dev/null
done

if [[ -z "${DISPLAY:-}" ]]; then
  for n in $(seq 90 120); do
    [[ -e /tmp/.X$n-lock ]] && continue
    Xvfb ":$n" -screen 0 640x480x24 >/dev/null 2>&1 &
    xvfb_pid=$!
    trap 'kill $xvfb_pid 2>/dev/null || true' EXIT
    export DISPLAY=":$n"
    sleep 1
    break
  done
fi

files=()
for s in "${sizes[@]}"; do files+=("$data/cad$s.wrl"); done
python3 "$here/bench_table.py" --build "$build" "${files[@]}"
