#!/usr/bin/env bash
# Makes the CAD tuning corpus (bench/corpus/README.md) from Debian packages:
#   scripts/make_cad_corpus.sh [OUTDIR]     (default .cache/cad-corpus)
# Installs kicad-packages3d (~380 MB download), occt-misc and the OCCT headers with apt when
# missing, unpacks freecad-common's sample STEP files (apt-get download, not installed),
# builds bench/corpus/step_tessellate and tessellates every part of bench/corpus/manifest.txt
# at a coarse and a fine deflection. Deterministic and idempotent: what exists is skipped.
# Writes OUTDIR/ply/<id>_{coarse,fine}.ply, OUTDIR/wrl/<id>.wrl (KiCad's own VRML of the
# part, when KiCad ships one) and OUTDIR/manifest.txt (a copy, with triangle counts).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
OUT="${1:-$ROOT/.cache/cad-corpus}"
MANIFEST="$ROOT/bench/corpus/manifest.txt"
KICAD=/usr/share/kicad/3dmodels
OCCT=/usr/share/opencascade/data
mkdir -p "$OUT/ply" "$OUT/wrl" "$OUT/bin" "$OUT/src"
OUT="$(cd "$OUT" && pwd)"
FREECAD="$OUT/src/freecad-common/usr/share/freecad/Mod/Idf/Idflibs"

sudo_if() { if [ "$(id -u)" = 0 ]; then "$@"; else sudo "$@"; fi; }

need=()
for pkg in kicad-packages3d occt-misc libocct-data-exchange-dev libocct-modeling-algorithms-dev \
           libocct-modeling-data-dev libocct-foundation-dev g++; do
  dpkg -s "$pkg" >/dev/null 2>&1 || need+=("$pkg")
done
if [ ${#need[@]} -gt 0 ]; then
  echo "== apt-get install ${need[*]}"
  sudo_if apt-get install -y --no-install-recommends "${need[@]}" ||
    { sudo_if apt-get update && sudo_if apt-get install -y --no-install-recommends "${need[@]}"; }
fi

if [ ! -d "$FREECAD" ]; then
  echo "== freecad-common (sample STEP files, unpacked only)"
  tmp="$(mktemp -d)"
  chmod a+rwx "$tmp"  # apt fetches as user _apt
  if (cd "$tmp" && apt-get download freecad-common >/dev/null); then
    dpkg-deb -x "$tmp"/freecad-common_*.deb "$OUT/src/freecad-common.partial"
    rm -rf "$OUT/src/freecad-common"
    mv "$OUT/src/freecad-common.partial" "$OUT/src/freecad-common"
  else
    echo "warning: apt-get download freecad-common failed: freecad parts skipped" >&2
  fi
  rm -rf "$tmp"
fi

TOOL="$OUT/bin/step_tessellate"
SRC="$ROOT/bench/corpus/step_tessellate.cpp"
if [ ! -x "$TOOL" ] || [ "$SRC" -nt "$TOOL" ]; then
  echo "== build $TOOL"
  g++ -O2 -std=c++17 -Wno-deprecated-declarations -I/usr/include/opencascade "$SRC" -o "$TOOL.tmp" \
    -lTKSTEP -lTKIGES -lTKXSBase -lTKBRep -lTKMesh -lTKTopAlgo -lTKGeomBase -lTKG3d -lTKMath -lTKernel
  mv "$TOOL.tmp" "$TOOL"
fi

# name deviation angular(deg): FreeCAD's mesh-export deflection (bench/corpus/README.md).
TESSELLATIONS=("coarse 0.2 20" "fine 0.03 6")

{
  echo "# made by scripts/make_cad_corpus.sh from bench/corpus/manifest.txt"
  echo "# id split source path coarse_triangles fine_triangles"
} > "$OUT/manifest.txt.tmp"
failed=0
while read -r id split source path; do
  case "$id" in ''|'#'*) continue ;; esac
  case "$source" in
    kicad) file="$KICAD/$path" ;;
    occt) file="$OCCT/$path" ;;
    freecad) file="$FREECAD/$path" ;;
    *) echo "manifest: unknown source $source" >&2; exit 1 ;;
  esac
  if [ ! -f "$file" ]; then
    echo "missing source for $id: $file" >&2
    failed=1
    continue
  fi
  counts=()
  for t in "${TESSELLATIONS[@]}"; do
    read -r name deviation angular <<<"$t"
    ply="$OUT/ply/${id}_$name.ply"
    if [ ! -s "$ply" ]; then
      printf '%-18s %-7s ' "$id" "$name"
      "$TOOL" "$file" "$ply.tmp" --deviation "$deviation" --angular "$angular"
      mv "$ply.tmp" "$ply"
    fi
    # Triangle count from the PLY header.
    counts+=("$(head -c 600 "$ply" | tr -d '\r' | awk '/^element face/ {print $3; exit}')")
  done
  wrl="${file%.*}.wrl"
  if [ -f "$wrl" ] && [ ! -s "$OUT/wrl/$id.wrl" ]; then
    cp "$wrl" "$OUT/wrl/$id.wrl.tmp" && mv "$OUT/wrl/$id.wrl.tmp" "$OUT/wrl/$id.wrl"
  fi
  echo "$id $split $source $path ${counts[*]}" >> "$OUT/manifest.txt.tmp"
done < "$MANIFEST"
mv "$OUT/manifest.txt.tmp" "$OUT/manifest.txt"
echo "== corpus in $OUT: $(ls "$OUT/ply" | grep -c '\.ply$') PLY, $(ls "$OUT/wrl" | grep -c '\.wrl$') WRL"
exit "$failed"
