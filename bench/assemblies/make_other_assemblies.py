#!/usr/bin/env python3
"""Writes assemblies built the ways the bench's racks are not, to try the hierarchical LOD as
on assemblies it has not seen (docs/benchmarks.md, "Assemblies of other kinds"):

  make_other_assemblies.py OUTDIR

  unique   300 distinct KiCad parts, each placed once, on 6 boards over a plate: no instances
  inline_once  `unique` with no DEF names, as Creo and SolidWorks place each part file by Inline
  scaled   a module of 36 parts, some scaled unevenly (1 1 3, 2 1 1) or evenly (1.5), USE'd 24
           times, some modules at twice the size, some mirrored
  pipes    16 pipes 20 m long and 6 tanks, as plain shapes, beside 120 valve groups USE'd
  vrml1    a VRML 1.0 file: two parts DEF'd once, USE'd 400 times under Separators
  creo     Creo's way: 64 subassembly files placed by Inline, each placing part files by Inline
  tower    a shelf of 16 parts USE'd 60 times one above the other (tall and narrow)
  geo      `pipes` in site coordinates, 5,080 km from the origin (written about a local origin)

Units are KiCad's (0.1 inch): convert with --unit 0.1in. Deterministic.
"""
import os
import random
import re
import shutil
import sys

from make_assemblies import library_parts


def material(rgb):
    return "appearance Appearance { material Material { diffuseColor %s } }" % rgb


def folder_with_parts(out, name, distinct, rng):
    folder = os.path.join(out, name)
    os.makedirs(os.path.join(folder, "parts"), exist_ok=True)
    parts = library_parts(distinct, rng)
    for p in parts:
        shutil.copyfile(p, os.path.join(folder, "parts", os.path.basename(p)))
    return folder, [os.path.basename(p) for p in parts]


def save(folder, name, lines):
    with open(os.path.join(folder, name + ".wrl"), "w") as f:
        f.write("\n".join(lines) + "\n")


def write_unique(out):
    rng = random.Random(11)
    folder, parts = folder_with_parts(out, "unique", 300, rng)
    text = ["#VRML V2.0 utf8"]
    for b in range(6):
        text.append("DEF Board%d Transform { translation %g 0 0 children [ Shape { %s geometry Box { size 500 500 6 } }"
                    % (b, b * 560, material("0 0.4 0.1")))
        for i in range(50):
            text.append('  DEF B%dU%d Transform { translation %g %g 3 rotation 0 0 1 %g children Inline { url "parts/%s" } }'
                        % (b, i, (i % 7 - 3) * 65, (i // 7 - 3) * 65, rng.choice([0, 1.5708]), parts[b * 50 + i]))
        text.append("] }")
    text.append("Transform { translation 1400 0 -200 children Shape { %s geometry Box { size 3400 600 20 } } }"
                % material("0.5 0.5 0.5"))
    save(folder, "unique", text)
    once = os.path.join(out, "inline_once")
    os.makedirs(once, exist_ok=True)
    if not os.path.exists(os.path.join(once, "parts")):
        os.symlink(os.path.join(os.path.abspath(folder), "parts"), os.path.join(once, "parts"))
    save(once, "inline_once", [re.sub(r"DEF \w+ ", "", line) for line in text])


def write_scaled(out):
    rng = random.Random(12)
    folder, parts = folder_with_parts(out, "scaled", 24, rng)
    text = ["#VRML V2.0 utf8", "DEF MOD Group { children [ Shape { %s geometry Box { size 400 400 6 } }" % material("0 0.3 0.5")]
    for i in range(36):
        scale = rng.choice(["1 1 1", "1 1 3", "2 1 1", "1.5 1.5 1.5"])
        text.append('  DEF M%d Transform { translation %g %g 3 scale %s children Inline { url "parts/%s" } }'
                    % (i, (i % 6 - 2.5) * 60, (i // 6 - 2.5) * 60, scale, parts[rng.randrange(24)]))
    text.append("] }")
    for k in range(1, 24):
        scale = "2 2 2" if k % 3 == 0 else ("1 1 1" if k % 3 == 1 else "1 -1 1")
        text.append("DEF Mod%d Transform { translation %g %g 0 scale %s children USE MOD }" % (k, (k % 6) * 900, (k // 6) * 900, scale))
    save(folder, "scaled", text)


def pipes_text(parts, rng):
    text = ["DEF VALVE Group { children ["]
    for i in range(12):
        text.append('  Transform { translation %g 0 %g children Inline { url "parts/%s" } }'
                    % ((i % 4) * 30, (i // 4) * 30, parts[rng.randrange(16)]))
    text.append("] }")
    for k in range(16):
        text.append("DEF Pipe%d Transform { translation 0 %g %g rotation 0 0 1 1.5708 children Shape { %s "
                    "geometry Cylinder { radius 25 height 8000 } } }" % (k, (k % 4) * 150, (k // 4) * 150, material("0.6 0.6 0.2")))
    for k in range(6):
        text.append("DEF Tank%d Transform { translation %g 300 900 children Shape { %s geometry Sphere { radius 300 } } }"
                    % (k, -3000 + k * 1200, material("0.7 0.7 0.7")))
    for k in range(1, 120):
        text.append("DEF Valve%d Transform { translation %g %g %g children USE VALVE }" % (k, -3900 + (k % 40) * 200, (k // 40) * 150 + 60, 700))
    return text


def write_pipes(out):
    folder, parts = folder_with_parts(out, "pipes", 16, random.Random(13))
    save(folder, "pipes", ["#VRML V2.0 utf8"] + pipes_text(parts, random.Random(13)))
    folder, parts = folder_with_parts(out, "geo", 16, random.Random(13))
    save(folder, "geo", ["#VRML V2.0 utf8", "Transform { translation 2e8 2e9 1000 children ["]
         + pipes_text(parts, random.Random(13)) + ["] }"])


def write_vrml1(out):
    rng = random.Random(14)
    folder = os.path.join(out, "vrml1")
    os.makedirs(folder, exist_ok=True)
    text = ["#VRML V1.0 ascii", "Separator {",
            "DEF PART Separator { Material { diffuseColor 0.8 0.3 0.1 } Cylinder { radius 5 height 30 } "
            "Translation { translation 0 20 0 } Cube { width 20 height 6 depth 20 } }",
            "DEF BOLT Separator { Material { diffuseColor 0.5 0.5 0.5 } Cylinder { radius 1.5 height 12 } }"]
    for k in range(400):
        text.append("Separator { Translation { translation %g %g %g } Rotation { rotation 0 1 0 %g } USE %s }"
                    % ((k % 20) * 40, (k // 100) * 60, ((k // 20) % 5) * 40, rng.choice([0, 1.5708, 3.1416]),
                       "PART" if k % 3 else "BOLT"))
    text.append("}")
    save(folder, "vrml1", text)


def write_creo(out):
    rng = random.Random(21)
    folder, parts = folder_with_parts(out, "creo", 20, rng)
    for s in range(4):
        sub = ["#VRML V2.0 utf8"]
        for i in range(25):
            sub.append('Transform { translation %g %g 0 rotation 0 0 1 %g children Inline { url "parts/%s" } }'
                       % ((i % 5) * 50, (i // 5) * 50, rng.choice([0, 1.57]), parts[rng.randrange(20)]))
        save(folder, "sub%d" % s, sub)
    text = ["#VRML V2.0 utf8"]
    for k in range(64):
        text.append('Transform { translation %g %g %g rotation 1 0 0 %g children Inline { url "sub%d.wrl" } }'
                    % ((k % 8) * 300, (k // 8) * 300, (k % 3) * 80, rng.choice([0, 0.3, 1.5708]), k % 4))
    save(folder, "creo", text)


def write_tower(out):
    rng = random.Random(22)
    folder, parts = folder_with_parts(out, "tower", 12, rng)
    text = ["#VRML V2.0 utf8", "DEF SHELF Group { children [ Shape { geometry Box { size 200 200 4 } }"]
    for i in range(16):
        text.append('  Transform { translation %g %g 2 children Inline { url "parts/%s" } }'
                    % ((i % 4 - 1.5) * 45, (i // 4 - 1.5) * 45, parts[rng.randrange(12)]))
    text.append("] }")
    for k in range(1, 60):
        text.append("Transform { translation 0 0 %g children USE SHELF }" % (k * 60))
    save(folder, "tower", text)


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    for write in (write_unique, write_scaled, write_pipes, write_vrml1, write_creo, write_tower):
        write(sys.argv[1])
    print("unique inline_once scaled pipes vrml1 creo tower geo written to %s" % sys.argv[1])


if __name__ == "__main__":
    main()
