"""The two experiments of the paper (Tang et al. 2015, §5): their meshes, measures and
pictures, left in the work directory. Each returns the routes it took, for the page."""
import glob
import os
import shutil
import subprocess

import raw_outputs as raw
import shell_numbers as num
from runner import die, must, nonempty, say
from settings import CAD_FILTER, CAD_REDUCTION_PARAMS, LEVELS, LOD_FILTER, LOD_ONE_LEVEL_PARAMS

LOAD_RUNS = 5


def remove(pattern):
    for path in glob.glob(pattern):
        os.remove(path)


def discard(path):
    if os.path.lexists(path):
        os.remove(path)


def read_mesh(tools, source, out):
    if not (tools.mls("-i", source, "-o", out, "-m", "vn", "fc") and nonempty(out)):
        die("meshlabserver cannot read %s" % source)


# ---------------------------------------------------------------- simplification
def stock_qem(tools, source, out):
    """MeshLab's QEM with its defaults, 90 %."""
    completed = os.path.join(tools.settings.work, "stock_qem_90.mlx")
    if not (tools.complete_mlx(tools.settings.bench("stock_qem_90.mlx"), completed)
            and tools.mls("-i", source, "-s", completed, "-o", out, "-m", "vn", "fc") and nonempty(out)):
        die("MeshLab's stock QEM failed on %s (see %s)" % (source, tools.mls_log))


def cadlod_simplify(tools, source, out, pct, ply):
    """cadlod with its defaults at PCT % reduction: by the CAD simplification filter when the
    plugin has it, else the LOD-set filter with that one level, else (on PLY, the same mesh
    as SOURCE) the simplifier core. Returns the route that made OUT."""
    script = os.path.join(tools.settings.work, "cadlod_%s.mlx" % pct)
    discard(out)
    if tools.has_filter(CAD_FILTER) and tools.single_filter_mlx(script, CAD_FILTER, CAD_REDUCTION_PARAMS % pct):
        if tools.mls("-i", source, "-s", script, "-o", out, "-m", "vn", "fc") and nonempty(out):
            return 'MeshLab filter "%s" (defaults but the stop criterion: reduction %%)' % CAD_FILTER
        discard(out)
    if tools.has_filter(LOD_FILTER) and tools.single_filter_mlx(script, LOD_FILTER, LOD_ONE_LEVEL_PARAMS % pct):
        if tools.mls("-i", source, "-s", script, "-o", out, "-l", "1", "-m", "vn", "fc") and nonempty(out):
            return ('MeshLab filter "%s" with one level (defaults but the levels), as the plugin has no "%s"'
                    % (LOD_FILTER, CAD_FILTER))
        discard(out)
    if not tools.measure(["simplify", ply, out, pct], out + ".log"):
        die("cadlod's simplifier failed on %s" % ply)
    return ("cadlod's simplifier core with its defaults (bench/paper/paper_measure), as no MeshLab filter of "
            "cadlod could do it")


def measure_mesh(tools, mesh, reference=None):
    """Compactness (and its histogram), and the distance to REFERENCE."""
    base = mesh[:-len(".ply")] if mesh.endswith(".ply") else mesh
    if not tools.measure(["compactness", mesh, base + ".hist", "20"], base + ".compactness"):
        die("cannot measure %s" % mesh)
    if reference and not tools.measure(["hausdorff", reference, mesh], base + ".hausdorff"):
        die("Hausdorff distance of %s failed" % mesh)


# ---------------------------------------------------------------- experiment 1
def experiment1(tools):
    """The shaft reduced by 90 % by MeshLab's QEM and by cadlod (Fig. 6)."""
    e = os.path.join(tools.settings.work, "exp1")
    os.makedirs(e, exist_ok=True)
    remove(os.path.join(e, "*.ply"))
    say("experiment 1: shaft, 90 % reduction")
    original = os.path.join(e, "original.ply")
    read_mesh(tools, tools.settings.shaft, original)
    stock_qem(tools, tools.settings.shaft, os.path.join(e, "stock.ply"))
    route = cadlod_simplify(tools, tools.settings.shaft, os.path.join(e, "cadlod.ply"), "90", original)
    say("cadlod route: %s" % route)
    measure_mesh(tools, original)
    for mesh in ("stock", "cadlod"):
        measure_mesh(tools, os.path.join(e, mesh + ".ply"), original)
    fig6_pictures(tools, e)
    fig6_histogram(tools, e)
    fig6_shading(tools, e)
    return route


def fig6_pictures(tools, e):
    """Shaded: the whole shaft from the side; wireframe: a close-up of the step from the
    14 mm to the 18 mm section (PNG8 with few colours keeps the dense wireframes small)."""
    common = ["--size", "800x600", "--crease", "30", "--up", "x"]
    views = {"shaded": ["--azimuth", "-15", "--elevation", "25", "--distance", "2.0"],
             "wire": ["--wire", "--azimuth", "-35", "--elevation", "30", "--distance", "0.2",
                      "--focus", "0.79,0.91,0.35"]}
    for mesh in ("original", "stock", "cadlod"):
        ply, shot = os.path.join(e, mesh + ".ply"), os.path.join(e, mesh + ".shot")
        if not (tools.render([ply, "--shot", os.path.join(e, mesh + "-shaded.png")] + common + views["shaded"], shot)
                and tools.render([ply, "--shot", os.path.join(e, mesh + "-wire.png")] + common + views["wire"], shot,
                                 append=True)):
            die("osg_render cannot draw %s (see %s)" % (mesh, tools.render_log))
    faces = lambda mesh: raw.value("faces", os.path.join(e, mesh + ".compactness")) or ""
    for kind in ("shaded", "wire"):
        target = os.path.join(tools.settings.img, "paper-fig6-%s.png" % kind)
        output = ["-colors", "32", "PNG8:" + target] if kind == "wire" else ["-depth", "8", target]
        must(["montage", "-font", "DejaVu-Sans", "-pointsize", "14",
              "-label", "(a) original, %s triangles" % faces("original"), os.path.join(e, "original-%s.png" % kind),
              "-label", "(b) MeshLab QEM, %s" % faces("stock"), os.path.join(e, "stock-%s.png" % kind),
              "-label", "(c) cadlod, %s" % faces("cadlod"), os.path.join(e, "cadlod-%s.png" % kind),
              "-tile", "3x1", "-geometry", "400x300+4+2"] + output)


GNUPLOT_HISTOGRAM = """set terminal pngcairo size 720,400 font "DejaVu Sans,10"
set output "{img}/paper-fig6-compactness.png"
set title "Triangle compactness, shaft and its 90 % reductions"
set xlabel "compactness 4√3·A / (l0²+l1²+l2²)  (1 = equilateral)"
set ylabel "share of triangles"
set xrange [0:1]
set yrange [0:*]
set key right top
set style fill transparent solid 0.35 noborder
set boxwidth 0.05
plot "{e}/original.hist" using 1:2 with boxes lc rgb "#606060" title "original", \\
     "{e}/stock.hist" using 1:2 with linespoints lw 2 pt 7 ps 0.6 lc rgb "#d04020" title "MeshLab QEM", \\
     "{e}/cadlod.hist" using 1:2 with linespoints lw 2 pt 5 ps 0.6 lc rgb "#2060c0" title "cadlod"
"""


def fig6_histogram(tools, e):
    script = GNUPLOT_HISTOGRAM.format(img=tools.settings.img, e=e)
    if subprocess.run(["gnuplot"], input=script.encode("utf-8"), check=False).returncode != 0:
        die("gnuplot failed")


def fig6_shading(tools, e):
    """The shading-error measure (docs/shading_measure.md) of both reductions against the
    original, and their difference images: the difference panel of each of the 12 views."""
    for mesh in ("stock", "cadlod"):
        prefix = os.path.join(e, "shading-%s-" % mesh)
        remove(prefix + "view*.png")
        if not tools.shading([os.path.join(e, "original.ply"), os.path.join(e, mesh + ".ply"), "--images", prefix],
                             os.path.join(e, mesh + ".shading")):
            die("shading_compare failed on %s" % mesh)
        for view in sorted(glob.glob(prefix + "view*.png")):
            must(["convert", view, "-crop", "256x256+512+0", "+repage", view[:-len(".png")] + "-diff.png"])
    for mesh in ("stock", "cadlod"):
        diffs = sorted(glob.glob(os.path.join(e, "shading-%s-view*-diff.png" % mesh)))
        must(["montage"] + diffs + ["-tile", "6x2", "-geometry", "256x256+1+1", "-background", "#404040",
                                    "-depth", "8", os.path.join(tools.settings.img, "paper-fig6-shading-%s.png" % mesh)])
    label = lambda mesh: "%s %%%% of pixels differ visibly, mean |ΔI| %s" % (
        raw.shading_value("visible", os.path.join(e, mesh + ".shading")),
        raw.shading_value("mean", os.path.join(e, mesh + ".shading")))
    both = os.path.join(e, "shading-view00.png")
    must(["montage", "-font", "DejaVu-Sans", "-pointsize", "14", "-background", "white",
          "-label", "MeshLab QEM: " + label("stock"), os.path.join(e, "shading-stock-view00.png"),
          "-label", "cadlod: " + label("cadlod"), os.path.join(e, "shading-cadlod-view00.png"),
          "-tile", "1x2", "-geometry", "+2+4", both])
    must(["convert", both, "-depth", "8", os.path.join(tools.settings.img, "paper-fig6-shading-view00.png")])


# ---------------------------------------------------------------- experiment 2
def experiment2(tools):
    """The assembly at every reduction of Table 1, each level alone and the two LOD sets
    along one camera path."""
    e = os.path.join(tools.settings.work, "exp2")
    os.makedirs(e, exist_ok=True)
    for pattern in ("level*.ply", "level*.flt", "paper.flt", "chain.flt"):
        remove(os.path.join(e, pattern))
    say("experiment 2: the assembly at 0 %s %%" % LEVELS)
    level = lambda k, ext: os.path.join(e, "level%d.%s" % (k, ext))
    read_mesh(tools, tools.settings.assembly, level(0, "ply"))
    reductions = LEVELS.split()
    for k, pct in enumerate(reductions, start=1):
        route = cadlod_simplify(tools, tools.settings.assembly, level(k, "ply"), pct, level(0, "ply"))
    say("levels: %s" % route)
    for k in range(len(reductions) + 1):
        measure_mesh(tools, level(k, "ply"))
        if not (tools.mls("-i", level(k, "ply"), "-o", level(k, "flt")) and nonempty(level(k, "flt"))):
            die("cadlod's OpenFlight exporter failed on level %d" % k)
    routes = {"cad_route": route, "level_route": route, "paper_set_route": paper_lod_set(tools, e),
              "chain_set_route": chain_lod_set(tools, e)}
    near, far = common_path(tools, e)
    for name in ("paper", "chain"):
        say("rendering the %s LOD set along the path" % name)
        measure_model(tools, os.path.join(e, name + ".flt"), os.path.join(e, name), near, far)
    for k in range(len(reductions) + 1):
        say("rendering level %d alone" % k)
        measure_model(tools, level(k, "flt"), os.path.join(e, "level%d" % k), near, far)
    return routes


def lod_set_filter(tools, mlx, out):
    """The LOD-set filter run by the script MLX on the assembly, all its levels saved as
    one .flt by cadlod's OpenFlight exporter. Returns None when that works, else why not."""
    completed = os.path.join(tools.settings.work, os.path.basename(mlx))
    if not (tools.has_filter(LOD_FILTER) and tools.complete_mlx(mlx, completed)):
        return 'the plugin has no "%s"' % LOD_FILTER
    tools.mls("-i", tools.settings.assembly, "-s", completed, "-o", out, "-l", "0")
    if nonempty(out):
        return None
    return first_failure(tools.mls_log, "-s " + completed)


def first_failure(log, command):
    """The first line that tells of a failure after the last run of COMMAND in LOG."""
    records = num.lines(raw.read_text(log) or "")
    start = max([n for n, line in enumerate(records, start=1) if command in line], default=0)
    for line in records[start:]:
        if "cannot write" in line or "failed" in line or "Failed" in line:
            return line
    return ""


def paper_lod_set(tools, e):
    """The paper's list as one .flt: the LOD-set filter with levelMode 1; if that fails, the
    same builder core through paper_measure. Returns its route."""
    failure = lod_set_filter(tools, tools.settings.bench("lod_set_paper.mlx"), os.path.join(e, "paper.flt"))
    if failure is None:
        return ('MeshLab filter "%s" with the level list %s (levelMode 1, other parameters default)'
                % (LOD_FILTER, LEVELS))
    core = os.path.join(e, "set-core")
    os.makedirs(core, exist_ok=True)
    if not tools.measure(["lodset", os.path.join(e, "level0.ply"), core, LEVELS], os.path.join(core, "lodset.log")):
        die("LOD-set fallback failed")
    shutil.copyfile(os.path.join(core, "lodset.flt"), os.path.join(e, "paper.flt"))
    return ("cadlod's LOD-set builder core with the levels %s (bench/paper/paper_measure), written by cadlod's "
            "OpenFlight core (one part per level), because %s" % (LEVELS, failure or "the filter failed"))


def chain_lod_set(tools, e):
    """The screen-space chain, the LOD-set filter's default. Returns its route."""
    failure = lod_set_filter(tools, tools.settings.bench("lod_set_chain.mlx"), os.path.join(e, "chain.flt"))
    if failure is not None:
        die("the LOD-set filter's screen-space chain failed: %s" % failure)
    return ('MeshLab filter "%s" with its defaults (screen-space chain: 1 px of measured error at 1080 px and 45°, '
            'distance ratio 2)' % LOD_FILTER)


def common_path(tools, e):
    """One camera path for every file: the union of the two sets' own paths over all their
    levels (osg_render's default), so that both are measured on the same frames."""
    for name in ("paper", "chain"):
        flt = os.path.join(e, name + ".flt")
        if not tools.render([flt, "--no-render", "--frames", tools.settings.frames], os.path.join(e, name + ".path")):
            die("OpenSceneGraph cannot load %s" % flt)
    near, far = raw.path_range(e)
    say("camera path from %s to %s model units" % (near, far))
    return near, far


def measure_model(tools, flt, prefix, near, far):
    """PREFIX.load (median load seconds), PREFIX.runN, PREFIX.fps and PREFIX.fpscpu (medians)."""
    for i in range(1, LOAD_RUNS + 1):
        if not tools.render([flt, "--no-render"], "%s.load%d" % (prefix, i)):
            die("OpenSceneGraph cannot load %s" % flt)
    write_median(prefix + ".load", "load_seconds", ["%s.load%d" % (prefix, i) for i in range(1, LOAD_RUNS + 1)])
    runs = ["%s.run%d" % (prefix, i) for i in range(1, int(tools.settings.runs) + 1)]
    extra = ("--near %s --far %s" % (near, far)).split()
    for run in runs:
        if not tools.render([flt, "--frames", tools.settings.frames] + extra, run):
            die("osg_render failed on %s" % flt)
    write_median(prefix + ".fps", "fps", runs)
    write_median(prefix + ".fpscpu", "fps_cpu", runs)


def write_median(out, key, files):
    values = [found for found in (raw.value(key, path) for path in files) if found is not None]
    with open(out, "w", encoding="utf-8", errors="surrogateescape") as stream:
        stream.write(num.median(values) + "\n")
