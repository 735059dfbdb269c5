// LOD chains side by side (issue 13): cadlod's screen-space chain against a meshoptimizer
// chain (levels at doubling errors, each measured like cadlod's and switched in at 1 px of
// its measured error), on VRML assemblies, PLY parts and the generated bench assembly.
// Prints one Markdown table; with --plot DIR also writes DIR/<name>.dat (distance, faces
// of each chain) for bench/lod/plot_chains.sh.
//   chain_bench [--assembly-segments N] [--shaft TRIANGLES] [--plot DIR] [--samples N] [--levels] [--verify] FILE...
// --verify re-measures each of cadlod's levels with other random points, 20 per input face
// (at least a million) per side, and prints the worst projected error found that way (with
// --levels, each level's: forward and backward distance beside the chain's own figure).
#include "cad_meshes.h"
#include "peer_meshopt.h"
#include "test_mesh.h"

#include "chain_measures.h"
#include "mesh_loading.h"

#include "lod/lod_chain.h"
#include "simplify/best_of_trials.h"  // bestOfTrials(), timed beside the chain

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

using cadlod::test::TestMesh;
using namespace cadlod;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Chain {
    std::vector<LodLevel> levels;
    double seconds = 0;
    double measureSeconds = 0;  // of `seconds`, measuring levels against level 0
    double verifiedPixels = 0;  // --verify: the largest projected error re-measured independently
};

// Each kept level of cadlod's chain measured again against level 0 with other random
// points (seeds the chain does not use) and kVerifySamplesPerFace times as many per side as
// the larger mesh has faces (at least kVerifyMinSamples), every face's centroid and edge
// midpoints on the level's side too: the largest error it projects to where it is first
// drawn, in pixels. What a user's own Hausdorff tool would find.
constexpr std::size_t kVerifySamplesPerFace = 20;
constexpr std::size_t kVerifyMinSamples = 1000000;

double verifiedPixels(TestMesh& input, const std::vector<std::unique_ptr<TestMesh>>& meshes,
                      const std::vector<LodLevel>& levels, const ViewParams& view, bool printEach)
{
    detail::ClosestFace<TestMesh> toInput(input);
    const std::size_t n = std::max(kVerifyMinSamples, kVerifySamplesPerFace * std::size_t(input.fn));
    const double pixelsPerUnitAtOne = view.viewportHeightPx / (2.0 * detail::tanHalfFov(view));
    double worst = 0;
    for (const LodLevel& l : levels) {
        if (l.level == 0)
            continue;
        for (const auto& m : meshes) {
            if (!m || !hasLodLevel(*m) || lodLevelHandle(*m)().level != l.level || m->fn != l.faces)
                continue;
            detail::ClosestFace<TestMesh> toLevel(*m);
            const double forward = oneSidedHausdorff(input, toLevel, n, 11).max;
            const double backward = oneSidedHausdorff(*m, toInput, n, 12, nullptr, {}, 1, true).max;
            const double px = std::max(forward, backward) * pixelsPerUnitAtOne / l.switchOut;
            if (printEach)
                std::printf("    level %2d re-measured: %g and %g model units (the chain's %g), %.3f px where first drawn\n",
                            l.level, forward, backward, l.hausdorffMax, px);
            worst = std::max(worst, px);
        }
    }
    return worst;
}

Chain cadlodChain(TestMesh& input, const LodChainOptions& options, bool verify = false, bool printEach = false)
{
    std::vector<std::unique_ptr<TestMesh>> meshes;
    TestMesh scratch;
    const auto t0 = std::chrono::steady_clock::now();
    const LodSetResult r = buildLodChain<TestMesh>(input, scratch, options, [&](int) -> TestMesh& {
        meshes.push_back(std::make_unique<TestMesh>());
        return *meshes.back();
    });
    Chain c;
    c.seconds = secondsSince(t0);
    c.measureSeconds = r.measureSeconds;
    if (!r.ok())
        std::fprintf(stderr, "cadlod chain: %s\n", r.error.c_str());
    c.levels = r.levels;
    if (verify && r.ok())
        c.verifiedPixels = verifiedPixels(input, meshes, r.levels, options.view, printEach);
    return c;
}

// Levels at meshoptimizer errors 1e-4, 2e-4, ... of the extent, each from level 0.
Chain meshoptChain(TestMesh& input, const ViewParams& view, std::size_t samples)
{
    const auto t0 = std::chrono::steady_clock::now();
    const double diagonal = liveDiagonal(input);
    std::vector<LodLevel> levels(1);
    levels[0].faces = input.fn;
    detail::ClosestFace<TestMesh> toInput(input);
    int lastFaces = input.fn;
    for (double e = 1e-4; e <= 1.0 && lastFaces > 4; e *= 2) {
        TestMesh m;
        vcg::tri::Append<TestMesh, TestMesh>::MeshCopy(m, input);
        bench::meshoptSimplify(m, 1, float(e));
        if (m.fn == 0 || m.fn >= lastFaces)
            continue;
        lastFaces = m.fn;
        SymmetricHausdorff h;
        h.forward = oneSidedHausdorff(input, m, samples, 1);
        h.backward = oneSidedHausdorff(m, toInput, samples, 2);
        LodLevel l;
        l.level = int(levels.size());
        l.faces = m.fn;
        l.hausdorffMax = h.max();
        levels.push_back(l);
    }
    const double floor = std::max(kRelativeErrorFloor * diagonal, 1e-12);
    const LevelSelection keep = selectUsefulLevels(levels, floor);
    std::vector<LodLevel> kept;
    for (std::size_t k = 0; k < levels.size(); ++k)
        if (keep.keep[k])
            kept.push_back(levels[k]);
    assignSwitchDistances(kept, diagonal, view, floor);
    kept.back().switchIn = kNeverCulled;
    Chain c;
    c.levels = kept;
    c.seconds = secondsSince(t0);
    return c;
}

double ninetyPercentSeconds(TestMesh& input, const RunTogether& together)
{
    TestMesh m;
    vcg::tri::Append<TestMesh, TestMesh>::MeshCopy(m, input);
    SimplifyParams p;
    p.reductionPerc = 90;
    const auto t0 = std::chrono::steady_clock::now();
    bestOfTrials(m, p, nullptr, together);
    return secondsSince(t0);
}

void writePlot(const std::string& path, const Chain& a, const Chain& b, double diagonal)
{
    std::ofstream out(path);
    out << "# distance/diagonal cadlod_faces meshopt_faces\n";
    for (int i = 0; i <= 600; ++i) {
        const double d = diagonal * std::pow(10.0, -1.0 + 4.0 * i / 600.0);
        out << d / diagonal << " " << bench::facesAt(a.levels, d) << " " << bench::facesAt(b.levels, d) << "\n";
    }
}

std::string levelList(const std::vector<LodLevel>& levels)
{
    std::string s;
    for (const LodLevel& l : levels)
        s += (s.empty() ? "" : " ") + std::to_string(l.faces);
    return s;
}

// One line per level: faces, measured error (% of the diagonal) and the distances between
// which it is drawn (in diagonals), each level's share of the scene figure beside.
void printLevelRanges(const std::vector<LodLevel>& levels, double diagonal)
{
    const double R = 1000.0 * diagonal;
    for (const LodLevel& l : levels) {
        const double a = std::min(l.switchOut, R), b = std::min(l.switchIn, R);
        const double scene = b > a ? l.faces * (b * b - a * a) / (R * R) : 0.0;
        std::printf("    level %2d: %7d faces, error %8.4f %%, drawn %10.4g to %10.4g diagonals, scene %.3f "
                    "triangles\n",
                    l.level, l.faces, 100 * l.hausdorffMax / diagonal, l.switchOut / diagonal,
                    std::min(l.switchIn, 1e9 * diagonal) / diagonal, scene);
    }
}

}  // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> files;
    std::string plotDir;
    int assemblySegments = 0;
    int shaftTriangles = 0;
    std::size_t samples = 0;
    bool withMeshopt = true;  // its chain takes minutes on a 1M-triangle shaft
    bool twoThreads = false;  // cadlod's chain and the 90 % run on two threads (measuring beside collapsing, two halves)
    bool printLevels = false; // each level's error and range after its chain's row
    bool verify = false;      // each cadlod level re-measured independently (verifiedPixels)
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--plot") && i + 1 < argc)
            plotDir = argv[++i];
        else if (!std::strcmp(argv[i], "--assembly-segments") && i + 1 < argc)
            assemblySegments = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--shaft") && i + 1 < argc)
            shaftTriangles = std::atoi(argv[++i]);
        else if (!std::strcmp(argv[i], "--samples") && i + 1 < argc)
            samples = std::size_t(std::atol(argv[++i]));
        else if (!std::strcmp(argv[i], "--no-meshopt"))
            withMeshopt = false;
        else if (!std::strcmp(argv[i], "--two-threads"))
            twoThreads = true;
        else if (!std::strcmp(argv[i], "--levels"))
            printLevels = true;
        else if (!std::strcmp(argv[i], "--verify"))
            verify = true;
        else if (argv[i][0] == '-') {
            std::fprintf(stderr, "usage: chain_bench [--assembly-segments N] [--shaft TRIANGLES] [--plot DIR] "
                                 "[--samples N] [--no-meshopt] [--two-threads] [--levels] [--verify] FILE...\n");
            return 2;
        } else
            files.push_back(argv[i]);
    }

    LodChainOptions options;
    options.hausdorffSamples = samples;
    if (twoThreads)
        options.runTogether = runOnTwoThreads;
    std::printf("Camera: %.0f deg vertical field of view, %.0f px, %.1f px error. Path: camera backing away from 1x "
                "to 1000x the diagonal (300 log-spaced distances); scene: objects on a disc of 1000x the diagonal.\n\n",
                options.view.fovYDegrees, options.view.viewportHeightPx, options.view.pixelThreshold);
    std::printf("| mesh | triangles | chain | levels | faces per level | path share | scene share | worst px | "
                "build s | build / 90 %% run |\n|---|---|---|---|---|---|---|---|---|---|\n");

    auto run = [&](const std::string& name, TestMesh& input) {
        const double diagonal = liveDiagonal(input);
        const std::size_t meshoptSamples = samples ? samples : std::min<std::size_t>(input.fn, 2000000);
        const double single = ninetyPercentSeconds(input, twoThreads ? RunTogether(runOnTwoThreads) : RunTogether(runInSequence));
        const Chain ours = cadlodChain(input, options, verify, printLevels);
        const bench::ChainFigures a = bench::chainFigures(ours.levels, diagonal, options.view);
        std::printf("| %s | %d | cadlod | %zu | %s | %.3f%% | %.3f%% | %.2f | %.2f | %.2f |\n", name.c_str(), input.fn,
                    ours.levels.size(), levelList(ours.levels).c_str(), 100 * a.pathShare, 100 * a.sceneShare,
                    a.worstPixels, ours.seconds, ours.seconds / single);
        if (printLevels) {
            printLevelRanges(ours.levels, diagonal);
            std::printf("    measuring the levels against level 0: %.2f s, %.2fx the 90 %% run\n", ours.measureSeconds,
                        ours.measureSeconds / single);
        }
        if (verify)
            std::printf("    re-measured independently: worst %.3f px\n", ours.verifiedPixels);
        std::fflush(stdout);
        if (!withMeshopt)
            return;
        const Chain theirs = meshoptChain(input, options.view, meshoptSamples);
        const bench::ChainFigures b = bench::chainFigures(theirs.levels, diagonal, options.view);
        std::printf("| | | meshopt | %zu | %s | %.3f%% | %.3f%% | %.2f | %.2f | |\n", theirs.levels.size(),
                    levelList(theirs.levels).c_str(), 100 * b.pathShare, 100 * b.sceneShare, b.worstPixels,
                    theirs.seconds);
        if (printLevels)
            printLevelRanges(theirs.levels, diagonal);
        std::printf("| | | ratio | | | **%.2f** | **%.2f** | | | |\n", a.pathShare / b.pathShare,
                    a.sceneShare / b.sceneShare);
        std::fflush(stdout);
        if (!plotDir.empty())
            writePlot(plotDir + "/" + name + ".dat", ours, theirs, diagonal);
    };

    if (shaftTriangles > 0) {
        TestMesh m;
        test::CadBuilder b;
        test::revolve(b, test::shaftProfile(2.0), test::shaftSpecForTriangles(shaftTriangles));
        b.build(m);
        run("bench shaft " + std::to_string(m.fn), m);
    }
    if (assemblySegments > 0) {
        TestMesh m;
        test::CadBuilder b;
        test::assembly(b, assemblySegments);
        b.build(m, true);
        run("bench assembly " + std::to_string(assemblySegments), m);
        TestMesh board;
        test::CadBuilder c;
        test::circuitBoard(c);
        c.build(board, true);
        run("bench board", board);
    }
    for (const std::string& file : files) {
        TestMesh m;
        std::string error;
        if (!bench::loadMesh(file, m, error)) {
            std::fprintf(stderr, "%s: %s\n", file.c_str(), error.c_str());
            continue;
        }
        std::string name = file.substr(file.find_last_of('/') + 1);
        run(name, m);
    }
    return 0;
}
