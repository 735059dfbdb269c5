#!/usr/bin/env python3
"""Writes instanced CAD assemblies from KiCad's 3D model library (Debian kicad-packages3d),
the way CAD exports share parts: each distinct part one file placed by Inline, boards
DEF'd once and USE'd, racks of boards USE'd again, some parts placed in a mirror.

  make_assemblies.py OUTDIR [NAME RACKS BOARDS PARTS_PER_BOARD DISTINCT SEED ROWS]...

With no assembly given it writes the bench's set:
  cabinet     3 racks x 8 boards x 80 parts  = 1,920 placements of 48 distinct parts
  cabinet_q   1 rack  x 4 boards x 80 parts  =   320 placements (a quarter)
  plant      10 racks x 10 boards x 100 parts = 10,000 placements of 64 distinct parts
  hall        8 racks x 10 boards x 100 parts =  8,000 placements of 64 distinct parts,
              in two rows across an aisle, the second row turned half round
  yard        the hall with its second row's racks set askew (turned 0.5 radian),
              the racks 50 inches apart so that each stands clear of the next
  yard_close  the yard with the hall's 10-inch gaps: each turned rack's box overlaps the next
  line        a production line: 28 stations on either side of a 23 m beam, those on the
              far side mirrored, each station a machine (a heatsink scaled up), a panel of
              24 parts and its own conveyor of 5 rollers (1,737 placements)
A rack holds its boards flat, one above the other. Racks stand in ROWS rows; every other row
is turned half round about the vertical, as racks that face each other across an aisle (the
yard turns them by TURN, its racks GAP apart).
Units are KiCad's (0.1 inch): convert with --unit 0.1in. Deterministic for a seed.
"""
import os
import random
import shutil
import sys

KICAD = "/usr/share/kicad/3dmodels"
FAMILIES = ["Capacitor_SMD", "Resistor_SMD", "Package_SO", "Package_QFP", "Connector_RJ", "Connector_PinHeader_2.54mm",
            "Package_TO_SOT_SMD", "Crystal", "Inductor_SMD", "Button_Switch_SMD", "Diode_SMD", "LED_SMD",
            "Capacitor_THT", "Connector_USB", "Package_DIP", "Relay_THT"]
BOARD_PITCH = 40.0  # boards lie one above the other, 4 inches apart, parts down
DEFAULT_SET = [("cabinet", 3, 8, 80, 48, 1, 1), ("cabinet_q", 1, 4, 80, 48, 1, 1), ("plant", 10, 10, 100, 64, 2, 1),
               ("hall", 8, 10, 100, 64, 3, 2), ("yard", 8, 10, 100, 64, 3, 2, "0.5", 500),
               ("yard_close", 8, 10, 100, 64, 3, 2, "0.5", 100)]


def library_parts(distinct, rng):
    """`distinct` KiCad part files, spread over the families, smallest files skipped."""
    chosen = []
    per_family = {}
    for family in FAMILIES:
        folder = os.path.join(KICAD, family + ".3dshapes")
        if os.path.isdir(folder):
            files = sorted(f for f in os.listdir(folder) if f.endswith(".wrl"))
            per_family[family] = [os.path.join(folder, f) for f in files if os.path.getsize(os.path.join(folder, f)) > 20000]
    families = [f for f in FAMILIES if per_family.get(f)]
    if not families:
        sys.exit("make_assemblies.py: no KiCad 3D models in %s (apt-get install kicad-packages3d)" % KICAD)
    k = 0
    while len(chosen) < distinct:
        pool = per_family[families[k % len(families)]]
        pick = pool[rng.randrange(len(pool))]
        if pick not in chosen:
            chosen.append(pick)
        k += 1
    return chosen


def board_text(name, parts, per_board, rng, pitch):
    """A board: its PCB (a box) and `per_board` parts placed on a grid by Inline."""
    side = int(per_board ** 0.5 + 0.999)
    lines = ["DEF %s Group { children [" % name,
             "  Shape { appearance Appearance { material Material { diffuseColor 0 0.4 0.1 } } "
             "geometry Box { size %g %g 0.6 } }" % (side * pitch, side * pitch)]
    for i in range(per_board):
        x = (i % side - side / 2 + 0.5) * pitch
        y = (i // side - side / 2 + 0.5) * pitch
        part = parts[rng.randrange(len(parts))]
        turn = rng.choice([0, 1.5708, 3.1416, 4.7124])
        mirror = " scale -1 1 1" if rng.random() < 0.05 else ""
        lines.append("  DEF U%d Transform { translation %g %g 0.3 rotation 0 0 1 %g%s children Inline { url \"parts/%s\" } }"
                     % (i + 1, x, y, turn, mirror, os.path.basename(part)))
    lines.append("] }")
    return "\n".join(lines)


def write_assembly(out, name, racks, boards, per_board, distinct, seed, rows, turn="3.14159265", gap=100):
    rng = random.Random(seed)
    folder = os.path.join(out, name)
    os.makedirs(os.path.join(folder, "parts"), exist_ok=True)
    parts = library_parts(distinct, rng)
    for p in parts:
        target = os.path.join(folder, "parts", os.path.basename(p))
        if not os.path.exists(target):
            shutil.copyfile(p, target)
    pitch = 60.0  # 6 inch grid, in KiCad's 0.1 inch
    side = int(per_board ** 0.5 + 0.999)
    board_size = side * pitch
    text = ["#VRML V2.0 utf8", "# %s: %d racks x %d boards x %d parts, %d distinct (cadlod bench/assemblies)"
            % (name, racks, boards, per_board, distinct)]
    designs = [board_text("BOARD_A", parts, per_board, rng, pitch), board_text("BOARD_B", parts, per_board, rng, pitch)]
    text.append("DEF RACK Group { children [")
    for b in range(boards):
        body = designs[b] if b < 2 else "USE BOARD_%s" % "AB"[b % 2]
        text.append(" DEF Board_%d Transform { translation 0 %g 0 rotation 1 0 0 1.5708 children %s }"
                    % (b + 1, b * BOARD_PITCH, body))
    text.append("] }")
    per_row = (racks + rows - 1) // rows
    row_pitch = board_size + boards * BOARD_PITCH + 2 * gap
    for r in range(1, racks):
        row, place = divmod(r, per_row)
        rotation = " rotation 0 1 0 " + turn if row % 2 else ""
        text.append("DEF Rack_%d Transform { translation %g 0 %g%s children USE RACK }"
                    % (r + 1, place * (board_size + gap), row * row_pitch, rotation))
    path = os.path.join(folder, name + ".wrl")
    with open(path, "w") as f:
        f.write("\n".join(text) + "\n")
    print("%s: %d placements of %d distinct parts" % (path, racks * boards * per_board, distinct))


def write_line(out, name="line", stations=28, seed=7):
    """Stations, each a group DEF'd once, USE'd along both sides of one long beam."""
    rng = random.Random(seed)
    folder = os.path.join(out, name)
    os.makedirs(os.path.join(folder, "parts"), exist_ok=True)
    parts = library_parts(16, rng)
    machine = os.path.join(KICAD, "Heatsink.3dshapes", "Heatsink_125x35x50mm_3xFixationM3.wrl")
    for p in parts + [machine]:
        shutil.copyfile(p, os.path.join(folder, "parts", os.path.basename(p)))
    station = ["DEF STATION Group { children [",
               '  DEF Machine Transform { translation 0 60 40 scale 3 3 3 children Inline { url "parts/%s" } }'
               % os.path.basename(machine),
               "  DEF Panel Transform { translation 0 -40 60 children [",
               "    Shape { appearance Appearance { material Material { diffuseColor 0.2 0.2 0.6 } } "
               "geometry Box { size 120 4 80 } }"]
    for i in range(24):
        station.append('    DEF P%d Transform { translation %g -44 %g rotation 1 0 0 1.5708 children Inline { url "parts/%s" } }'
                       % (i + 1, (i % 6 - 2.5) * 18, (i // 6 - 1.5) * 18, os.path.basename(parts[rng.randrange(len(parts))])))
    station.append("  ] }")
    for r in range(5):
        roller = ("DEF ROLLER Shape { appearance Appearance { material Material { diffuseColor 0.7 0.7 0.7 } } "
                  "geometry Cylinder { radius 4 height 28 } }") if r == 0 else "USE ROLLER"
        station.append("  DEF Roller_%d Transform { translation %g 120 8 rotation 1 0 0 1.5708 children %s }"
                       % (r + 1, (r - 2) * 60, roller))
    station.append("] }")
    text = ["#VRML V2.0 utf8", "# %s: %d stations on either side of a beam (cadlod bench/assemblies)" % (name, 2 * stations),
            "DEF Beam Shape { appearance Appearance { material Material { diffuseColor 0.5 0.5 0.5 } } "
            "geometry Box { size 9000 30 8 } }"]
    for i in range(stations):
        x = -4200 + i * 310
        body = "\n".join(station) if i == 0 else "USE STATION"
        text.append("DEF Station_%d Transform { translation %g -120 0 children %s }" % (i + 1, x, body))
        text.append("DEF Mirrored_%d Transform { translation %g 120 0 scale 1 -1 1 children USE STATION }" % (i + 1, x))
    path = os.path.join(folder, name + ".wrl")
    with open(path, "w") as f:
        f.write("\n".join(text) + "\n")
    print("%s: %d placements" % (path, 2 * stations * 31 + 1))


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    out = sys.argv[1]
    specs = sys.argv[2:]
    todo = DEFAULT_SET if not specs else [
        (specs[i], *(int(v) for v in specs[i + 1:i + 7]))
        for i in range(0, len(specs), 7)]
    for spec in todo:
        write_assembly(out, *spec)
    if not specs:
        write_line(out)


if __name__ == "__main__":
    main()
