#!/usr/bin/env python3
"""Reproduces the two experiments of the paper (Tang et al. 2015, §5) on the bundled samples
and regenerates docs/paper-reproduction.md with its pictures (docs/img/paper-*.png):
 - Experiment 1 (Fig. 6): docs/sample/shaft.wrl reduced by 90 % with MeshLab's stock
   "Quadric Edge Collapse Decimation" (defaults) and with cadlod's CAD Quadric Edge
   Collapse (defaults): shaded and wireframe pictures, compactness histograms and
   numbers, symmetric Hausdorff distance to the original, and the shading-error measure
   (bench/shading) with its difference images.
 - Experiment 2 (Table 1): docs/sample/cad_assembly.wrl.gz at 0/50/60/70/80/90 %
   reduction: triangles, .flt size, OpenSceneGraph load time and frame rate of every level
   alone, as ratios against level 0 next to the paper's; then two whole LOD sets, the
   paper's list and the screen-space chain, along one camera path that backs away across
   every switch distance: triangles drawn per frame and per level (bench/lod_path) and
   frame rate.
Everything runs through the staged meshlabserver with cadlod's plugins; rendering is
OpenSceneGraph (bench/paper/osg_render) on a private Xvfb (Mesa software GL).

Environment: CADLOD_BUILD_DIR (default build/; configured with -DCADLOD_BUILD_BENCH=ON),
PAPER_FRAMES (frames per frame-rate run, default 300), PAPER_RUNS (runs per figure,
median kept, default 5). Writes only docs/img/paper-*.png, docs/paper-reproduction.md and
$CADLOD_BUILD_DIR/paper-reproduction/ (raw outputs, logs, and routes.json: the settings
and routes of the run, from which --document-only writes the page again).
"""
import argparse
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import document  # noqa: E402
import experiments  # noqa: E402
import raw_outputs  # noqa: E402
import settings as paper_settings  # noqa: E402
from runner import Tools, die, say  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def arguments():
    parser = argparse.ArgumentParser(description="Reproduce the paper's experiments and write "
                                                 "docs/paper-reproduction.md.")
    parser.add_argument("--document-only", action="store_true",
                        help="only write the page from the raw outputs of an earlier run")
    parser.add_argument("--work", help="the work directory of that run (default: "
                                       "$CADLOD_BUILD_DIR/paper-reproduction)")
    parser.add_argument("--output", help="where to write the page (default: docs/paper-reproduction.md)")
    return parser.parse_args()


def measure(setup):
    """Builds the tools, runs both experiments and records what the page needs besides the
    raw outputs."""
    work = setup.work
    os.makedirs(work, exist_ok=True)
    os.makedirs(setup.img, exist_ok=True)
    tools = Tools(setup)
    for log in (tools.mls_log, tools.render_log):
        open(log, "wb").close()
    tools.build()
    tools.start_xvfb()
    try:
        tools.list_filters()
        experiments.experiment1(tools)
        routes = experiments.experiment2(tools)
    finally:
        tools.stop_xvfb()
    # The page names the route of the last simplification for both experiments.
    raw_outputs.save_state(work, dict(frames=setup.frames, runs=setup.runs, **routes))


def main():
    args = arguments()
    setup = paper_settings.from_environment(ROOT)
    if not setup.runs.isdigit():
        die("PAPER_RUNS must be a whole number, not %r" % setup.runs)
    if args.work and not args.document_only:
        die("--work reads an earlier run: use it with --document-only")
    work, doc = args.work or setup.work, args.output or setup.doc
    if not args.document_only:
        measure(setup)
    document.write(work, doc)
    say("wrote %s" % doc if args.document_only else "wrote %s and %s/paper-fig6-*.png" % (doc, setup.img))


if __name__ == "__main__":
    main()
