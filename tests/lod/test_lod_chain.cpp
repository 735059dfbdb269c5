// The screen-space LOD chain (core/lod_chain.h): levels planned by projected error, down to
// the far field, each drawn only where its measured error projects below the pixel error.
#include "cad_meshes.h"
#include "test_mesh.h"

#include "lod/lod_chain.h"
#include "lod/lod_proxies.h"  // detail::trimmedBox

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

using namespace cadlod;
using namespace cadlod::test;

namespace {

struct Chain {
    TestMesh input;
    TestMesh scratch;
    std::vector<std::unique_ptr<TestMesh>> meshes;  // by level number as newLevel(k) gave them
    LodSetResult result;

    explicit Chain(const CadBuilder& b, const LodChainOptions& options = {})
    {
        b.build(input, true);
        result = buildLodChain<TestMesh>(input, scratch, options, [&](int k) -> TestMesh& {
            meshes.resize(std::max<std::size_t>(meshes.size(), std::size_t(k) + 1));
            meshes[std::size_t(k)] = std::make_unique<TestMesh>();
            return *meshes[std::size_t(k)];
        });
    }
    // The mesh of kept level i.
    TestMesh& level(std::size_t i)
    {
        if (i == 0)
            return input;
        for (auto& m : meshes)
            if (m && hasLodLevel(*m) && lodLevelHandle(*m)().level == int(i) && m->fn == result.levels[i].faces)
                return *m;
        ADD_FAILURE() << "no mesh for level " << i;
        return input;
    }
};

CadBuilder boardBuilder()
{
    CadBuilder b;
    circuitBoard(b);
    return b;
}

CadBuilder assemblyBuilder()
{
    CadBuilder b;
    assembly(b, 256);
    return b;
}

// A cup of `segments` around its axis: a wall 1 thick, 30 high, around a cavity 28 deep.
CadBuilder cupBuilder(int segments)
{
    CadBuilder b;
    RevolveSpec spec;
    spec.segments = segments;
    revolve(b, {{0, 0}, {0, 10}, {30, 10}, {30, 9}, {2, 9}, {2, 0}}, spec);
    return b;
}

double projectedPixels(double error, double distance, const ViewParams& view)
{
    return error * view.viewportHeightPx / (2.0 * distance * std::tan(0.5 * view.fovYDegrees * M_PI / 180.0));
}

// The symmetric Hausdorff distance of `level` to `input` measured again, independently of the
// chain: other seeds, `perFace` random points per input face each way.
double remeasuredError(TestMesh& input, TestMesh& level, std::size_t perFace)
{
    const std::size_t samples = std::size_t(input.fn) * perFace;
    return std::max(oneSidedHausdorff(input, level, samples, 11).max, oneSidedHausdorff(level, input, samples, 12).max);
}

}  // namespace

TEST(LodChain, GoesDownToTheFarFieldInContiguousRanges)
{
    Chain c(assemblyBuilder());
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    const auto& levels = c.result.levels;
    ASSERT_GE(levels.size(), 5u);
    EXPECT_LE(levels.back().faces, 0.02 * levels.front().faces);
    EXPECT_EQ(levels.front().switchOut, 0.0);
    for (std::size_t k = 1; k < levels.size(); ++k) {
        EXPECT_LT(levels[k].faces, levels[k - 1].faces);
        EXPECT_GT(levels[k].hausdorffMax, levels[k - 1].hausdorffMax);
        EXPECT_EQ(levels[k].switchOut, levels[k - 1].switchIn);  // contiguous
        EXPECT_GT(levels[k].switchIn, levels[k].switchOut);      // monotone, never empty
    }
    EXPECT_EQ(levels.back().switchIn, kNeverCulled);
}

// With a farthest distance (a cluster proxy whose parent takes over there), the chain stops:
// its levels are the unbounded chain's up to that distance, the last one drawn on from there,
// and no box or tetrahedron follows.
TEST(LodChain, AFarthestDistanceEndsTheChainWithTheSameLevelsBeforeIt)
{
    const Chain whole(assemblyBuilder());
    ASSERT_TRUE(whole.result.ok()) << whole.result.error;
    ASSERT_GE(whole.result.levels.size(), 6u);
    LodChainOptions options;
    options.farthestDistance = whole.result.levels[3].switchOut;
    const Chain cut(assemblyBuilder(), options);
    ASSERT_TRUE(cut.result.ok()) << cut.result.error;
    const auto& levels = cut.result.levels;
    ASSERT_GE(levels.size(), 3u);
    EXPECT_LT(levels.size(), whole.result.levels.size());
    for (std::size_t k = 0; k + 1 < levels.size(); ++k) {
        EXPECT_EQ(levels[k].faces, whole.result.levels[k].faces) << "level " << k;
        EXPECT_EQ(levels[k].switchIn, whole.result.levels[k].switchIn) << "level " << k;
    }
    EXPECT_LE(levels.back().switchOut, options.farthestDistance);
    EXPECT_EQ(levels.back().switchIn, kNeverCulled);
    EXPECT_GT(levels.back().faces, 12);  // not the box
}

// Measured again, independently (other seed, four times the samples), no level is drawn
// where its error projects to more than the pixel error (5 % sampling slack).
TEST(LodChain, NoLevelIsDrawnBeyondItsPixelError)
{
    LodChainOptions options;
    Chain c(boardBuilder(), options);
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    for (std::size_t k = 1; k < c.result.levels.size(); ++k) {
        TestMesh& m = c.level(k);
        EXPECT_LE(projectedPixels(remeasuredError(c.input, m, 4), c.result.levels[k].switchOut, options.view),
                  options.view.pixelThreshold * 1.05)
            << "level " << k << " (" << m.fn << " faces)";
    }
}

// Far levels remove the board's small components whole, and only within their budget.
TEST(LodChain, SmallPartsGoOnlyWithinTheBudget)
{
    Chain c(boardBuilder());
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    int removed = 0;
    for (const SimplifyStats& s : c.result.steps) {
        EXPECT_LE(s.largestRemovedComponent, s.errorBound * (1 + 1e-9));
        removed = std::max(removed, s.removedComponents);
    }
    EXPECT_GT(removed, 0);
}

// Where the model is kFarFieldPixels high the pieces go into the far field, said in the log of
// the first level made there; the levels before it are made by the quadric error.
TEST(LodChain, FarLevelsAreMadeInTheFarField)
{
    LodChainOptions options;
    Chain c(boardBuilder(), options);
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    std::size_t first = 0;
    for (std::size_t k = 1; k < c.result.levels.size() && first == 0; ++k)
        for (const std::string& line : c.result.steps[k - 1].relaxed)
            if (line.find("far field from") != std::string::npos)
                first = k;
    ASSERT_GT(first, 1u) << "no far field, or from the first level";
    // The model is at most kFarFieldPixels high where that level is drawn (its budget there
    // is at least the error of the level before it).
    const LodLevel& level = c.result.levels[first];
    EXPECT_LE(projectedPixels(c.result.modelSize, level.switchIn, options.view), kFarFieldPixels);
}

// Where a level's measured error lands more than the distance ratio beyond the level before
// it (its budget underestimated the distance), the mesh the sessions passed through halfway is
// measured and becomes a level before it, said in its log lines.
TEST(LodChain, AGapWiderThanTheRatioGetsTheLevelHalfwayThrough)
{
    LodChainOptions options;
    Chain c(assemblyBuilder(), options);
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    const auto& levels = c.result.levels;
    int added = 0;
    for (std::size_t k = 1; k + 1 < levels.size(); ++k) {
        const std::vector<std::string>& said = c.result.steps[k - 1].relaxed;
        if (std::none_of(said.begin(), said.end(),
                         [](const std::string& line) { return line.find("added halfway") != std::string::npos; }))
            continue;
        ++added;
        EXPECT_GT(levels[k + 1].hausdorffMax, options.distanceRatio * levels[k - 1].hausdorffMax) << "level " << k;
        EXPECT_GT(levels[k].hausdorffMax, levels[k - 1].hausdorffMax) << "level " << k;
        EXPECT_LT(levels[k].hausdorffMax, levels[k + 1].hausdorffMax) << "level " << k;
        EXPECT_LT(levels[k].faces, levels[k - 1].faces) << "level " << k;
        EXPECT_GT(levels[k].faces, levels[k + 1].faces) << "level " << k;
    }
    EXPECT_GT(added, 0);
}

TEST(LodChain, CullingEndsTheLastRangeWhereTheModelIsThatSmall)
{
    LodChainOptions options;
    options.cullPixels = 2;
    Chain c(assemblyBuilder(), options);
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    // Where the model is 2 px high, or where the last level starts if that is farther.
    const double d = c.result.levels.back().switchIn;
    const double lastStarts = projectedPixels(c.result.modelSize, c.result.levels.back().switchOut, options.view);
    EXPECT_NEAR(projectedPixels(c.result.modelSize, d, options.view), std::min(2.0, lastStarts), 1e-9);
}

TEST(LodChain, MeasuringBesideTheCollapsesOnTwoThreadsGivesTheSameChain)
{
    LodChainOptions threaded;
    threaded.runTogether = runOnTwoThreads;
    Chain one(assemblyBuilder()), two(assemblyBuilder(), threaded);
    ASSERT_TRUE(one.result.ok()) << one.result.error;
    ASSERT_TRUE(two.result.ok()) << two.result.error;
    ASSERT_GE(one.result.levels.size(), 5u);
    ASSERT_EQ(one.result.levels.size(), two.result.levels.size());
    for (std::size_t i = 0; i < one.result.levels.size(); ++i) {
        const LodLevel &a = one.result.levels[i], &b = two.result.levels[i];
        EXPECT_EQ(a.faces, b.faces) << "level " << i;
        EXPECT_EQ(a.hausdorffMax, b.hausdorffMax) << "level " << i;
        EXPECT_EQ(a.hausdorffMean, b.hausdorffMean) << "level " << i;
        EXPECT_EQ(a.switchIn, b.switchIn) << "level " << i;
        EXPECT_EQ(a.switchOut, b.switchOut) << "level " << i;
        TestMesh &ma = one.level(i), &mb = two.level(i);
        ASSERT_EQ(ma.vert.size(), mb.vert.size());
        for (std::size_t v = 0; v < ma.vert.size(); ++v)
            ASSERT_EQ(ma.vert[v].cP(), mb.vert[v].cP()) << "level " << i << " vertex " << v;
    }
}

TEST(LodChain, TheFarthestLevelIsOutwardTetrahedra)
{
    Chain c(assemblyBuilder());
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    TestMesh& last = c.level(c.result.levels.size() - 1);
    vcg::tri::UpdateTopology<TestMesh>::VertexFace(last);
    const auto components = connectedComponents(last);
    ASSERT_FALSE(components.empty());
    EXPECT_EQ(last.fn, 4 * int(components.size()));
    for (const auto& component : components) {
        ASSERT_EQ(component.faces.size(), 4u);
        // Closed and outward: the signed volume (sum over faces of a . (b x c) / 6) is that
        // of the tetrahedron inscribed in a box, a third of the box's, whether that box is
        // the part's or the part's grown (kTetrahedronScales).
        double volume = 0;
        for (const auto* f : component.faces) {
            const vcg::Point3d a = vcg::Point3d::Construct(f->cP(0)), b = vcg::Point3d::Construct(f->cP(1)),
                               d = vcg::Point3d::Construct(f->cP(2));
            volume += a.dot(b ^ d) / 6.0;
        }
        const vcg::Point3d e = component.box.Dim();
        EXPECT_NEAR(volume, e[0] * e[1] * e[2] / 3.0, 1e-6 * e[0] * e[1] * e[2]);
    }
    // It serves from where the model is a few pixels high, not before.
    const double d = c.result.levels.back().switchOut;
    EXPECT_LE(projectedPixels(c.result.modelSize, d, LodChainOptions().view), 8.0 + 1e-9);
}

TEST(LodChain, BadCameraIsAClearError)
{
    LodChainOptions options;
    options.view.fovYDegrees = 0;
    Chain c(assemblyBuilder(), options);
    EXPECT_FALSE(c.result.ok());
    EXPECT_NE(c.result.error.find("field of view"), std::string::npos);
    EXPECT_TRUE(c.meshes.empty());
}

// A piece of at least halvesMinFaces faces starts its first level as two halves side by
// side (collapse_halves.h): the chain is the same on one thread and two, and every level
// is still drawn only within its pixel error.
TEST(LodChain, LargePiecesStartAsTwoHalvesWithTheSameChainOnTwoThreads)
{
    LodChainOptions sequential;
    sequential.simplify.halvesMinFaces = 1000;
    LodChainOptions threaded = sequential;
    threaded.runTogether = runOnTwoThreads;
    Chain one(assemblyBuilder(), sequential), two(assemblyBuilder(), threaded);
    ASSERT_TRUE(one.result.ok()) << one.result.error;
    ASSERT_TRUE(two.result.ok()) << two.result.error;
    ASSERT_FALSE(one.result.steps.empty());
    EXPECT_GT(one.result.steps[0].halvesCollapses, 0);  // level 1
    EXPECT_GT(one.result.steps[0].halvesBandVertices, 0);
    const std::vector<std::string>& said = one.result.steps[0].relaxed;  // logged with the level
    EXPECT_TRUE(std::any_of(said.begin(), said.end(),
                            [](const std::string& line) { return line.find("two halves side by side") != std::string::npos; }));
    ASSERT_EQ(one.result.levels.size(), two.result.levels.size());
    for (std::size_t i = 0; i < one.result.levels.size(); ++i) {
        EXPECT_EQ(one.result.levels[i].faces, two.result.levels[i].faces) << "level " << i;
        EXPECT_EQ(one.result.levels[i].switchOut, two.result.levels[i].switchOut) << "level " << i;
        TestMesh &ma = one.level(i), &mb = two.level(i);
        ASSERT_EQ(ma.vert.size(), mb.vert.size());
        for (std::size_t v = 0; v < ma.vert.size(); ++v)
            ASSERT_EQ(ma.vert[v].cP(), mb.vert[v].cP()) << "level " << i << " vertex " << v;
        if (i == 0)
            continue;
        EXPECT_LE(projectedPixels(remeasuredError(one.input, ma, 4), one.result.levels[i].switchOut, sequential.view),
                  sequential.view.pixelThreshold * 1.05)
            << "level " << i << " (" << ma.fn << " faces)";
    }
}

// A plate with a thin blade welded to one of its bottom corners, sticking 20 below it: one
// connected component. Its box proxy may leave the blade out (it holds 0.1 % of the area),
// the box of its vertices may not.
TEST(LodChain, ATrimmedBoxLeavesOutAThinBladeStickingOut)
{
    CadBuilder b;
    const int first = stripPlate(b, 40, 40, 4, 8);
    const int corner = first + 2 * 4;  // bottom outline point 4: (20, 0, 0)
    const int side = b.addPoint(20.5, 0, 0);
    const int tip = b.addPoint(20.25, 0, -20);
    b.addTriangle(corner, tip, side);
    TestMesh m;
    b.build(m);
    vcg::tri::UpdateTopology<TestMesh>::VertexFace(m);
    const auto components = connectedComponents(m);
    ASSERT_EQ(components.size(), 1u);

    const vcg::Box3d all = detail::trimmedBox(components[0], 0.0);
    EXPECT_DOUBLE_EQ(all.min[2], -20.0);
    EXPECT_DOUBLE_EQ(all.max[2], 4.0);

    for (double share : {0.02, 0.05}) {
        const vcg::Box3d trimmed = detail::trimmedBox(components[0], share);
        EXPECT_DOUBLE_EQ(trimmed.min[2], 0.0) << share;  // the plate's bottom, not the blade's tip
        EXPECT_DOUBLE_EQ(trimmed.max[2], 4.0) << share;
        EXPECT_DOUBLE_EQ(trimmed.min[0], 0.0) << share;  // the plate's sides hold their place
        EXPECT_DOUBLE_EQ(trimmed.max[0], 40.0) << share;
        EXPECT_DOUBLE_EQ(trimmed.min[1], 0.0) << share;
        EXPECT_DOUBLE_EQ(trimmed.max[1], 40.0) << share;
    }
    // A tenth of the area at each end cuts into the plate's sides too (its edges at x = 0 and
    // 40 hold 4 % each, with the corners of the top and bottom strips), which is why the chain
    // measures every trim and keeps the best; top and bottom, 42 % each, hold.
    const vcg::Box3d tenth = detail::trimmedBox(components[0], 0.1);
    EXPECT_DOUBLE_EQ(tenth.min[2], 0.0);
    EXPECT_DOUBLE_EQ(tenth.max[2], 4.0);
    EXPECT_GT(tenth.min[0], 0.0);
    EXPECT_LT(tenth.max[0], 40.0);
}

// Inscribed in a cube, a tetrahedron leaves four corners a third of the diagonal off; grown
// 1.5 times about the centre, its missing corners and its own vertices stand a quarter off,
// and it serves from a quarter closer. The chain measures the sizes it tries and keeps that.
TEST(LodChain, ACubesTetrahedronIsGrownToStandAQuarterOfTheDiagonalOff)
{
    CadBuilder b;
    stripPlate(b, 40, 40, 40, 8);
    Chain c(b);
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    const LodLevel& last = c.result.levels.back();
    ASSERT_EQ(last.faces, 4);
    EXPECT_NEAR(last.hausdorffMax / c.result.modelSize, 0.25, 0.01);
    const std::vector<std::string>& said = c.result.steps.back().relaxed;
    EXPECT_TRUE(std::any_of(said.begin(), said.end(),
                            [](const std::string& line) { return line.find("grown 1.5 times") != std::string::npos; }));
    // Its vertices stand outside the cube, a quarter of the diagonal beyond its corners.
    TestMesh& m = c.level(c.result.levels.size() - 1);
    for (const auto& v : m.vert)
        if (!v.IsD())
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_NEAR(std::abs(v.cP()[axis] - 20.0), 30.0, 1e-9);
}

// A cup: a thin wall around a deep cavity, like a jack's socket. Its far levels must keep the
// cavity open, with long faces across the rim. Held to its distance, a far-field level may
// make faces less compact than the chain's shape guard allows (kChainMinCompactness): its
// budget is a distance, and a level the guard kept heavier would be drawn farther out.
TEST(LodChain, FarLevelsAreHeldToTheirDistanceNotToTheShapeGuard)
{
    LodChainOptions options;
    Chain c(cupBuilder(48), options);
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    const double farFieldFrom = detail::distanceForPixels(c.result.modelSize, kFarFieldPixels, options.view);
    double leastCompact = 1.0;
    for (std::size_t k = 1; k < c.result.levels.size(); ++k) {
        const LodLevel& level = c.result.levels[k];
        const auto& lines = c.result.steps[k - 1].relaxed;
        const bool proxy = std::any_of(lines.begin(), lines.end(),
                                       [](const std::string& line) { return line.find(" proxy: ") != std::string::npos; });
        if (level.switchOut >= farFieldFrom && !proxy)
            leastCompact = std::min(leastCompact, c.result.compactness[k].min);
        TestMesh& m = c.level(k);
        EXPECT_LE(projectedPixels(remeasuredError(c.input, m, 16), level.switchOut, options.view),
                  options.view.pixelThreshold * 1.05)
            << "level " << k << " (" << m.fn << " faces)";
    }
    EXPECT_LT(leastCompact, kChainMinCompactness);
}

// Held to its distance in the far field, a collapse may turn a face up to a quarter turn (never
// over it, and never away from its input face), whatever the normal threshold that holds the
// levels before it. The near levels of these cups never turn a face 60°, so their chains are
// the same with a threshold of 60° and 89°. With 60° in the far field too, their far levels
// differed.
TEST(LodChain, FarLevelsDoNotDependOnTheNormalThreshold)
{
    for (const int segments : {16, 24}) {
        LodChainOptions strict, lax;
        strict.simplify.normalThreshold = 60;
        lax.simplify.normalThreshold = 89;
        Chain a(cupBuilder(segments), strict), b(cupBuilder(segments), lax);
        ASSERT_TRUE(a.result.ok() && b.result.ok()) << a.result.error << b.result.error;
        ASSERT_EQ(a.result.levels.size(), b.result.levels.size()) << segments << " segments";
        for (std::size_t k = 0; k < a.result.levels.size(); ++k) {
            EXPECT_EQ(a.result.levels[k].faces, b.result.levels[k].faces) << segments << " segments, level " << k;
            EXPECT_EQ(a.result.levels[k].hausdorffMax, b.result.levels[k].hausdorffMax) << segments << " segments, level " << k;
        }
    }
}

// A halfway copy (a factor of √ratio past a planned distance) that no planned level after it
// made lighter by a tenth is the level for the distances up to the next copy: before, the next
// copy took its place and the mesh was lost. Two drilled plates side by side: the sessions go
// 192 -> 132 faces at a halfway distance, stay at 132 at the next planned one, and reach 112
// only at the halfway distance after it.
TEST(LodChain, AHalfwayCopyNoPlannedLevelLightensIsKept)
{
    CadBuilder b;
    drilledPlate(b, 40, 2, 3, 16);
    const int second = drilledPlate(b, 40, 2, 3, 16);
    b.translate(second, 50, 0, 0);
    Chain c(b);
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    std::string faces;
    bool between = false;
    for (const LodLevel& level : c.result.levels) {
        faces += " " + std::to_string(level.faces);
        between |= level.faces > 112 && level.faces < 192;
    }
    EXPECT_TRUE(between) << "levels:" << faces;
}

// A fin welded around a tube: the ring under it has edges of three faces, whose vertices no
// collapse may move. The chain cuts the fin off along them (said in its first level's log)
// and its levels go lighter than the ring: a level of fewer faces than the ring has vertices
// is drawn before the proxies, each level within its pixel error, measured again.
TEST(LodChain, AFinWeldedOnARingIsCutOffSoTheRingSimplifiesToo)
{
    const int segments = 128;
    CadBuilder b;
    tubeWithFin(b, segments);
    LodChainOptions options;
    Chain c(b, options);
    ASSERT_TRUE(c.result.ok()) << c.result.error;
    const auto& first = c.result.steps.front().relaxed;
    EXPECT_TRUE(std::any_of(first.begin(), first.end(), [&](const std::string& line) {
        return line.find("cut apart along " + std::to_string(segments) + " of " + std::to_string(segments) +
                         " non-manifold edges") != std::string::npos;
    }));
    int lightest = c.result.levels.front().faces;
    for (std::size_t k = 1; k < c.result.levels.size(); ++k) {
        const auto& lines = c.result.steps[k - 1].relaxed;
        const bool proxy = std::any_of(lines.begin(), lines.end(),
                                       [](const std::string& line) { return line.find(" proxy: ") != std::string::npos; });
        if (!proxy)
            lightest = std::min(lightest, c.result.levels[k].faces);
        TestMesh& m = c.level(k);
        EXPECT_LE(projectedPixels(remeasuredError(c.input, m, 4), c.result.levels[k].switchOut, options.view),
                  options.view.pixelThreshold * 1.05)
            << "level " << k << " (" << m.fn << " faces)";
    }
    EXPECT_LT(lightest, segments);
}
