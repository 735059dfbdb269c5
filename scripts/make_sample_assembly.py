#!/usr/bin/env python3
"""Writes cadlod's bundled sample CAD models (docs/sample/), tessellated the way CAD
exporters do it: cylinders as long thin strips running the full length of a feature,
flat ends and steps as fans and rings. Units are millimetres, as a CAD export keeps them.

  shaft.wrl            a stepped shaft with chamfers (23,716 triangles, as the paper's Fig. 6 part)
  cad_assembly.wrl.gz  shaft + two bearing housings + four bolts + base plate (47,512
                       triangles, the paper's Table 1 assembly), VRML97, gzip, one Transform
                       per part, DEF/USE for the shared housing, bolt and materials.
Deterministic: the same files every run.
"""
import gzip
import math
import os
import sys


class Mesh:
    def __init__(self):
        self.points = []
        self.faces = []

    def add_ring(self, radius, z, n):
        start = len(self.points)
        for i in range(n):
            a = 2.0 * math.pi * i / n
            self.points.append((radius * math.cos(a), radius * math.sin(a), z))
        return start

    def add_point(self, p):
        self.points.append(p)
        return len(self.points) - 1

    def strip(self, ring0, ring1, n, outward=True):
        """Quads between two rings, split along the long diagonal: CAD-style slivers."""
        for i in range(n):
            j = (i + 1) % n
            a, b, c, d = ring0 + i, ring0 + j, ring1 + j, ring1 + i
            if outward:
                self.faces += [(a, b, c), (a, c, d)]
            else:
                self.faces += [(a, c, b), (a, d, c)]

    def fan(self, center, ring, n, facing_up):
        for i in range(n):
            j = (i + 1) % n
            if facing_up:
                self.faces.append((center, ring + i, ring + j))
            else:
                self.faces.append((center, ring + j, ring + i))


def stepped_shaft(n):
    """Radii/lengths of a stepped shaft along z, 1 mm chamfers at both ends."""
    sections = [(10.0, 30.0), (14.0, 40.0), (18.0, 60.0), (14.0, 40.0), (10.0, 30.0)]
    chamfer = 1.0
    m = Mesh()
    z = 0.0
    # profile: list of (radius, z) from one end to the other
    profile = [(sections[0][0] - chamfer, 0.0), (sections[0][0], chamfer)]
    for k, (r, length) in enumerate(sections):
        z_end = z + length
        if k > 0:
            prev_r = sections[k - 1][0]
            # the previous section ended with a ring at (prev_r, z): the step is a flat
            # annulus from there to the new radius
            profile.append((r, z))
            if r > prev_r:
                profile[-1] = (r - chamfer, z)
                profile.append((r, z + chamfer))
        end_z = z_end - chamfer if k == len(sections) - 1 else z_end
        profile.append((r, end_z))
        z = z_end
    profile.append((sections[-1][0] - chamfer, z))
    rings = [m.add_ring(r, zz, n) for r, zz in profile]
    for a, b in zip(rings, rings[1:]):
        m.strip(a, b, n)
    bottom = m.add_point((0.0, 0.0, 0.0))
    top = m.add_point((0.0, 0.0, z))
    m.fan(bottom, rings[0], n, facing_up=False)
    m.fan(top, rings[-1], n, facing_up=True)
    return m


def tube(r_out, r_in, length, n):
    """A bearing housing: a thick tube, closed by two annular faces."""
    m = Mesh()
    o0, o1 = m.add_ring(r_out, 0.0, n), m.add_ring(r_out, length, n)
    i0, i1 = m.add_ring(r_in, 0.0, n), m.add_ring(r_in, length, n)
    m.strip(o0, o1, n, outward=True)
    m.strip(i0, i1, n, outward=False)
    m.strip(o1, i1, n, outward=True)
    m.strip(i0, o0, n, outward=True)
    return m


def bolt(n):
    """Hex head (6 sides) on a round shank."""
    m = Mesh()
    head0, head1 = m.add_ring(8.0, 0.0, 6), m.add_ring(8.0, 6.0, 6)
    m.strip(head0, head1, 6)
    m.fan(m.add_point((0, 0, 6.0)), head1, 6, facing_up=True)
    under = m.add_point((0, 0, 0.0))
    m.fan(under, head0, 6, facing_up=False)
    s0, s1 = m.add_ring(4.0, 0.0, n), m.add_ring(4.0, -40.0, n)
    m.strip(s1, s0, n)
    m.fan(m.add_point((0, 0, -40.0)), s1, n, facing_up=False)
    return m


def box(sx, sy, sz):
    m = Mesh()
    for z in (0, sz):
        for y in (0, sy):
            for x in (0, sx):
                m.add_point((x - sx / 2, y - sy / 2, z - sz))
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    for a, b, c, d in quads:
        m.faces += [(a, b, c), (a, c, d)]
    return m


def fmt(v):
    s = "%.5f" % v
    s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def indexed_face_set(m, indent):
    pad = " " * indent
    pts = ", ".join("%s %s %s" % tuple(fmt(c) for c in p) for p in m.points)
    idx = " ".join("%d %d %d -1" % f for f in m.faces)
    return (f"{pad}geometry IndexedFaceSet {{\n"
            f"{pad}  solid TRUE\n{pad}  creaseAngle 0.5\n"
            f"{pad}  coord Coordinate {{ point [ {pts} ] }}\n"
            f"{pad}  coordIndex [ {idx} ]\n{pad}}}\n")


def shape(m, material, indent=6):
    pad = " " * indent
    return (f"{pad}Shape {{\n{pad}  appearance Appearance {{ material {material} }}\n"
            + indexed_face_set(m, indent + 2) + f"{pad}}}\n")


def part(name, translation, rotation, body):
    t = " ".join(fmt(c) for c in translation)
    r = " ".join(fmt(c) for c in rotation)
    return (f"DEF {name} Transform {{\n  translation {t}\n  rotation {r}\n"
            f"  children [\n{body}  ]\n}}\n")


def write_shaft(path):
    shaft = stepped_shaft(847)
    text = ("#VRML V2.0 utf8\n# cadlod sample: stepped shaft, units mm\n"
            + part("SHAFT", (0, 0, 0), (0, 0, 1, 0),
                   shape(shaft, "Material { diffuseColor 0.7 0.7 0.75 specularColor 0.5 0.5 0.5 }")))
    with open(path, "w") as f:
        f.write(text)
    return len(shaft.faces)


def write_assembly(path):
    shaft, housing, screw, plate = stepped_shaft(847), tube(30.0, 19.0, 40.0, 1299), bolt(242), box(260, 90, 12)
    steel = "DEF STEEL Material { diffuseColor 0.7 0.7 0.75 specularColor 0.5 0.5 0.5 }"
    parts = [part("SHAFT", (0, 0, 0), (0, 1, 0, 1.5707963), shape(shaft, steel))]
    parts.append(part("HOUSING_A", (15, 0, 0), (0, 1, 0, 1.5707963),
                      "      DEF HOUSING Shape {\n        appearance Appearance { material DEF CAST "
                      "Material { diffuseColor 0.35 0.4 0.5 } }\n"
                      + indexed_face_set(housing, 8) + "      }\n"))
    parts.append(part("HOUSING_B", (145, 0, 0), (0, 1, 0, 1.5707963), "      USE HOUSING\n"))
    for k, (x, y) in enumerate([(35, 40), (35, -40), (165, 40), (165, -40)]):
        body = ("      DEF BOLT Shape {\n        appearance Appearance { material USE STEEL }\n"
                + indexed_face_set(screw, 8) + "      }\n") if k == 0 else "      USE BOLT\n"
        parts.append(part("BOLT_%d" % (k + 1), (x, y, -34), (0, 0, 1, 0), body))
    parts.append(part("BASE_PLATE", (100, 0, -34), (0, 0, 1, 0),
                      shape(plate, "Material { diffuseColor 0.25 0.25 0.28 }")))
    text = ("#VRML V2.0 utf8\n# cadlod sample assembly: shaft, two bearing housings, four bolts, base plate; units mm\n"
            + "".join(parts))
    with gzip.GzipFile(path, "wb", mtime=0) as f:
        f.write(text.encode("ascii"))
    return len(shaft.faces) + 2 * len(housing.faces) + 4 * len(screw.faces) + len(plate.faces)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "docs", "sample")
    os.makedirs(out, exist_ok=True)
    print("shaft.wrl: %d triangles" % write_shaft(os.path.join(out, "shaft.wrl")))
    print("cad_assembly.wrl.gz: %d triangles" % write_assembly(os.path.join(out, "cad_assembly.wrl.gz")))


if __name__ == "__main__":
    main()
