#!/usr/bin/env bash
# One PNG per DIR/*.dat written by chain_bench --plot: triangles drawn against distance
# (in model diagonals, log scale) for cadlod's chain and the meshoptimizer chain.
#   bench/lod/plot_chains.sh DIR
set -euo pipefail
dir="$1"
command -v gnuplot >/dev/null || { echo "plot_chains.sh: gnuplot is missing (apt-get install gnuplot-nox)" >&2; exit 1; }
for dat in "$dir"/*.dat; do
  png="${dat%.dat}.png"
  title=$(basename "${dat%.dat}")
  gnuplot <<GP
set terminal png size 900,500
set output "$png"
set title "Triangles drawn against distance: $title" noenhanced
set logscale xy
set xlabel "distance / model diagonal"
set ylabel "triangles drawn"
set grid
set key top right
plot "$dat" using 1:(\$2 > 0 ? \$2 : 1/0) with steps lw 2 title "cadlod chain", \
     "$dat" using 1:(\$3 > 0 ? \$3 : 1/0) with steps lw 2 dt 2 title "meshoptimizer chain"
GP
  echo "$png"
done
