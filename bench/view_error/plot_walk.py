#!/usr/bin/env python3
"""Plots the triangles share and the worst error on screen along the walk, one line per file,
from the CSV `view_error --walk-csv` writes; the estimates' shares, when present, dashed: the
per-cluster estimate in black, the estimate with long triangles held in grey.

Draws with matplotlib when it is installed, else with gnuplot, else writes an SVG by hand.
The output's format follows its extension (.png or .svg; the hand-written SVG is always SVG).
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys
import tempfile


def read_walk(path):
    """Rows by file, in the CSV's order: {file: [row dict, ...]}."""
    series = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            series.setdefault(row["file"], []).append(row)
    return series


def column(rows, name):
    return [float(r[name]) for r in rows if r[name] != ""]


# The dashed reference curves: (CSV column, legend, colour).
ESTIMATES = [("estimate_share", "estimate", "black"), ("held_estimate_share", "held estimate", "grey")]


def estimates_in(series):
    """The reference curves the CSV holds (an older CSV has no held estimate)."""
    rows = [r for rows in series.values() for r in rows]
    return [e for e in ESTIMATES if any(r.get(e[0]) for r in rows)]


def plot_matplotlib(series, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(9, 7))
    for name, rows in series.items():
        index = column(rows, "index")
        label = os.path.basename(name)
        top.plot(index, column(rows, "triangles_share"), label=label)
        bottom.plot(index, column(rows, "worst_px"), label=label)
    rows = next(iter(series.values()))
    for key, label, colour in estimates_in(series):
        top.plot(column(rows, "index"), column(rows, key), "--", color=colour, label=label)
    top.set_ylabel("triangles share of level 0")
    bottom.set_ylabel("worst error (px)")
    bottom.set_xlabel("walk point")
    top.legend()
    fig.savefig(out)


def gnuplot_script(series, data_files, out):
    terminal = "svg size 900,700" if out.endswith(".svg") else "pngcairo size 900,700"
    lines = [f"set terminal {terminal}", f"set output '{out}'", "set datafile separator ','",
             "set termoption noenhanced", "set multiplot layout 2,1", "set key outside right",
             "set ylabel 'triangles share of level 0'"]
    share = [f"'{d}' using 1:2 with lines title '{os.path.basename(n)}'" for n, d in zip(series, data_files)]
    for i, (_, label, colour) in enumerate(estimates_in(series)):
        share.append(f"'{data_files[0]}' using 1:{4 + i} with lines dashtype 2 lc '{colour}' title '{label}'")
    lines.append("plot " + ", ".join(share))
    lines += ["set ylabel 'worst error (px)'", "set xlabel 'walk point'"]
    worst = [f"'{d}' using 1:3 with lines title '{os.path.basename(n)}'" for n, d in zip(series, data_files)]
    lines += ["plot " + ", ".join(worst), "unset multiplot"]
    return "\n".join(lines) + "\n"


def plot_gnuplot(series, out):
    estimates = [key for key, _, _ in estimates_in(series)]
    with tempfile.TemporaryDirectory() as tmp:
        data_files = []
        for i, rows in enumerate(series.values()):
            path = os.path.join(tmp, f"walk{i}.csv")
            with open(path, "w", newline="") as f:
                writer = csv.writer(f)
                for r in rows:
                    writer.writerow([r["index"], r["triangles_share"], r["worst_px"]] + [r[key] for key in estimates])
            data_files.append(path)
        subprocess.run(["gnuplot"], input=gnuplot_script(series, data_files, out), text=True, check=True)


COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"]


def svg_panel(curves, top, height, width, label):
    """One panel's SVG: curves is [(points, colour, dashed)], points [(x, y)]."""
    xs = [x for points, _, _ in curves for x, _ in points]
    ys = [y for points, _, _ in curves for _, y in points]
    x0, x1, y1 = min(xs), max(xs), max(ys) or 1.0
    left, right = 70, width - 200

    def at(x, y):
        return (left + (x - x0) / ((x1 - x0) or 1.0) * (right - left), top + height - y / y1 * height)

    parts = [f'<rect x="{left}" y="{top}" width="{right - left}" height="{height}" '
             'fill="none" stroke="black"/>',
             f'<text x="{left}" y="{top - 6}" font-size="13">{label} (0 to {y1:.3g})</text>']
    for points, colour, dashed in curves:
        path = " ".join(f"{px:.1f},{py:.1f}" for px, py in (at(x, y) for x, y in points))
        dash = ' stroke-dasharray="6,4"' if dashed else ""
        parts.append(f'<polyline points="{path}" fill="none" stroke="{colour}"{dash}/>')
    return parts


def plot_svg(series, out):
    width, height = 900, 700
    share, worst, legend = [], [], []
    for i, (name, rows) in enumerate(series.items()):
        colour = COLOURS[i % len(COLOURS)]
        index = column(rows, "index")
        share.append((list(zip(index, column(rows, "triangles_share"))), colour, False))
        worst.append((list(zip(index, column(rows, "worst_px"))), colour, False))
        legend.append((os.path.basename(name), colour))
    rows = next(iter(series.values()))
    for key, label, colour in estimates_in(series):
        share.append((list(zip(column(rows, "index"), column(rows, key))), colour, True))
        legend.append((label, colour))
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}">',
             '<rect width="100%" height="100%" fill="white"/>']
    parts += svg_panel(share, 40, 270, width, "triangles share of level 0")
    parts += svg_panel(worst, 380, 270, width, "worst error (px) along the walk")
    for i, (name, colour) in enumerate(legend):
        parts.append(f'<text x="{width - 190}" y="{60 + 18 * i}" font-size="12" '
                     f'fill="{colour}">{name}</text>')
    parts.append("</svg>")
    with open(out, "w") as f:
        f.write("\n".join(parts) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("csv", help="the CSV of view_error --walk-csv")
    parser.add_argument("-o", "--output", default="walk.png", help="the picture (.png or .svg)")
    args = parser.parse_args()
    series = read_walk(args.csv)
    if not series:
        sys.exit(f"plot_walk: {args.csv} has no rows")
    try:
        import matplotlib  # noqa: F401
        plot_matplotlib(series, args.output)
    except ImportError:
        if shutil.which("gnuplot"):
            plot_gnuplot(series, args.output)
        else:
            out = os.path.splitext(args.output)[0] + ".svg"
            plot_svg(series, out)
            args.output = out
    print(args.output)


if __name__ == "__main__":
    main()
