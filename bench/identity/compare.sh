#!/usr/bin/env bash
# Compares two OUT_DIRs of bench/identity/outputs.sh, one line per output, and exits 1 on
# any difference (or an output missing on one side):
#   bench/identity/compare.sh OLD_OUT NEW_OUT
# .flt and chain plot .dat files: cmp. Reports (.json): jq -S with the timings removed
# (.timings and any .seconds/.millis). Bench tables (.md): the timing figures removed: the
# corpus rows' last two columns (s, peak MB: memory varies with the allocator, not the
# result), the chain rows' build s and build / 90 % run, "measuring ... s" lines and the
# wall time. Logs are not compared.
set -uo pipefail
old="$1" new="$2"

normalize() {  # FILE -> stdout, timing fields removed
  case "$1" in
    *.json) jq -S 'del(.timings) | del(.. | .seconds?, .millis?, .milliseconds?)' "$1" ;;
    */corpus.md|*/corpus.raw.md)
      sed -E -e 's/\| [0-9.]+ \| [0-9.]+ \|$/| - | - |/' -e 's/Wall time [0-9.]+ s/Wall time - s/' "$1" ;;
    */chains.md)
      sed -E -e '/\| cadlod \|/s/\| [0-9.infa-]+ \| [0-9.infa-]+ \|$/| - | - |/' \
             -e '/\| meshopt \|/s/\| [0-9.]+ \| \|$/| - | |/' \
             -e '/measuring the levels against level 0:/d' "$1" ;;
    *) cat "$1" ;;
  esac
}

status=0
mapfile -t files < <(cd "$old" && find . -path ./inputs -prune -o -type f \( -name '*.flt' -o -name '*.json' \
  -o -name '*.md' -o -name '*.dat' \) -print | sed 's|^\./||' | sort)
mapfile -t newfiles < <(cd "$new" && find . -path ./inputs -prune -o -type f \( -name '*.flt' -o -name '*.json' \
  -o -name '*.md' -o -name '*.dat' \) -print | sed 's|^\./||' | sort)
for f in $(comm -13 <(printf '%s\n' "${files[@]}") <(printf '%s\n' "${newfiles[@]}")); do
  printf '%-40s DIFFERENT (only in %s)\n' "$f" "$new"; status=1
done
for f in "${files[@]}"; do
  if [ ! -f "$new/$f" ]; then
    printf '%-40s DIFFERENT (missing in %s)\n' "$f" "$new"; status=1; continue
  fi
  # A run that failed leaves an empty output: say so rather than compare two empties.
  if [ ! -s "$old/$f" ]; then
    printf '%-40s DIFFERENT (empty)\n' "$f"; status=1; continue
  fi
  case "$f" in
    *.flt|*.dat) cmp -s "$old/$f" "$new/$f"; same=$? ;;
    *) cmp -s <(normalize "$old/$f") <(normalize "$new/$f"); same=$? ;;
  esac
  if [ "$same" = 0 ]; then
    printf '%-40s identical\n' "$f"
  else
    printf '%-40s DIFFERENT\n' "$f"; status=1
  fi
done
[ -s "$old/demo.flt" ] || { printf '%-40s DIFFERENT (missing in %s)\n' demo.flt "$old"; status=1; }
exit "$status"
