#!/usr/bin/env python3
"""One large part: a wavy sheet 2 m square of CELLS x CELLS quads (2 triangles each), one
IndexedFaceSet no DEF names, as a scanned casting or a large housing comes out of a CAD export.

    python3 bench/assemblies/make_sheet.py WORK [CELLS]     (default 1024: 2,097,152 triangles)

Writes WORK/sheet/sheet.wrl (docs/benchmarks.md, "Chunks cut again near the viewer").
"""
import math
import os
import sys


def main():
    work = sys.argv[1]
    cells = int(sys.argv[2]) if len(sys.argv) > 2 else 1024
    os.makedirs(os.path.join(work, "sheet"), exist_ok=True)
    path = os.path.join(work, "sheet", "sheet.wrl")
    with open(path, "w") as f:
        f.write("#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [\n")
        for j in range(cells + 1):
            f.write(",".join("%g %g %g" % (2.0 * i / cells, 2.0 * j / cells,
                                           0.03 * math.sin(12.0 * i / cells) * math.cos(4.0 * j / cells))
                             for i in range(cells + 1)))
            f.write(",\n")
        f.write("] } coordIndex [\n")
        row = cells + 1
        for j in range(cells):
            f.write(" ".join("%d %d %d %d -1" % (j * row + i, j * row + i + 1, (j + 1) * row + i + 1, (j + 1) * row + i)
                             for i in range(cells)))
            f.write("\n")
        f.write("] } }\n")
    print(path)


if __name__ == "__main__":
    main()
