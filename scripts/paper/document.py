"""Writing docs/paper-reproduction.md from the raw outputs of a run (work directory)
and the template beside this file. Every figure keeps the format it had when an awk
program or bash's printf wrote it (see shell_numbers)."""
import datetime
import os
import re
import subprocess

import raw_outputs as raw
import shell_numbers as num
from settings import LEVELS, STOCK_FILTER

TEMPLATE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "paper-reproduction.md.in")

# Paper Table 1, per level 0/50/60/70/80/90 %: triangles, fps, load seconds, MB.
PAPER_TRI = ["47512", "23189", "8852", "6189", "4339", "4672"]
PAPER_FPS = ["66", "79", "83", "95", "102", "117"]
PAPER_LOAD = ["0.53", "0.47", "0.31", "0.26", "0.19", "0.11"]
PAPER_MB = ["6.4", "3.7", "2.3", "2.0", "1.3", "0.75"]


def val(key, path):
    """A key's value as the page shows it: empty when the key is missing."""
    found = raw.value(key, path)
    return "" if found is None else found


def ratio(a, b):
    n = num.number
    return num.fmt(".2f", num.divide(n(a), n(b)) if num.positive(b) else 0.0)


def share(a, b):
    n = num.number
    return num.fmt(".1f", num.divide(100 * n(a), n(b)) if num.positive(b) else 0.0) + " %"


# ---------------------------------------------------------------- experiment 1
def compactness_row(name, prefix):
    c = prefix + ".compactness"
    below01 = num.fmt(".2f", 100 * num.number(val("below01", c))) + " %"
    below03 = num.fmt(".2f", 100 * num.number(val("below03", c))) + " %"
    row = "| %s | %s | %s | %s | %s | %s | %s |" % (
        name, val("faces", c), val("zero_area_faces", c), val("mean", c), val("p5", c), below01, below03)
    h = prefix + ".hausdorff"
    if os.path.isfile(h):
        return row + " %s (%s %%) | %s (%s %%) |" % (
            val("max", h), val("max_pct_diag", h), val("mean", h), val("mean_pct_diag", h))
    return row + " – | – |"


def reduction_note(name, prefix, original):
    """What share of the faces a method removed, against the 90 % asked for."""
    f = num.number(val("faces", prefix + ".compactness"))
    f0 = num.number(val("faces", original + ".compactness"))
    return "%s removed %s %% of %d faces (%d left, target %d)." % (
        name, num.fmt(".1f", 100 * (1 - num.divide(f, f0))), num.integer(f0), num.integer(f),
        num.integer(f0 / 10 + 0.5))


def fig6_summary(e1):
    """One sentence comparing the two 90 % reductions."""
    cadlod, stock = os.path.join(e1, "cadlod"), os.path.join(e1, "stock")
    cm, sm = val("mean", cadlod + ".compactness"), val("mean", stock + ".compactness")
    cs, ss = val("below01", cadlod + ".compactness"), val("below01", stock + ".compactness")
    ch, sh = val("max", cadlod + ".hausdorff"), val("max", stock + ".hausdorff")
    n, f = num.number, num.fmt
    return ("cadlod against MeshLab QEM: mean compactness %s against %s (x%s), slivers below 0.1 "
            "%s %% against %s %%, largest distance to the original %s against %s mm (x%s).") % (
        f(".3f", n(cm)), f(".3f", n(sm)), f(".2f", num.divide(n(cm), n(sm)) if num.positive(sm) else 0.0),
        f(".1f", 100 * n(cs)), f(".1f", 100 * n(ss)), f(".3g", n(ch)), f(".3g", n(sh)),
        f(".2f", num.divide(n(ch), n(sh)) if num.positive(sh) else 0.0))


def shading_row(name, prefix):
    """The shading measure beside compactness and Hausdorff, per mesh."""
    s = prefix + ".shading"
    return "| %s | %s | %s %% | %s %% | %s | %s %% | %s |" % (
        name, val("faces", prefix + ".compactness"), raw.shading_value("visible", s),
        raw.shading_value("silhouette", s), raw.shading_value("mean", s),
        val("max_pct_diag", prefix + ".hausdorff"), val("mean", prefix + ".compactness"))


def shading_views(e1):
    """The visible share of every view, both reductions side by side."""
    lines = ["| view | 0 | 1 | 2 | 3 | 4 | 5 | 6 | 7 | 8 | 9 | 10 | 11 |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for mesh, name in (("stock", "MeshLab QEM"), ("cadlod", "cadlod")):
        path = os.path.join(e1, mesh + ".shading")
        if raw.read_text(path) is None:
            continue
        cells = "".join(" %s |" % num.fmt(".2f", num.number(words[4])) for words in raw.rows(path)
                        if len(words) == 6 and re.fullmatch(r"[0-9]+", words[0]))
        lines.append("| %s, visible %% |%s" % (name, cells))
    return "\n".join(lines)


# ---------------------------------------------------------------- experiment 2
def table1(e2):
    level = lambda k, ext: os.path.join(e2, "level%d.%s" % (k, ext))
    t0, f0, c0 = val("faces", level(0, "compactness")), raw.text_of(level(0, "fps")), raw.text_of(level(0, "fpscpu"))
    l0, s0 = raw.text_of(level(0, "load")), size_of(level(0, "flt"))
    lines = ["| reduction | triangles | .flt bytes | load s | fps | fps by CPU time | triangles ratio (paper) "
             "| fps ratio (paper) | fps-by-CPU ratio | load ratio (paper) | size ratio (paper) |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for k, pct in enumerate(["0"] + LEVELS.split()):
        t, f, c = val("faces", level(k, "compactness")), raw.text_of(level(k, "fps")), raw.text_of(level(k, "fpscpu"))
        l, s = raw.text_of(level(k, "load")), size_of(level(k, "flt"))
        lines.append("| %s %% | %s | %s | %s | %s | %s | %s (%s) | %s (%s) | %s | %s (%s) | %s (%s) |" % (
            pct, t, s, num.bash_fixed(4, l), num.bash_fixed(1, f), num.bash_fixed(1, c),
            ratio(t, t0), ratio(PAPER_TRI[k], PAPER_TRI[0]), ratio(f, f0), ratio(PAPER_FPS[k], PAPER_FPS[0]),
            ratio(c, c0), ratio(l, l0), ratio(PAPER_LOAD[k], PAPER_LOAD[0]), ratio(s, s0),
            ratio(PAPER_MB[k], PAPER_MB[0])))
    return "\n".join(lines)


def size_of(path):
    try:
        return raw.file_size(path)
    except OSError:
        return ""


def path_row(e2, name, prefix, levels):
    """A model along the common path: triangles in the file, drawn per frame, frame rate."""
    run1, base = prefix + ".run1", os.path.join(e2, "level0")
    t0, o0 = val("path_mean_triangles", base + ".run1"), val("path_outside_mean_triangles", base + ".run1")
    f0, c0 = raw.text_of(base + ".fps"), raw.text_of(base + ".fpscpu")
    fps, cpu = raw.text_of(prefix + ".fps"), raw.text_of(prefix + ".fpscpu")
    drawn, outside = val("path_mean_triangles", run1), val("path_outside_mean_triangles", run1)
    return "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
        name, levels, val("triangles", run1), drawn, share(drawn, t0), outside, share(outside, o0),
        num.bash_fixed(1, fps), num.bash_fixed(1, cpu), ratio(fps, f0), ratio(cpu, c0))


def path_table(e2):
    paper, chain = os.path.join(e2, "paper"), os.path.join(e2, "chain")
    return "\n".join([
        "| model | LOD levels | triangles in the file | mean triangles drawn per frame | share of level 0 alone "
        "| the same, camera outside the bounding sphere | share | fps | fps by CPU time | fps ratio | fps-by-CPU ratio |",
        "|---|---|---|---|---|---|---|---|---|---|---|",
        path_row(e2, "level 0 alone (no LOD)", os.path.join(e2, "level0"), "–"),
        path_row(e2, "the paper's list (%s %%)" % LEVELS, paper, val("lod_levels", paper + ".run1")),
        path_row(e2, "screen-space chain (default)", chain, val("lod_levels", chain + ".run1"))])


def set_levels(prefix):
    """Every level of a set: its range, and the frames of the path that drew it."""
    level, drawn, count = {}, {}, 0.0
    for words in raw.rows(prefix + ".run1"):
        field = lambda i: words[i] if i < len(words) else ""
        if words and words[0] == "level":
            level[field(1)] = (field(3), field(5), field(6))
            count = num.number(field(1)) + 1
        if words and words[0] == "path_level":
            drawn[field(1)] = (field(3), field(5), field(7), field(9), field(11))
    lines = ["| level | triangles | drawn from | to (mm) | frames of the path that drew it | first–last frame "
             "| camera distance of those frames (mm) |", "|---|---|---|---|---|---|---|"]
    k = 0
    while k < count:
        tri, near, far = level.get(str(k), ("", "", ""))
        frames, first, last, d0, d1 = drawn.get(str(k), ("", "", "", "", ""))
        seen = num.truthy(frames)
        g = lambda text: num.fmt(".4g", num.number(text))
        lines.append("| %d | %s | %s | %s | %d | %s | %s |" % (
            k, tri, g(near), "never" if num.number(far) >= 1e29 else g(far), num.integer(num.number(frames)),
            first + "–" + last if seen else "–", g(d0) + " – " + g(d1) if seen else "–"))
        k += 1
    return "\n".join(lines)


def path_note(e2, near, far, frames):
    """Where the path runs, against the size of the model and the first switch of each set."""
    radius, first = "", {}
    for path in (os.path.join(e2, "paper.run1"), os.path.join(e2, "chain.run1")):
        for words in raw.rows(path):
            second = words[1] if len(words) > 1 else ""
            if words and words[0] == "radius":
                radius = second
            if words and words[0] == "level" and num.looks_numeric(second) and num.number(second) == 1:
                first["chain" if "chain" in path else "paper"] = words[5] if len(words) > 5 else ""
    r, f = num.number(radius), num.fmt
    return ("The path: %d frames; the camera orbits the assembly once while it backs away, log-spaced, from %s mm "
            "to %s mm from the centre. The bounding radius is %s mm: the whole assembly fills the 45° view from "
            "%s mm. The path starts closer, at half the first switch distance, because both sets switch level 0 out "
            "already at %s mm (the paper's list) and %s mm (the chain), inside the assembly. It ends 1.25 times "
            "beyond the last switch between levels of either set.") % (
        num.integer(num.number(frames)), f(".3g", num.number(near)), f(".4g", num.number(far)), f(".4g", r),
        f(".3g", r / 0.41421356), f(".3g", num.number(first.get("paper"))), f(".3g", num.number(first.get("chain"))))


# ---------------------------------------------------------------- the page
def command_output(argv):
    try:
        done = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, check=False)
    except OSError:
        return ""
    return done.stdout.decode("utf-8", "surrogateescape").rstrip("\n")


def cpu_name():
    for line in num.lines(raw.read_text("/proc/cpuinfo") or ""):
        if "model name" in line:
            pieces = line.split(":")
            return pieces[1].lstrip(" ") if len(pieces) > 1 else ""
    return ""


def renderer(run1):
    for words in raw.rows(run1):
        if words and words[0] == "gl_renderer":
            return " ".join(words[1:])
    return ""


def figures(work, state):
    """Every placeholder of the template, from the work directory and the run's state."""
    e1, e2 = os.path.join(work, "exp1"), os.path.join(work, "exp2")
    near, far = raw.path_range(e2)
    chain_run = os.path.join(e2, "chain.run1")
    notes = [reduction_note("MeshLab QEM", os.path.join(e1, "stock"), os.path.join(e1, "original")),
             reduction_note("cadlod", os.path.join(e1, "cadlod"), os.path.join(e1, "original")), fig6_summary(e1)]
    return {
        "date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d"),
        "nproc": command_output(["nproc"]),
        "cpu": cpu_name(),
        "osg_version": command_output(["dpkg-query", "-W", "-f=${Version}", "libopenscenegraph-dev"]),
        "renderer": renderer(chain_run),
        "stock_filter": STOCK_FILTER,
        "cad_route": state["cad_route"],
        "compactness_rows": "\n".join(compactness_row(name, os.path.join(e1, mesh)) for mesh, name in
                                      (("original", "original"), ("stock", "MeshLab QEM"), ("cadlod", "cadlod"))),
        "reduction_notes": "\n".join(notes),
        "shading_rows": "\n".join([shading_row("MeshLab QEM", os.path.join(e1, "stock")),
                                   shading_row("cadlod", os.path.join(e1, "cadlod"))]),
        "shading_views": shading_views(e1),
        "level_route": state["level_route"],
        "frames": state["frames"],
        "runs": state["runs"],
        "table1": table1(e2),
        "paper_set_route": state["paper_set_route"],
        "chain_set_route": state["chain_set_route"],
        "levels": LEVELS,
        "path_note": path_note(e2, near, far, state["frames"]),
        "outside_frames": val("path_outside_frames", chain_run),
        "radius": num.bash_fixed(0, val("radius", chain_run)),
        "path_table": path_table(e2),
        "paper_levels": set_levels(os.path.join(e2, "paper")),
        "chain_levels": set_levels(os.path.join(e2, "chain")),
    }


def fill(template, values):
    """The template with every @name@ replaced, in one pass; a name without a value is an error."""
    return re.sub(r"@([a-z0-9_]+)@", lambda m: values[m.group(1)], template)


def write(work, doc):
    state = raw.load_state(work)
    with open(TEMPLATE, encoding="utf-8") as stream:
        template = stream.read()
    page = fill(template, figures(work, state))
    with open(doc, "wb") as stream:
        stream.write(page.encode("utf-8", "surrogateescape"))
