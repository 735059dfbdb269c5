# Sourced by the GUI tests that drive MeshLab through the probe (gui_probe/gui_probe.cpp).
# run_probe MESHLAB PROBE_LIB SCENARIO DIR FILE...: runs the staged MeshLab on FILE... with
# the probe preloaded, scenario SCENARIO, scratch directory DIR; the probe's facts end up
# in DIR/facts.txt, MeshLab's output in DIR/meshlab.log. Returns MeshLab's exit status
# (0 once the probe went through every step).
run_probe() {
  local meshlab=$1 probe=$2 scenario=$3 dir=$4
  shift 4
  CADLOD_GUI_PROBE=$scenario CADLOD_GUI_PROBE_OUT="$dir/facts.txt" CADLOD_GUI_PROBE_DIR="$dir" \
    LD_PRELOAD="${CADLOD_SANITIZER_PRELOAD:-} $probe" HOME="$dir/home" \
    timeout 200 "$meshlab" "$@" >"$dir/meshlab.log" 2>&1
}

# A small CAD-like part in metres: a plate with a boss, a few hundred triangles, quick
# enough for every filter.
write_sample_part() {
  python3 - "$1" <<'PY'
import math, sys
pts, faces = [], []
def grid(nx, ny, z, flip):
    base = len(pts)
    for j in range(ny + 1):
        for i in range(nx + 1):
            pts.append((0.4 * i / nx, 0.3 * j / ny, z))
    for j in range(ny):
        for i in range(nx):
            a = base + j * (nx + 1) + i
            q = (a, a + 1, a + nx + 2, a + nx + 1)
            faces.extend([(q[0], q[1], q[2]), (q[0], q[2], q[3])] if not flip else [(q[0], q[2], q[1]), (q[0], q[3], q[2])])
grid(12, 9, 0.0, True)
grid(12, 9, 0.02, False)
n = 24
base = len(pts)
for k in range(n):
    a = 2 * math.pi * k / n
    pts.append((0.2 + 0.06 * math.cos(a), 0.15 + 0.06 * math.sin(a), 0.02))
    pts.append((0.2 + 0.06 * math.cos(a), 0.15 + 0.06 * math.sin(a), 0.1))
for k in range(n):
    b0, t0, b1, t1 = base + 2 * k, base + 2 * k + 1, base + 2 * ((k + 1) % n), base + 2 * ((k + 1) % n) + 1
    faces.extend([(b0, b1, t1), (b0, t1, t0)])
with open(sys.argv[1], "w") as f:
    f.write("#VRML V2.0 utf8\nDEF Plate Shape { appearance Appearance { material Material { diffuseColor 0.6 0.6 0.7 } }\n")
    f.write(" geometry IndexedFaceSet { creaseAngle 0.5 coord Coordinate { point [\n")
    f.write(",\n".join("%g %g %g" % p for p in pts))
    f.write(" ] }\n coordIndex [\n")
    f.write("\n".join("%d %d %d -1" % t for t in faces))
    f.write(" ] } }\n")
PY
}
