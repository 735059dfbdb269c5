// Shading and accuracy of cadlod's simplifier against its peers on real CAD parts (issue 14):
// every corpus PLY (scripts/make_cad_corpus.sh, bench/corpus/README.md) and two bench
// meshes of tests/simplify/cad_meshes.h, at several reductions, each tool in a forked process.
// Per reduction, one Markdown table with a row per part: cadlod's figures and its ratio to
// the best peer on that part; then a summary line in issue 14's terms.
//
//   corpus_bench [--corpus DIR]            default .cache/cad-corpus
//                [--parts GLOB,GLOB...]    part names (file stem, e.g. lqfp64_fine, bench_shaft)
//                [--reductions 50,75,90,95]
//                [--tools cadlod,vcglib,vcglib-cad,cgal,meshopt]  (cadlod is always run)
//                [--quick]                 6 tuning parts, reductions 75,95
//                [--no-bench-meshes] [--resolution 256] [--raw FILE] [--images DIR]
//                [--same-count]            every peer gets cadlod's resulting face count as its target
//                [--files FILE,...]        more inputs: VRML (assemblies, one part per VRML part) or PLY
//                [--far-field]             issue 13's far-field check, see below
//                [--log]                   cadlod's log of every run (what gave way) to stderr
//                [--part-borders]          cadlod keeps part borders (keepPartBorders, off by default)
//                [--feature-penalty X] [--shading-weight X] [--large-face-weight X]
//                [--tie-tolerance X] [--quality-threshold X] [--shading-angle DEG] [--boundary-weight X]
//                [--min-compactness X] [--feature-angle DEG] [--candidates N] [--sliver-count-share X]
//                [--trials-max-faces N]    (0: no weight trials, one run with the weights given)
//                                          cadlod's SimplifyParams of those names (tuning sweeps)
//                [--meshes DIR]            every input and result as PLY (DIR/<part>_input.ply,
//                                          DIR/<part>_<reduction>_<tool>.ply), to look into a loss
// --raw writes every tool's row (one Markdown table); --images writes the shading
// difference images of every run (use with --parts).
//
// --far-field: cadlod against meshoptimizer at 99 and 99.5 % on the demo assembly, the bench
// assembly, the bench board, the bench shaft and the corpus, meshoptimizer at cadlod's face
// count (--same-count); one table of both tools' Hausdorff and silhouette mismatch instead
// of the per-reduction tables. With --quick, only the quick corpus parts.
#include "cad_meshes.h"
#include "mesh_checks.h"
#include "peer_cgal.h"
#include "forked_run.h"
#include "indexed_mesh.h"
#include "mesh_loading.h"
#include "peer_meshopt.h"
#include "stock_quadric.h"
#include "test_mesh.h"

#include "ply_read.h"
#include "shading_error.h"

#include "measure/compactness.h"
#include "measure/hausdorff.h"
#include "simplify/best_of_trials.h"

#include <vcg/complex/algorithms/update/normal.h>

#include <fnmatch.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using cadlod::test::TestMesh;
using cadlod::test::toIndexed;

namespace {

struct Part {
    std::string name;
    bool heldOut = false;
    std::function<bool(TestMesh&)> build;
};

struct Row {
    bool ok = false;
    int in = 0, target = 0, out = 0;
    double seconds = 0;
    double peakMb = 0;
    double visible = 0, silhouette = 0, meanDelta = 0;  // shading
    double hMax = 0, hMean = 0;                          // % of diagonal
    double slivers = 0;                                   // % of faces, compactness < 0.1
    int folded = 0, newNonManifold = 0;
};

std::vector<std::string> split(const std::string& s)
{
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty())
            out.push_back(item);
    return out;
}

double secondsSince(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// A PLY of the corpus as a TestMesh, with its solids as cadlod part ids.
bool loadCorpusPly(const std::string& path, TestMesh& m)
{
    cadlod::shading::IndexedMesh im;
    std::vector<int> parts;
    std::string error;
    if (!cadlod::shading::readPly(path, im, error, &parts)) {
        std::fprintf(stderr, "%s: %s\n", path.c_str(), error.c_str());
        return false;
    }
    m.Clear();
    auto vi = vcg::tri::Allocator<TestMesh>::AddVertices(m, int(im.xyz.size() / 3));
    for (std::size_t v = 0; v < im.xyz.size() / 3; ++v, ++vi)
        vi->P() = vcg::Point3f(float(im.xyz[3 * v]), float(im.xyz[3 * v + 1]), float(im.xyz[3 * v + 2]));
    auto fi = vcg::tri::Allocator<TestMesh>::AddFaces(m, int(im.tri.size() / 3));
    for (std::size_t f = 0; f < im.tri.size() / 3; ++f, ++fi)
        for (int k = 0; k < 3; ++k)
            fi->V(k) = &m.vert[im.tri[3 * f + k]];
    if (std::set<int>(parts.begin(), parts.end()).size() > 1) {
        auto h = vcg::tri::Allocator<TestMesh>::GetPerFaceAttribute<int>(m, cadlod::kPartAttribute);
        for (std::size_t f = 0; f < parts.size(); ++f)
            h[f] = parts[f];
    }
    return true;
}

// What cadlod's log says about a run (the filter's log lines), for looking into a loss.
void printSimplifyLog(const std::string& what, const cadlod::SimplifyStats& s)
{
    std::fprintf(stderr, "%s: %d -> %d faces (target %d), stopped by %s; feature breaks %d, components removed %d; "
                         "largest error %.4g %% of the diagonal; refused: %d feature, %d flip, %d topology, %d shape\n",
                 what.c_str(), s.facesBefore, s.facesAfter, s.targetFaces, s.stoppedBy.c_str(), s.featureBreaks,
                 s.removedComponents, 100 * s.largestErrorFraction(), s.rejectedFeature, s.rejectedFlip,
                 s.rejectedTopology, s.rejectedCompactness);
    if (!s.weightTrials.empty())
        std::fprintf(stderr, "  %s\n", s.weightTrials.c_str());
    for (const std::string& line : s.relaxed)
        std::fprintf(stderr, "  %s\n", line.c_str());
}

// cadlod's parameters but for the face target: the defaults, or as the options set them.
cadlod::SimplifyParams cadlodParams;

// `logAs`: when not empty, cadlod's log goes to stderr under that name.
void simplifyWith(const std::string& tool, TestMesh& m, int target, double& seconds, const std::string& logAs = {})
{
    if (tool == "cgal") {
        cadlod::bench::CgalMesh sm = cadlod::bench::toCgal(m);
        const auto t = std::chrono::steady_clock::now();
        cadlod::bench::cgalSimplify(sm, target);
        seconds = secondsSince(t);
        cadlod::bench::fromCgal(sm, m);
        return;
    }
    if (tool == "vcglib" || tool == "vcglib-cad")  // MeshLab has normals on every loaded mesh
        vcg::tri::UpdateNormal<TestMesh>::PerVertexNormalizedPerFaceNormalized(m);
    const auto t = std::chrono::steady_clock::now();
    if (tool == "cadlod") {
        cadlod::SimplifyParams p = cadlodParams;
        p.targetFaces = target;
        const cadlod::SimplifyStats stats = cadlod::bestOfTrials(m, p);
        if (!logAs.empty())
            printSimplifyLog(logAs, stats);
    } else if (tool == "vcglib") {
        cadlod::test::stockSimplify(m, target, cadlod::test::stockDefaults<TestMesh>());
    } else if (tool == "vcglib-cad") {
        // MeshLab's dialog with the options a CAD user ticks: planar simplification, normal
        // check, preserve topology, preserve boundary.
        vcg::tri::TriEdgeCollapseQuadricParameter pp = cadlod::test::stockDefaults<TestMesh>();
        pp.QualityQuadric = true;
        pp.NormalCheck = true;
        pp.PreserveTopology = true;
        pp.PreserveBoundary = true;
        cadlod::test::stockSimplify(m, target, pp);
    } else if (tool == "meshopt") {
        cadlod::bench::meshoptSimplify(m, target);
    }
    seconds = secondsSince(t);
}

// Resident memory figures of this process, kB ("VmRSS", "VmHWM").
long statusKb(const char* key)
{
    std::ifstream in("/proc/self/status");
    for (std::string line; std::getline(in, line);)
        if (line.rfind(key, 0) == 0)
            return std::atol(line.c_str() + std::strlen(key) + 1);
    return 0;
}

struct PartContext {
    const Part* part = nullptr;
    TestMesh* original = nullptr;
    const cadlod::shading::Reference* reference = nullptr;
    int originalNonManifold = 0;
    std::string imageDir;
    bool log = false;     // cadlod's log of every run to stderr
    std::string meshDir;  // inputs and results as PLY (empty: none)
};

std::string reductionText(double reduction)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", reduction);
    return buf;
}

// `target` 0: the face count of `reduction`.
Row runOne(const PartContext& ctx, const std::string& tool, double reduction, int target)
{
    Row r;
    TestMesh m;
    if (!ctx.part->build(m))
        return r;
    r.in = m.fn;
    r.target = target > 0 ? target : int(std::lround(m.fn * (1.0 - reduction / 100.0)));
    // Peak memory of this run above what the process held before it (the parent's input
    // mesh and renders are shared): reset the high-water mark, Linux >= 4.0.
    {
        std::ofstream clear("/proc/self/clear_refs");
        clear << "5";
    }
    const long baseKb = statusKb("VmRSS:");
    simplifyWith(tool, m, r.target, r.seconds,
                 ctx.log ? ctx.part->name + " " + reductionText(reduction) + " %" : std::string());
    r.peakMb = std::max(0L, statusKb("VmHWM:") - baseKb) / 1024.0;
    r.out = m.fn;

    vcg::tri::Allocator<TestMesh>::CompactEveryVector(m);
    if (!ctx.meshDir.empty())
        cadlod::test::savePly(ctx.meshDir + "/" + ctx.part->name + "_" + reductionText(reduction) + "_" + tool + ".ply", m);
    const cadlod::shading::IndexedMesh im = toIndexed(m);
    std::string prefix;
    if (!ctx.imageDir.empty())
        prefix = ctx.imageDir + "/" + ctx.part->name + "_" + reductionText(reduction) + "_" + tool + "_";
    const cadlod::shading::Result s = ctx.reference->compare(im.ref(), prefix);
    r.visible = s.visiblePercent;
    r.silhouette = s.silhouettePercent;
    r.meanDelta = s.meanAbsDelta;
    const std::size_t samples = std::min<std::size_t>(ctx.original->fn, 1000000);
    const cadlod::SymmetricHausdorff h = cadlod::symmetricHausdorff(*ctx.original, m, samples);
    r.hMax = 100 * h.maxFraction();
    r.hMean = 100 * h.meanFraction();
    r.slivers = 100 * cadlod::meshCompactness(m).shareBelow01;
    r.folded = cadlod::test::foldedFaces(m, *ctx.original, 90.0);
    r.newNonManifold = std::max(0, cadlod::test::nonManifoldEdges(m) - ctx.originalNonManifold);
    r.ok = true;
    return r;
}

// A run's time limit: a minute, plus a second per 2 000 input triangles (4M: 35 min). Far
// beyond any tool's time on the corpus; it only stops a peer that loops.
unsigned timeLimitSeconds(int triangles) { return 60u + unsigned(triangles / 2000); }

Row runForked(const PartContext& ctx, const std::string& tool, double reduction, int target)
{
    bool timedOut = false;
    const unsigned limit = timeLimitSeconds(ctx.original->fn);
    const Row r = cadlod::bench::runForked<Row>([&] { return runOne(ctx, tool, reduction, target); }, limit,
                                                &timedOut);
    if (timedOut)
        std::fprintf(stderr, "%s on %s at %g %%: stopped after %u s (counted as failed)\n", tool.c_str(),
                     ctx.part->name.c_str(), reduction, limit);
    return r;
}

std::set<std::string> heldOutIds(const std::string& manifest)
{
    std::set<std::string> ids;
    std::ifstream in(manifest);
    for (std::string line; std::getline(in, line);) {
        std::istringstream words(line);
        std::string id, splitName;
        if (words >> id >> splitName && id[0] != '#' && splitName == "heldout")
            ids.insert(id);
    }
    return ids;
}

std::vector<Part> corpusParts(const std::string& dir, const std::set<std::string>& heldOut)
{
    std::vector<std::string> files;
    if (DIR* d = opendir((dir + "/ply").c_str())) {
        while (const dirent* e = readdir(d)) {
            const std::string name = e->d_name;
            if (name.size() > 4 && name.compare(name.size() - 4, 4, ".ply") == 0)
                files.push_back(name);
        }
        closedir(d);
    }
    std::sort(files.begin(), files.end());
    std::vector<Part> parts;
    for (const std::string& f : files) {
        Part p;
        p.name = f.substr(0, f.size() - 4);
        const std::string id = p.name.substr(0, p.name.rfind('_'));
        p.heldOut = heldOut.count(id) > 0;
        const std::string path = dir + "/ply/" + f;
        p.build = [path](TestMesh& m) { return loadCorpusPly(path, m); };
        parts.push_back(p);
    }
    return parts;
}

std::vector<Part> benchParts(bool withBoard)
{
    std::vector<Part> parts;
    // The 24k-triangle stepped shaft and the small assembly of simplify_bench.
    parts.push_back({"bench_shaft", false, [](TestMesh& m) {
                         cadlod::test::CadBuilder b;
                         cadlod::test::revolve(b, cadlod::test::shaftProfile(2.0), cadlod::test::shaftSpec(1200, 1));
                         b.build(m);
                         return true;
                     }});
    parts.push_back({"bench_assembly", false, [](TestMesh& m) {
                         cadlod::test::CadBuilder b;
                         cadlod::test::assembly(b, 256);
                         b.build(m, true);
                         return true;
                     }});
    if (withBoard)  // the KiCad-like board of issue 14, wrecked at 90 % before features were priced
        parts.push_back({"bench_board", false, [](TestMesh& m) {
                             cadlod::test::CadBuilder b;
                             cadlod::test::circuitBoard(b);
                             b.build(m, true);
                             return true;
                         }});
    return parts;
}

// Inputs named on the command line, by file name without its extensions.
std::vector<Part> fileParts(const std::vector<std::string>& files)
{
    std::vector<Part> parts;
    for (const std::string& path : files) {
        std::string name = path.substr(path.find_last_of('/') + 1);
        name = name.substr(0, name.find('.'));
        parts.push_back({name, false, [path](TestMesh& m) {
                             std::string error;
                             if (cadlod::bench::loadMesh(path, m, error))
                                 return true;
                             std::fprintf(stderr, "%s: %s\n", path.c_str(), error.c_str());
                             return false;
                         }});
    }
    return parts;
}

bool matches(const std::string& name, const std::vector<std::string>& globs)
{
    if (globs.empty())
        return true;
    for (const std::string& g : globs)
        if (fnmatch(g.c_str(), name.c_str(), 0) == 0)
            return true;
    return false;
}

std::string ratioText(double mine, double best)
{
    char buf[32];
    if (best <= 0)
        std::snprintf(buf, sizeof buf, mine <= 0 ? "1.00" : "inf");
    else
        std::snprintf(buf, sizeof buf, "%.2f", mine / best);
    return buf;
}

double ratio(double mine, double best) { return best <= 0 ? (mine <= 0 ? 1.0 : 1e9) : mine / best; }

// A peer counts for "best" only when it reached the face target (within 2 % + 2 faces):
// stopping short keeps more of the surface and would be an unfair yardstick.
bool reached(const Row& r) { return r.ok && r.out <= r.target + std::max(2.0, 0.02 * r.target); }

// The best figures on one part among the tools `counts(tool, row)` accepts, each measure on
// its own (the best shading and the best Hausdorff may come from different tools).
struct BestOf {
    double visible = 1e300, hMax = 1e300, slivers = 1e300;
    std::string visibleTool, hTool, sliverTool;  // empty: no tool counted
};

template <class Counts>
BestOf bestOf(const std::vector<std::string>& tools, std::map<std::string, Row>& rows, Counts counts)
{
    BestOf b;
    for (const std::string& tool : tools) {
        const Row& r = rows[tool];
        if (!counts(tool, r))
            continue;
        if (r.visible < b.visible) b.visible = r.visible, b.visibleTool = tool;
        if (r.hMax < b.hMax) b.hMax = r.hMax, b.hTool = tool;
        if (r.slivers < b.slivers) b.slivers = r.slivers, b.sliverTool = tool;
    }
    return b;
}

// Issue 14's bars: shading within 1.1× of the best or under 0.2 % of the pixels, Hausdorff
// within 1.1×, slivers within 1 point.
bool shadingWithin(const Row& r, const BestOf& b) { return ratio(r.visible, b.visible) <= 1.1 || r.visible <= 0.2; }
bool hausdorffWithin(const Row& r, const BestOf& b) { return ratio(r.hMax, b.hMax) <= 1.1; }
bool sliversWithin(const Row& r, const BestOf& b) { return r.slivers - b.slivers <= 1.0; }

// Per tool, on how many parts it is within issue 14's tolerances of the best of the other
// tools (shading ≤ 1.1× or ≤ 0.2 %, Hausdorff ≤ 1.1×): where the bar of the targets, the
// best of all the others, stands for each simplifier, cadlod's peers included. Only tools
// that reached the face target count as "others"; a tool short of it is not within.
void printWithinBestOfOthers(const std::vector<std::string>& tools, std::vector<std::map<std::string, Row>>& parts)
{
    std::printf("\nEach tool within 1.1× of the best of the others (shading ok / Hausdorff ok / parts):");
    for (const std::string& tool : tools) {
        int judged = 0, shadingOk = 0, hausdorffOk = 0;
        for (std::map<std::string, Row>& rows : parts) {
            const BestOf best =
                bestOf(tools, rows, [&](const std::string& other, const Row& r) { return other != tool && reached(r); });
            if (best.hTool.empty() || !rows[tool].ok)
                continue;
            const Row& r = rows[tool];
            ++judged;
            shadingOk += reached(r) && shadingWithin(r, best);
            hausdorffOk += reached(r) && hausdorffWithin(r, best);
        }
        std::printf("%s %s %d/%d/%d", tool == tools.front() ? "" : ";", tool.c_str(), shadingOk, hausdorffOk, judged);
    }
    std::printf(".\n");
}

// cadlod against the peers that keep issue 14's other rules on the same part: no more faces
// turned over 90° from the input than cadlod's, no new non-manifold edge. A peer that
// reaches a lower Hausdorff distance by collapsing a chip's lead across its bend (turned
// faces) or by pinching two sheets together (non-manifold edges) sets a bar cadlod is not
// allowed to reach that way; this line shows the same targets judged without those bars.
struct CleanPeerCounts {
    int judged = 0, shadingOk = 0, hausdorffOk = 0, sliverOk = 0, hausdorffAbove15 = 0;
    void add(const CleanPeerCounts& o)
    {
        judged += o.judged, shadingOk += o.shadingOk, hausdorffOk += o.hausdorffOk, sliverOk += o.sliverOk;
        hausdorffAbove15 += o.hausdorffAbove15;
    }
};

CleanPeerCounts againstCleanPeers(const std::vector<std::string>& tools, std::vector<std::map<std::string, Row>>& parts)
{
    CleanPeerCounts n;
    for (std::map<std::string, Row>& rows : parts) {
        const Row& c = rows["cadlod"];
        if (!c.ok)
            continue;
        const BestOf best = bestOf(tools, rows, [&](const std::string& tool, const Row& p) {
            return tool != "cadlod" && reached(p) && p.folded <= c.folded && p.newNonManifold == 0;
        });
        ++n.judged;
        if (best.hTool.empty()) {  // no peer keeps the rules: cadlod is the best that does
            n.shadingOk += reached(c), n.hausdorffOk += reached(c), n.sliverOk += reached(c);
            continue;
        }
        n.shadingOk += reached(c) && shadingWithin(c, best);
        n.hausdorffOk += reached(c) && hausdorffWithin(c, best);
        n.sliverOk += reached(c) && sliversWithin(c, best);
        n.hausdorffAbove15 += ratio(c.hMax, best.hMax) > 1.5;
    }
    return n;
}

void printAgainstCleanPeers(const char* what, const CleanPeerCounts& n)
{
    std::printf("\n%s against the peers that turn no more faces than cadlod and make no new non-manifold edge: "
                "shading ok %d/%d, Hausdorff ok %d/%d, slivers ok %d/%d; Hausdorff above 1.5× the best of them: %d.\n",
                what, n.shadingOk, n.judged, n.hausdorffOk, n.judged, n.sliverOk, n.judged, n.hausdorffAbove15);
}

// results[reduction][part][tool]
using Results = std::map<double, std::vector<std::map<std::string, Row>>>;

// The inputs issue 13 names for its far-field check.
bool issue13Input(const std::string& name)
{
    return name == "bench_assembly" || name == "bench_board" || name == "cad_assembly";
}

std::string farFieldVerdict(const Row& c, const Row& o)
{
    const bool hausdorff = c.hMax <= o.hMax, silhouette = c.silhouette <= o.silhouette;
    if (hausdorff && silhouette)
        return "yes";
    return std::string("**no**: ") + (hausdorff ? "" : "H") + (hausdorff || silhouette ? "" : ", ") +
           (silhouette ? "" : "silhouette");
}

// Issue 13's far-field check: per part and reduction, cadlod against meshoptimizer at
// cadlod's face count; "no worse" is cadlod's figure at most meshoptimizer's.
void printFarField(const std::vector<Part>& parts, const std::vector<double>& reductions, Results& results)
{
    std::printf("meshopt is given cadlod's resulting face count as its target (no error bound); both are measured "
                "against the input in the same run. H: symmetric Hausdorff, %% of the input's bbox diagonal; "
                "silhouette: %% of the covered pixels that only one image covers; visible: %% of the covered pixels "
                "a viewer sees differ (docs/shading_measure.md).\n\n");
    std::printf("| part | red. | tris in | faces cadlod | faces meshopt | H cadlod | H meshopt | silh. cadlod | "
                "silh. meshopt | visible cadlod | visible meshopt | cadlod no worse |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    struct Count {
        int pairs = 0, hausdorff = 0, silhouette = 0, both = 0;
    };
    std::map<double, Count> all, named;
    for (double red : reductions)
        for (std::size_t pi = 0; pi < parts.size(); ++pi) {
            const Row& c = results[red][pi]["cadlod"];
            const Row& o = results[red][pi]["meshopt"];
            const std::string name = parts[pi].name + (parts[pi].heldOut ? "*" : "");
            if (!c.ok || !o.ok) {
                std::printf("| %s | %g%% | failed |\n", name.c_str(), red);
                continue;
            }
            std::printf("| %s | %g%% | %d | %d | %d | %.3f | %.3f | %.2f | %.2f | %.2f | %.2f | %s |\n", name.c_str(),
                        red, c.in, c.out, o.out, c.hMax, o.hMax, c.silhouette, o.silhouette, c.visible, o.visible,
                        farFieldVerdict(c, o).c_str());
            for (Count* n : {&all[red], issue13Input(parts[pi].name) ? &named[red] : nullptr}) {
                if (!n)
                    continue;
                ++n->pairs;
                n->hausdorff += c.hMax <= o.hMax;
                n->silhouette += c.silhouette <= o.silhouette;
                n->both += c.hMax <= o.hMax && c.silhouette <= o.silhouette;
            }
        }
    for (double red : reductions) {
        const Count& a = all[red];
        const Count& n = named[red];
        std::printf("\n**%g %%:** cadlod no worse than meshopt on the demo and bench assembly and board: %d/%d "
                    "(Hausdorff %d/%d, silhouette %d/%d); on all inputs: %d/%d (Hausdorff %d/%d, silhouette %d/%d).\n",
                    red, n.both, n.pairs, n.hausdorff, n.pairs, n.silhouette, n.pairs, a.both, a.pairs, a.hausdorff,
                    a.pairs, a.silhouette, a.pairs);
    }
}

}  // namespace

int main(int argc, char** argv)
{
    std::string corpus = std::string(CADLOD_SOURCE_DIR) + "/.cache/cad-corpus";
    std::string reductionsText = "50,75,90,95", toolsText = "cadlod,vcglib,vcglib-cad,cgal,meshopt";
    std::string rawPath, imageDir, meshDir;
    std::vector<std::string> globs, files;
    bool quick = false, withBench = true, sameCount = false, farField = false, log = false;
    int resolution = 256;
    for (int i = 1; i < argc; ++i) {
        const std::string key = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) {
                std::fprintf(stderr, "%s needs a value\n", key.c_str());
                std::exit(2);
            }
            return argv[++i];
        };
        if (key == "--corpus") corpus = value();
        else if (key == "--parts") globs = split(value());
        else if (key == "--reductions") reductionsText = value();
        else if (key == "--tools") toolsText = value();
        else if (key == "--quick") quick = true;
        else if (key == "--no-bench-meshes") withBench = false;
        else if (key == "--resolution") resolution = std::stoi(value());
        else if (key == "--raw") rawPath = value();
        else if (key == "--images") imageDir = value();
        else if (key == "--meshes") meshDir = value();
        else if (key == "--same-count") sameCount = true;
        else if (key == "--files") files = split(value());
        else if (key == "--far-field") farField = true;
        else if (key == "--log") log = true;
        else if (key == "--part-borders") cadlodParams.keepPartBorders = true;
        else if (key == "--feature-penalty") cadlodParams.featurePenalty = std::stod(value());
        else if (key == "--shading-weight") cadlodParams.shadingWeight = std::stod(value());
        else if (key == "--large-face-weight") cadlodParams.largeFaceWeight = std::stod(value());
        else if (key == "--tie-tolerance") cadlodParams.tieTolerance = std::stod(value());
        else if (key == "--quality-threshold") cadlodParams.qualityThreshold = std::stod(value());
        else if (key == "--shading-angle") cadlodParams.shadingAngle = std::stod(value());
        else if (key == "--boundary-weight") cadlodParams.boundaryWeight = std::stod(value());
        else if (key == "--min-compactness") cadlodParams.minCompactness = std::stod(value());
        else if (key == "--sliver-count-share") cadlodParams.sliverCountShare = std::stod(value());
        else if (key == "--feature-angle") cadlodParams.featureAngle = std::stod(value());
        else if (key == "--candidates") cadlodParams.candidatesPerEdge = std::stoi(value());
        else if (key == "--trials-max-faces") cadlodParams.weightTrialsMaxFaces = std::stoi(value());
        else {
            std::fprintf(stderr, "unknown option %s (see the head of corpus_bench.cpp)\n", key.c_str());
            return 2;
        }
    }
    if (quick) {
        if (globs.empty())
            globs = {"lqfp64_fine", "cp_radial_d10_fine", "trafo_ei42_fine", "valve_pentode_fine",
                     "wemos_d1_mini_fine", "occt_linkrods_coarse"};
        reductionsText = "75,95";
    }
    if (farField) {
        reductionsText = "99,99.5";
        toolsText = "meshopt";
        sameCount = true;
        files.push_back(std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz");
        if (!globs.empty())
            globs.insert(globs.end(), {"bench_*", "cad_assembly"});
    }
    std::vector<std::string> tools = {"cadlod"};
    for (const std::string& t : split(toolsText))
        if (t != "cadlod" && std::find(tools.begin(), tools.end(), t) == tools.end()) {
            if (t != "vcglib" && t != "vcglib-cad" && t != "cgal" && t != "meshopt") {
                std::fprintf(stderr, "unknown tool %s\n", t.c_str());
                return 2;
            }
            tools.push_back(t);
        }
    std::string peerList;
    for (std::size_t i = 1; i < tools.size(); ++i)
        peerList += (i > 1 ? ", " : "") + tools[i];
    std::vector<double> reductions;
    for (const std::string& r : split(reductionsText))
        reductions.push_back(std::stod(r));

    std::vector<Part> all = fileParts(files);
    if (withBench) {
        const std::vector<Part> bench = benchParts(farField);
        all.insert(all.end(), bench.begin(), bench.end());
    }
    const std::vector<Part> corpusList =
        corpusParts(corpus, heldOutIds(std::string(CADLOD_SOURCE_DIR) + "/bench/corpus/manifest.txt"));
    if (corpusList.empty())
        std::fprintf(stderr, "note: no corpus PLY in %s/ply (scripts/make_cad_corpus.sh makes it)\n", corpus.c_str());
    all.insert(all.end(), corpusList.begin(), corpusList.end());
    std::vector<Part> parts;
    for (const Part& p : all)
        if (matches(p.name, globs))
            parts.push_back(p);
    if (parts.empty()) {
        std::fprintf(stderr, "no part selected\n");
        return 1;
    }

    Results results;
    for (double red : reductions)
        results[red].resize(parts.size());
    cadlod::shading::Options shadingOptions;
    shadingOptions.resolution = resolution;
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t pi = 0; pi < parts.size(); ++pi) {
        TestMesh original;
        if (!parts[pi].build(original))
            continue;
        if (!meshDir.empty())
            cadlod::test::savePly(meshDir + "/" + parts[pi].name + "_input.ply", original);
        const cadlod::shading::IndexedMesh input = toIndexed(original);
        const cadlod::shading::Reference reference(input.ref(), shadingOptions);
        PartContext ctx{&parts[pi], &original, &reference, cadlod::test::nonManifoldEdges(original), imageDir, log,
                       meshDir};
        for (double red : reductions)
            for (const std::string& tool : tools) {  // cadlod first: --same-count needs its result
                const int target = sameCount && tool != "cadlod" ? results[red][pi]["cadlod"].out : 0;
                results[red][pi][tool] = runForked(ctx, tool, red, target);
            }
        std::fprintf(stderr, "[%5.0f s] %zu/%zu %s (%d triangles)\n", secondsSince(start), pi + 1, parts.size(),
                     parts[pi].name.c_str(), original.fn);
    }

    if (!rawPath.empty()) {
        std::FILE* raw = std::fopen(rawPath.c_str(), "w");
        if (raw) {
            std::fprintf(raw, "| part | red. | tool | tris in | target | tris out | shading %% | silh. %% | mean |dI| | "
                              "H max %%diag | H mean %%diag | slivers %% | flipped | new non-manif. | s | peak MB |\n"
                              "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
            for (double red : reductions)
                for (std::size_t pi = 0; pi < parts.size(); ++pi)
                    for (const std::string& tool : tools) {
                        const Row& r = results[red][pi][tool];
                        if (!r.ok) {
                            std::fprintf(raw, "| %s | %g%% | %s | failed |\n", parts[pi].name.c_str(), red, tool.c_str());
                            continue;
                        }
                        std::fprintf(raw,
                                     "| %s%s | %g%% | %s | %d | %d | %d | %.3f | %.3f | %.2f | %.4f | %.5f | %.1f | %d | "
                                     "%d | %.3f | %.1f |\n",
                                     parts[pi].name.c_str(), parts[pi].heldOut ? "*" : "", red, tool.c_str(), r.in,
                                     r.target, r.out, r.visible, r.silhouette, r.meanDelta, r.hMax, r.hMean, r.slivers,
                                     r.folded, r.newNonManifold, r.seconds, r.peakMb);
                    }
            std::fclose(raw);
        }
    }

    if (farField) {
        printFarField(parts, reductions, results);
        std::printf("\nWall time %.0f s.\n", secondsSince(start));
        return 0;
    }
    std::printf("Parts marked * are held out (bench/corpus/manifest.txt). Ratios are cadlod / best peer on the part "
                "(peers: %s, counted only when they reached the face target); slivers: cadlod minus best, in points.\n",
                peerList.c_str());
    struct Totals {
        int pairs = 0, shadingOk = 0, hausdorffOk = 0, sliverOk = 0, reachedTarget = 0, flips = 0, flipParts = 0;
        int noPeer = 0;
        double worstShading = 0, worstHausdorff = 0, worstSliver = -1e9;
        std::string worstShadingPart, worstHausdorffPart, worstSliverPart;
    };
    Totals overall;
    CleanPeerCounts cleanOverall;
    for (double red : reductions) {
        std::printf("\n### %g %% reduction\n\n", red);
        std::printf("| part | tris in | out | shading %% | ×best | mean |ΔI| | H max %%diag | ×best | H mean %%diag | "
                    "slivers %% | −best | flipped | new NM | s | MB |\n");
        std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
        Totals t;
        for (std::size_t pi = 0; pi < parts.size(); ++pi) {
            const Row& c = results[red][pi]["cadlod"];
            const std::string name = parts[pi].name + (parts[pi].heldOut ? "*" : "");
            if (!c.ok) {
                std::printf("| %s | failed |\n", name.c_str());
                continue;
            }
            const BestOf best = bestOf(tools, results[red][pi],
                                       [](const std::string& tool, const Row& p) { return tool != "cadlod" && reached(p); });
            const bool anyPeer = !best.visibleTool.empty();
            ++t.pairs;
            t.reachedTarget += reached(c);
            t.flips += c.folded;
            t.flipParts += c.folded > 0;
            std::string shadingRatio = "-", hRatio = "-", sliverDelta = "-";
            if (anyPeer) {
                const double rs = ratio(c.visible, best.visible), rh = ratio(c.hMax, best.hMax);
                const double ds = c.slivers - best.slivers;
                t.shadingOk += shadingWithin(c, best);
                t.hausdorffOk += hausdorffWithin(c, best);
                t.sliverOk += sliversWithin(c, best);
                if (rs > t.worstShading) t.worstShading = rs, t.worstShadingPart = name;
                if (rh > t.worstHausdorff) t.worstHausdorff = rh, t.worstHausdorffPart = name;
                if (ds > t.worstSliver) t.worstSliver = ds, t.worstSliverPart = name;
                shadingRatio = ratioText(c.visible, best.visible) + " " + best.visibleTool;
                hRatio = ratioText(c.hMax, best.hMax) + " " + best.hTool;
                char buf[48];
                std::snprintf(buf, sizeof buf, "%+.1f %s", ds, best.sliverTool.c_str());
                sliverDelta = buf;
            } else {
                ++t.noPeer;
            }
            std::printf("| %s | %d | %d%s | %.3f | %s | %.2f | %.4f | %s | %.5f | %.1f | %s | %d | %d | %.2f | %.0f |\n",
                        name.c_str(), c.in, c.out, reached(c) ? "" : " (short)", c.visible, shadingRatio.c_str(),
                        c.meanDelta, c.hMax, hRatio.c_str(), c.hMean, c.slivers, sliverDelta.c_str(), c.folded,
                        c.newNonManifold, c.seconds, c.peakMb);
        }
        const int judged = t.pairs - t.noPeer;
        auto pct = [](int a, int b) { return b ? 100.0 * a / b : 0.0; };
        std::printf("\n**%g %%:** shading ≤ 1.1× best or ≤ 0.2 %%: %d/%d (%.0f %%); Hausdorff ≤ 1.1× best: %d/%d "
                    "(%.0f %%); slivers ≤ best + 1 pt: %d/%d (%.0f %%); worst ratios: shading %.2f (%s), Hausdorff "
                    "%.2f (%s), slivers %+.1f pts (%s); flipped faces %d (on %d parts); face target reached %d/%d.\n",
                    red, t.shadingOk, judged, pct(t.shadingOk, judged), t.hausdorffOk, judged,
                    pct(t.hausdorffOk, judged), t.sliverOk, judged, pct(t.sliverOk, judged), t.worstShading,
                    t.worstShadingPart.c_str(), t.worstHausdorff, t.worstHausdorffPart.c_str(), t.worstSliver,
                    t.worstSliverPart.c_str(), t.flips, t.flipParts, t.reachedTarget, t.pairs);
        printWithinBestOfOthers(tools, results[red]);
        const CleanPeerCounts clean = againstCleanPeers(tools, results[red]);
        char label[32];
        std::snprintf(label, sizeof label, "%g %%, judged", red);
        printAgainstCleanPeers(label, clean);
        cleanOverall.add(clean);
        overall.pairs += t.pairs;
        overall.noPeer += t.noPeer;
        overall.shadingOk += t.shadingOk;
        overall.hausdorffOk += t.hausdorffOk;
        overall.sliverOk += t.sliverOk;
        overall.reachedTarget += t.reachedTarget;
        overall.flips += t.flips;
        overall.flipParts += t.flipParts;
    }
    const int judged = overall.pairs - overall.noPeer;
    std::printf("\n**All (part, reduction) pairs:** shading ok %d/%d, Hausdorff ok %d/%d, slivers ok %d/%d, "
                "flipped faces %d, face target reached %d/%d. Wall time %.0f s.\n",
                overall.shadingOk, judged, overall.hausdorffOk, judged, overall.sliverOk, judged, overall.flips,
                overall.reachedTarget, overall.pairs, secondsSince(start));
    printAgainstCleanPeers("All pairs, judged", cleanOverall);
    return 0;
}
