#!/usr/bin/env bash
# Reproduces the two experiments of the paper (Tang et al. 2015, §5) on the bundled samples
# and regenerates docs/paper-reproduction.md with its pictures (docs/img/paper-*.png); the
# work is done by scripts/paper/reproduce_paper.py (see there).
#
#   scripts/reproduce_paper.sh [--document-only [--work DIR] [--output FILE]]
# Environment: CADLOD_BUILD_DIR (default build/; configured with -DCADLOD_BUILD_BENCH=ON),
# PAPER_FRAMES (frames per frame-rate run, default 300), PAPER_RUNS (runs per figure,
# median kept, default 5).
# Writes only docs/img/paper-*.png, docs/paper-reproduction.md and $CADLOD_BUILD_DIR/paper-reproduction/.
exec python3 "$(dirname "${BASH_SOURCE[0]}")/paper/reproduce_paper.py" "$@"
