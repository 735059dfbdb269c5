#!/usr/bin/env bash
# Hierarchical LOD side by side (docs/benchmarks.md, "Hierarchical LOD"):
#   bench/assemblies/hlod.sh BUILD_DIR WORK_DIR [ASSEMBLY...]   (default: demo cabinet_q cabinet plant hall yard yard_close line)
# For each assembly (the bundled demo, or one made by make_assemblies.py or, for unique scaled
# pipes vrml1 creo tower geo inline_once, make_other_assemblies.py into WORK_DIR), in one
# run: --hlod auto (the default: the fewest draw calls above 400 placements, instances up to
# that), --hlod off (a node per placement), the mode auto did not choose (--hlod instances or
# --hlod calls; on make_other_assemblies.py's, only where auto chose calls) and, for the demo and
# cabinet_q, --instances expand (one node for the whole model: the chain of the per-cluster
# estimate). Prints build time and peak memory, then bench/view_error's worst error on
# screen, triangles, drawables and, where the expanded chain exists, the ratio to the
# 16x16x16 per-cluster estimate, on the inside, walk and approach paths.
set -euo pipefail
BUILD="$(cd "$1" && pwd)"; WORK="$2"; shift 2
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
ASSEMBLIES=("$@"); [ $# -gt 0 ] || ASSEMBLIES=(demo cabinet_q cabinet plant hall yard yard_close line)
CADLOD="$BUILD/cli/cadlod"; VIEW="$BUILD/bench/view_error/view_error"
mkdir -p "$WORK/hlod"; WORK="$(cd "$WORK" && pwd)"
OTHER=" unique inline_once scaled pipes vrml1 creo tower geo "  # make_other_assemblies.py's
for a in "${ASSEMBLIES[@]}"; do
  [ "$a" = demo ] || [ -f "$WORK/$a/$a.wrl" ] && continue
  case "$OTHER" in *" $a "*) python3 "$HERE/make_other_assemblies.py" "$WORK" >/dev/null ;;
                   *) python3 "$HERE/make_assemblies.py" "$WORK" >/dev/null ;; esac
done

input_of() { [ "$1" = demo ] && echo "$HERE/../../docs/sample/cad_assembly.wrl.gz" || echo "$WORK/$1/$1.wrl"; }
unit_of() { [ "$1" = demo ] && echo mm || echo 0.1in; }

printf "%-10s %-7s %8s %8s\n" assembly run seconds peak_MB
for a in "${ASSEMBLIES[@]}"; do
  runs=(auto off other); { [ "$a" = demo ] || [ "$a" = cabinet_q ]; } && runs+=(expand)
  ran=()
  for r in "${runs[@]}"; do
    if [ "$r" = other ]; then  # the tree auto did not choose
      tree=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["hlod"]["tree"])' "$WORK/hlod/$a.auto.json")
      if [ "$tree" = calls ]; then r=instances; else r=calls; fi
      [ "$r" = calls ] && [[ "$OTHER" == *" $a "* ]] && continue
    fi
    ran+=("$r")
    out="$WORK/hlod/$a.$r"
    if [ "$r" = expand ]; then args=(--instances expand); else args=(--hlod "$r"); fi
    /usr/bin/time -f "%e %M" -o "$out.time" "$CADLOD" convert "$(input_of "$a")" -o "$out.flt" \
      --unit "$(unit_of "$a")" "${args[@]}" --force -q --report "$out.json" 2>"$out.log"
    read -r s kb < "$out.time"
    printf "%-10s %-7s %8.1f %8d\n" "$a" "$r" "$s" $((kb / 1024))
  done
  estimate=(); [ -f "$WORK/hlod/$a.expand.flt" ] && estimate=(--estimate "$WORK/hlod/$a.expand.flt")
  files=(); for r in "${ran[@]}"; do files+=("$WORK/hlod/$a.$r.flt"); done
  "$VIEW" "${estimate[@]}" --walk-csv "$WORK/hlod/$a.walk.csv" "${files[@]}" | sed "s|$WORK/hlod/||"
done
