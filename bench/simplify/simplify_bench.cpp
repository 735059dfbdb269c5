// Side-by-side simplification benchmark on CAD-like tessellations (tests/simplify/
// cad_meshes.h): cadlod's CAD Quadric Edge Collapse, vcglib's stock quadric collapse set up
// as MeshLab's filter sets it up, meshoptimizer and CGAL Garland–Heckbert. Each run is a
// forked process (peak memory per run); prints one Markdown table.
//   simplify_bench [--sizes 24000,250000,1000000] [--reductions 50,90]
//                  [--tools cadlod,vcglib,meshopt,cgal,direct] [--assembly-segments 1024]
//                  [--dump-ply DIR]   (also write each input mesh, for meshlab_stock.sh)
//                  [--quality 0]      (time and memory only, e.g. under a profiler)
// Tool "direct" runs no simplifier: the part tessellated by the generator at about the
// target size, the reference a simplifier's output can be held against.
#include "cad_meshes.h"
#include "mesh_checks.h"
#include "peer_cgal.h"
#include "forked_run.h"
#include "peer_meshopt.h"
#include "stock_quadric.h"
#include "test_mesh.h"

#include "measure/compactness.h"
#include "measure/hausdorff.h"
#include "simplify/best_of_trials.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

using cadlod::test::TestMesh;

namespace {

struct MeshSpec {
    std::string name;
    std::function<void(TestMesh&)> build;
    // The same part as the exporter would tessellate it with about this many triangles:
    // the reference a simplifier's output can be held against (tool "direct").
    std::function<void(TestMesh&, int)> direct;
};

struct Row {
    int in = 0, out = 0;
    double seconds = 0;
    long peakKb = 0;
    double cMean = 0, cP5 = 0, cBelow01 = 0;
    double hMax = 0, hMean = 0;
    int folded = 0, nonManifold = 0;
    bool ok = false;
    bool measured = false;  // quality columns filled
};

bool measureQuality = true;

// A stepped shaft (centre-drilled ends) tessellated like a CAD exporter with about
// `triangles` triangles (cad_meshes.h's shaftSpecForTriangles).
MeshSpec shaft(int triangles)
{
    const cadlod::test::RevolveSpec spec = cadlod::test::shaftSpecForTriangles(triangles);
    const int segments = spec.segments, rings = spec.cylinderRings;
    auto build = [](TestMesh& m, int segments, int rings) {
        cadlod::test::CadBuilder b;
        cadlod::test::revolve(b, cadlod::test::shaftProfile(2.0), cadlod::test::shaftSpec(segments, rings));
        b.build(m);
    };
    return {"shaft " + std::to_string(cadlod::test::shaftTriangles(segments, rings, false)),
            [=](TestMesh& m) { build(m, segments, rings); },
            [=](TestMesh& m, int target) {
                const int perSegment = cadlod::test::shaftTriangles(1, 1, false);
                build(m, std::max(8, int(std::lround(double(target) / perSegment))), 1);
            }};
}

int assemblyTriangles(int segments)
{
    cadlod::test::CadBuilder b;
    cadlod::test::assembly(b, segments);
    return int(b.triangles.size());
}

MeshSpec assembly(int segments)
{
    auto build = [](TestMesh& m, int segments) {
        cadlod::test::CadBuilder a;
        cadlod::test::assembly(a, segments);
        a.build(m, true);
    };
    return {"assembly " + std::to_string(assemblyTriangles(segments)), [=](TestMesh& m) { build(m, segments); },
            [=](TestMesh& m, int target) {
                int coarse = 8;
                while (coarse < segments && assemblyTriangles(coarse + 8) <= target)
                    coarse += 8;
                build(m, coarse);
            }};
}

double secondsSince(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void simplifyWith(const std::string& tool, TestMesh& m, int target, double& seconds)
{
    if (tool == "cgal") {
        cadlod::bench::CgalMesh sm = cadlod::bench::toCgal(m);
        const auto t = std::chrono::steady_clock::now();
        cadlod::bench::cgalSimplify(sm, target);
        seconds = secondsSince(t);
        cadlod::bench::fromCgal(sm, m);
        return;
    }
    const auto t = std::chrono::steady_clock::now();
    if (tool == "cadlod" || tool == "cadlod-2t" || tool == "cadlod-whole") {
        cadlod::SimplifyParams p;
        p.targetFaces = target;
        if (tool == "cadlod-whole")
            p.halvesMinFaces = 0;
        cadlod::bestOfTrials(m, p, nullptr, tool == "cadlod-2t" ? cadlod::RunTogether(cadlod::runOnTwoThreads) : cadlod::RunTogether(cadlod::runInSequence));
    } else if (tool == "vcglib") {
        cadlod::test::stockSimplify(m, target, cadlod::test::stockDefaults<TestMesh>());
    } else if (tool == "meshopt") {
        cadlod::bench::meshoptSimplify(m, target);
    }
    seconds = secondsSince(t);
}

Row runOne(const MeshSpec& spec, const std::string& tool, int reduction)
{
    Row r;
    TestMesh m;
    spec.build(m);
    r.in = m.fn;
    const int target = int(std::lround(m.fn * (1.0 - reduction / 100.0)));
    if (tool == "direct")
        spec.direct(m, target);
    else
        simplifyWith(tool, m, target, r.seconds);
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    r.peakKb = usage.ru_maxrss;
    r.out = m.fn;
    r.ok = true;
    if (!measureQuality)
        return r;

    TestMesh original;
    spec.build(original);
    const cadlod::CompactnessStats c = cadlod::meshCompactness(m);
    r.cMean = c.mean;
    r.cP5 = c.p5;
    r.cBelow01 = c.shareBelow01;
    const std::size_t samples = std::min<std::size_t>(original.fn, 1000000);
    const cadlod::SymmetricHausdorff h = cadlod::symmetricHausdorff(original, m, samples);
    r.hMax = h.maxFraction();
    r.hMean = h.meanFraction();
    r.folded = cadlod::test::foldedFaces(m, original, 90.0);
    r.nonManifold = cadlod::test::nonManifoldEdges(m);
    r.measured = true;
    return r;
}

// In a child process, so that peak memory belongs to this run alone.
Row runForked(const MeshSpec& spec, const std::string& tool, int reduction)
{
    return cadlod::bench::runForked<Row>([&] { return runOne(spec, tool, reduction); });
}

std::vector<std::string> split(const std::string& s)
{
    std::vector<std::string> out;
    std::stringstream in(s);
    for (std::string item; std::getline(in, item, ',');)
        if (!item.empty())
            out.push_back(item);
    return out;
}

// A run's time and peak, for the ratios printed under the table.
struct Timed {
    std::string mesh, red, tool;
    double seconds, peakKb;
};

// Every other tool against `reference` on the same mesh and reduction: throughput (the
// reference's time over the tool's) and peak memory, the figures issue 14 asks for.
void printRatios(const std::vector<Timed>& timed, const std::string& reference)
{
    bool header = false;
    for (const Timed& ref : timed) {
        if (ref.tool != reference)
            continue;
        for (const Timed& t : timed) {
            if (t.tool == reference || t.mesh != ref.mesh || t.red != ref.red || !(t.seconds > 0))
                continue;
            if (!header) {
                std::printf("\n| mesh | red. | tool | throughput / %s | peak / %s |\n|---|---|---|---|---|\n",
                            reference.c_str(), reference.c_str());
                header = true;
            }
            std::printf("| %s | %s%% | %s | %.2f | %.2f |\n", t.mesh.c_str(), t.red.c_str(), t.tool.c_str(),
                        ref.seconds / t.seconds, ref.peakKb > 0 ? t.peakKb / ref.peakKb : 0.0);
        }
    }
}

}  // namespace

int main(int argc, char** argv)
{
    std::string sizes = "24000,250000,1000000", reductions = "50,90", tools = "cadlod,vcglib,meshopt,cgal";
    int assemblySegments = 1024;
    std::string dumpDir;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--sizes") sizes = value;
        else if (key == "--reductions") reductions = value;
        else if (key == "--tools") tools = value;
        else if (key == "--assembly-segments") assemblySegments = std::stoi(value);
        else if (key == "--dump-ply") dumpDir = value;
        else if (key == "--quality") measureQuality = value != "0";
        else {
            std::fprintf(stderr, "unknown option %s\n", key.c_str());
            return 2;
        }
    }
    std::vector<MeshSpec> meshes;
    for (const std::string& s : split(sizes))
        meshes.push_back(shaft(std::stoi(s)));
    if (assemblySegments > 0)
        meshes.push_back(assembly(assemblySegments));

    for (const MeshSpec& spec : meshes)
        if (!dumpDir.empty()) {
            TestMesh m;
            spec.build(m);
            std::string file = spec.name;
            std::replace(file.begin(), file.end(), ' ', '_');
            cadlod::test::savePly(dumpDir + "/" + file + ".ply", m);
        }
    std::printf("| mesh | red. | tool | tris in | tris out | s | tris/s | peak MB | c mean | c p5 | c<0.1 | "
                "H max %%diag | H mean %%diag | flipped | non-manif. |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    std::vector<Timed> timed;
    for (const MeshSpec& spec : meshes)
        for (const std::string& red : split(reductions))
            for (const std::string& tool : split(tools)) {
                const Row r = runForked(spec, tool, std::stoi(red));
                if (r.ok)
                    timed.push_back({spec.name, red, tool, r.seconds, double(r.peakKb)});
                if (!r.ok) {
                    std::printf("| %s | %s%% | %s | failed |\n", spec.name.c_str(), red.c_str(), tool.c_str());
                    continue;
                }
                std::printf("| %s | %s%% | %s | %d | %d | %.3f | %.0f | %.0f |", spec.name.c_str(), red.c_str(),
                            tool.c_str(), r.in, r.out, r.seconds, r.seconds > 0 ? r.in / r.seconds : 0.0,
                            r.peakKb / 1024.0);
                if (r.measured)
                    std::printf(" %.3f | %.3f | %.1f%% | %.4f | %.5f | %d | %d |\n", r.cMean, r.cP5,
                                100 * r.cBelow01, 100 * r.hMax, 100 * r.hMean, r.folded, r.nonManifold);
                else
                    std::printf(" - | - | - | - | - | - | - |\n");
                std::fflush(stdout);
            }
    printRatios(timed, "vcglib");
    return 0;
}
