#!/usr/bin/env bash
# Builds the seed corpora at run time (nothing is copied into the repository):
#   make_seeds.sh FUZZ_BUILD_DIR OUT_DIR
# VRML seeds: the castle-demo-models corpus (../shared/corpus) files up to 64 KiB and the
# VRML snippets of tests/vrml and tests/badinput; gzip seeds: the same, gzipped, plus the
# corpus's own .wrz/.wrl.gz; OpenFlight seeds: files written by flt_seed_writer.
set -euo pipefail
build="$1"; out="$2"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
corpus="${CADLOD_CORPUS_DIR:-$root/../shared/corpus}/castle-demo-models"
mkdir -p "$out"/fuzz_vrml_text "$out"/fuzz_vrml_gzip "$out"/fuzz_flt_reader

n=0
while IFS= read -r -d '' f; do
  n=$((n + 1))
  case "$f" in
    *.wrz|*.gz) cp "$f" "$out/fuzz_vrml_gzip/corpus_$n.wrz"
                gzip -dc "$f" > "$out/fuzz_vrml_text/corpus_$n.wrl" 2>/dev/null || true ;;
    *) cp "$f" "$out/fuzz_vrml_text/corpus_$n.wrl"
       gzip -c "$f" > "$out/fuzz_vrml_gzip/corpus_$n.wrz" ;;
  esac
done < <(find "$corpus" -type f \( -name '*.wrl' -o -name '*.wrz' -o -name '*.wrl.gz' -o -name '*.vrml' \) \
           -size -64k -print0 2>/dev/null)

# Raw-string VRML snippets of the unit tests ("#VRML ..." up to the closing delimiter).
python3 - "$root" "$out" <<'PY'
import pathlib, re, sys, gzip
root, out = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
k = 0
for src in sorted(list((root / "tests/vrml").glob("*.cpp")) + list((root / "tests/badinput").glob("*.cpp"))):
    for m in re.finditer(r'R"(\w*)\((#VRML.*?)\)\1"', src.read_text(errors="replace"), re.S):
        k += 1
        data = m.group(2).encode()
        (out / "fuzz_vrml_text" / f"test_{k}.wrl").write_bytes(data)
        (out / "fuzz_vrml_gzip" / f"test_{k}.wrz").write_bytes(gzip.compress(data))
print(f"{k} VRML snippets from the unit tests")
PY

"$build/tests/fuzz/flt_seed_writer" "$out/fuzz_flt_reader"
for t in fuzz_vrml_text fuzz_vrml_gzip fuzz_flt_reader; do
  echo "$t: $(find "$out/$t" -type f | wc -l) seeds"
done
