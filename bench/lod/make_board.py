#!/usr/bin/env python3
"""Writes a large board assembly from the CAD corpus's KiCad VRML exports (made by
scripts/make_cad_corpus.sh): COUNT parts, each a copy of one of the corpus's .wrl files
(taken in turn, sorted by name) under its own DEF'd Transform on a square grid, turned by
a quarter turn every other row, its DEF/USE names made unique per copy. What a CAD user
exports for a populated board: hundreds of parts, each of several shapes and materials.
Deterministic: the same file for the same corpus and COUNT.

  bench/lod/make_board.py CORPUS_WRL_DIR COUNT OUT.wrl
"""
import math
import os
import re
import sys

# Grid spacing in the files' units (KiCad's VRML unit is 2.54 mm): wider than the largest
# corpus part but for the 125 mm heat sink, which its neighbours may touch.
SPACING = 40.0

NAME = re.compile(r"\b(DEF|USE)\s+([^\s{}\[\]]+)")


def body(text, suffix):
    """The file's nodes without its header line, every DEF/USE name given `suffix`."""
    lines = text.split("\n", 1)
    rest = lines[1] if lines[0].startswith("#VRML") and len(lines) > 1 else text
    return NAME.sub(lambda m: f"{m.group(1)} {m.group(2)}_{suffix}", rest)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    corpus, count, out = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    files = sorted(f for f in os.listdir(corpus) if f.endswith(".wrl"))
    if not files or count < 1:
        sys.exit(f"no .wrl files in {corpus}, or COUNT < 1")
    texts = [open(os.path.join(corpus, f), encoding="latin-1").read() for f in files]
    side = math.isqrt(count - 1) + 1  # the smallest square grid that holds them
    tmp = out + ".partial"
    with open(tmp, "w", encoding="latin-1") as w:
        w.write("#VRML V2.0 utf8\n# cadlod bench: a board of %d parts from the CAD corpus\n" % count)
        w.write("Group { children [\n")
        for i in range(count):
            row, col = divmod(i, side)
            turn = 1.5707963 if row % 2 else 0.0
            w.write("DEF Part_%d_%s Transform {\n translation %.3f %.3f 0\n rotation 0 0 1 %.7f\n children [\n"
                    % (i, os.path.splitext(files[i % len(files)])[0], col * SPACING, row * SPACING, turn))
            w.write(body(texts[i % len(texts)], str(i)))
            w.write("\n ]\n}\n")
        w.write("] }\n")
    os.replace(tmp, out)


if __name__ == "__main__":
    main()
