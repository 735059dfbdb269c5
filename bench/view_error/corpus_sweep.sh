#!/usr/bin/env bash
# Every VRML file of a corpus through `cadlod convert` (the defaults) and bench/view_error:
#   bench/view_error/corpus_sweep.sh BUILD_DIR CORPUS_DIR WORK_DIR
# Prints one line per file (converted or the first line of its error), then how many
# converted, the worst error on screen over all of them per path, and the files above 1.2 px.
set -uo pipefail
BUILD="$(cd "$1" && pwd)"; CORPUS="$2"; WORK="$3"
mkdir -p "$WORK"; WORK="$(cd "$WORK" && pwd)"
CADLOD="$BUILD/cli/cadlod"; VIEW="$BUILD/bench/view_error/view_error"
converted=0; failed=0; : > "$WORK/sweep.txt"
while IFS= read -r -d '' f; do
  n=$(echo "${f#"$CORPUS"/}" | tr '/ ' '__'); out="$WORK/$n.flt"
  if timeout 300 "$CADLOD" convert "$f" -o "$out" --force -q 2>"$WORK/$n.log"; then
    converted=$((converted + 1))
    "$VIEW" "$out" 2>/dev/null | awk -v n="$n" '{print n, $2, $4, $8, $10}' >> "$WORK/sweep.txt"
  else
    failed=$((failed + 1)); echo "$n: $(head -1 "$WORK/$n.log")"
  fi
done < <(find "$CORPUS" -type f \( -iname '*.wrl' -o -iname '*.wrl.gz' -o -iname '*.wrz' \) -print0 | sort -z)
echo "converted $converted, refused $failed"
awk '{ if ($3 > worst[$2]) { worst[$2] = $3; at[$2] = $1 } }
     END { for (p in worst) printf "worst %-8s %.2f px (%s)\n", p, worst[p], at[p] }' "$WORK/sweep.txt" | sort
awk '$3 > 1.2 { printf "above 1.2 px: %s %s %.2f px, %.1f %% of the triangles, %s drawables\n", $1, $2, $3, 100 * $4, $5 }' "$WORK/sweep.txt"
