#!/usr/bin/env bash
# Runs every fuzz target concurrently (niced) for SECONDS each, then keeps any crasher,
# timeout or out-of-memory input as a regression input under regressions/<target>/.
#   tests/fuzz/run_fuzzers.sh [SECONDS] [FUZZ_BUILD_DIR] [WORK_DIR]
# Build first: cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ \
#   -DCMAKE_C_COMPILER=clang -DCADLOD_BUILD_FUZZERS=ON && cmake --build build-fuzz --target cadlod_fuzzers
# Logs: WORK_DIR/<target>.log; the last "#N DONE/pulse cov: ft:" line has the figures.
set -uo pipefail
seconds="${1:-1800}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${2:-$here/../../build-fuzz}"
work="${3:-$build/fuzz-work}"
targets=(fuzz_vrml_text fuzz_vrml_gzip fuzz_flt_reader)

bash "$here/make_seeds.sh" "$build" "$work/seeds"
pids=()
for t in "${targets[@]}"; do
  mkdir -p "$work/corpus/$t" "$work/artifacts/$t"
  # An OpenFlight model never needs one allocation of 64 MiB from a 64 KiB file: a bigger
  # one is memory amplification, reported as a crash instead of a slow unit.
  extra=()
  [ "$t" = fuzz_flt_reader ] && extra=(-malloc_limit_mb=64)
  # -fork keeps fuzzing after a crash (each crash is saved to artifacts/).
  nice -n 10 "$build/tests/fuzz/$t" "$work/corpus/$t" "$work/seeds/$t" \
    -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=10 -max_len=65536 \
    -artifact_prefix="$work/artifacts/$t/" -print_final_stats=1 "${extra[@]}" > "$work/$t.log" 2>&1 &
  pids+=($!)
done
status=0
for i in "${!targets[@]}"; do
  wait "${pids[$i]}" || status=1
done

for t in "${targets[@]}"; do
  found=0
  for f in "$work/artifacts/$t"/*; do
    [ -f "$f" ] || continue
    found=$((found + 1))
    cp "$f" "$here/regressions/$t/$(basename "$f")"
  done
  echo "$t: $(grep -E 'cov: [0-9]+' "$work/$t.log" | tail -1)"
  echo "$t: $found new crasher/timeout/oom inputs kept in tests/fuzz/regressions/$t/"
done
exit $status
