// buildLodSet on a plain vcglib mesh: level counts, error and switch-distance monotony,
// the per-mesh LodLevel attribute, part attributes carried into every level.
#include "lod/distance_to_level_zero.h"
#include "lod/lod_builder.h"
#include "lod/useful_levels.h"
#include "test_mesh.h"

#include <gtest/gtest.h>

#include <vcg/complex/algorithms/create/platonic.h>

#include <algorithm>
#include <deque>
#include <thread>

using namespace cadlod;
using cadlod::test::TestMesh;

namespace {

void makeSphereWithTwoParts(TestMesh& m)
{
    vcg::tri::Sphere(m, 4);  // 5120 faces
    auto part = facePartHandle(m);
    for (auto& f : m.face)
        part[f] = vcg::Barycenter(f)[2] > 0 ? 1 : 0;
    partTableHandle(m)() = {PartIdentity{"LOWER", {1, 0, 0, 1}}, PartIdentity{"UPPER", {0, 0, 1, 1}}};
}

int facesRepeatingAVertex(const TestMesh& m)
{
    int n = 0;
    for (const auto& f : m.face)
        n += !f.IsD() && (f.cV(0) == f.cV(1) || f.cV(1) == f.cV(2) || f.cV(2) == f.cV(0));
    return n;
}

struct Built {
    TestMesh original;
    std::deque<TestMesh> levels;
    LodSetResult result;
};

// Builds the set of whatever b.original holds.
void buildFrom(Built& b, const LodSetOptions& options)
{
    vcg::tri::UpdateTopology<TestMesh>::VertexFace(b.original);
    b.result = buildLodSet<TestMesh>(b.original, options, [&b](int) -> TestMesh& {
        b.levels.emplace_back();
        return b.levels.back();
    });
}

void build(Built& b, const LodSetOptions& options)
{
    makeSphereWithTwoParts(b.original);
    buildFrom(b, options);
}

}  // namespace

TEST(LodBuilder, PaperLevelsAreCoarserAndFurther)
{
    Built b;
    LodSetOptions options;  // 50 60 70 80 90, each from the previous level
    build(b, options);
    ASSERT_TRUE(b.result.ok()) << b.result.error;
    const auto& levels = b.result.levels;
    ASSERT_EQ(levels.size(), 6u);
    ASSERT_EQ(b.levels.size(), 5u);
    EXPECT_EQ(levels[0].faces, 5120);
    const int expected[] = {5120, 2560, 2048, 1536, 1024, 512};
    for (int k = 1; k < 6; ++k) {
        EXPECT_NEAR(levels[k].faces, expected[k], 2) << "level " << k;
        EXPECT_EQ(b.levels[k - 1].fn, levels[k].faces);
        EXPECT_EQ(facesRepeatingAVertex(b.levels[k - 1]), 0) << "level " << k;
        EXPECT_LT(levels[k].faces, levels[k - 1].faces);
        EXPECT_GT(levels[k].hausdorffMax, 0.0);
        EXPECT_GE(levels[k].hausdorffMax, levels[k - 1].hausdorffMax) << "level " << k;
        EXPECT_NEAR(levels[k].reduction, 1.0 - double(levels[k].faces) / 5120, 1e-12);
    }
    // Errors stay small against the unit sphere (diagonal ~3.46).
    EXPECT_LT(levels[5].hausdorffMax, 0.1);
    for (int k = 0; k < 6; ++k) {
        EXPECT_LE(levels[k].switchOut, levels[k].switchIn);
        if (k + 1 < 6)
            EXPECT_EQ(levels[k].switchIn, levels[k + 1].switchOut);
        EXPECT_EQ(levels[k].setId, 1);
        EXPECT_EQ(levels[k].level, k);
    }
    EXPECT_EQ(levels[0].switchOut, 0.0);
    EXPECT_GT(levels[5].switchIn, levels[5].switchOut);
}

TEST(LodBuilder, EveryMeshCarriesItsLevelAndParts)
{
    Built b;
    LodSetOptions options;
    options.levels = "50 90";
    options.setId = 7;
    build(b, options);
    ASSERT_TRUE(b.result.ok()) << b.result.error;
    ASSERT_TRUE(hasLodLevel(b.original));
    EXPECT_EQ(lodLevelHandle(b.original)().level, 0);
    EXPECT_EQ(lodLevelHandle(b.original)().setId, 7);
    for (int k = 0; k < 2; ++k) {
        TestMesh& m = b.levels[k];
        ASSERT_TRUE(hasLodLevel(m));
        EXPECT_EQ(lodLevelHandle(m)().level, k + 1);
        EXPECT_EQ(lodLevelHandle(m)().setId, 7);
        EXPECT_EQ(lodLevelHandle(m)().faces, m.fn);
        ASSERT_TRUE(hasParts(m));
        EXPECT_EQ(partTableHandle(m)().size(), 2u);
        EXPECT_EQ(partTableHandle(m)()[1].name, "UPPER");
        // Part borders are kept: faces of part 1 stay above the equator.
        auto part = facePartHandle(m);
        int upper = 0;
        for (auto& f : m.face) {
            if (f.IsD())
                continue;
            upper += part[f] == 1;
            if (part[f] == 1)
                EXPECT_GT(vcg::Barycenter(f)[2], -0.05f);
        }
        EXPECT_GT(upper, m.fn / 4);
    }
}

TEST(LodBuilder, FromOriginalGivesSameFaceCounts)
{
    Built b;
    LodSetOptions options;
    options.levels = "50 80";
    options.fromOriginal = true;
    build(b, options);
    ASSERT_TRUE(b.result.ok()) << b.result.error;
    EXPECT_NEAR(b.result.levels[1].faces, 2560, 2);
    EXPECT_NEAR(b.result.levels[2].faces, 1024, 2);
}

TEST(LodBuilder, TheLevelsWeightTrialsRunTwoAtATimeAndGiveTheSameSet)
{
    // What the set hands to its RunTogether from within a pair it started on this thread:
    // the pairs of a level's weight trials (the level is simplified on the calling thread,
    // the previous one measured on the other).
    const std::thread::id caller = std::this_thread::get_id();
    int depth = 0, nestedPairs = 0;
    LodSetOptions threaded;
    threaded.levels = "50 90";
    threaded.runTogether = [&](const Task& a, const Task& b) {
        const bool onCaller = std::this_thread::get_id() == caller;
        if (onCaller)
            nestedPairs += depth++ > 0;
        runOnTwoThreads(a, b);
        if (onCaller)
            --depth;
    };
    LodSetOptions sequential = threaded;
    sequential.runTogether = nullptr;
    Built one, two;
    build(one, sequential);
    build(two, threaded);
    ASSERT_TRUE(one.result.ok()) << one.result.error;
    ASSERT_TRUE(two.result.ok()) << two.result.error;
    ASSERT_EQ(two.result.steps.size(), 2u);
    int trialPairs = 0;
    for (const SimplifyStats& s : two.result.steps) {
        // "plane weights tried (…): 0.005 (…); 0.05 (…); …": one parenthesis per trial, and the
        // header's; the last trial, the closest run again slivers first, runs alone.
        const int trials = int(std::count(s.weightTrials.begin(), s.weightTrials.end(), '(')) - 2;
        EXPECT_GE(trials, 4) << s.weightTrials;  // three plane weights, the constraint planes at a quarter
        EXPECT_NE(s.weightTrials.find("slivers first"), std::string::npos) << s.weightTrials;
        trialPairs += trials / 2;
    }
    EXPECT_EQ(nestedPairs, trialPairs);
    for (std::size_t i = 0; i < one.result.steps.size(); ++i)
        EXPECT_EQ(one.result.steps[i].weightTrials, two.result.steps[i].weightTrials) << "level " << i + 1;
    ASSERT_EQ(one.result.levels.size(), two.result.levels.size());
    for (std::size_t i = 0; i < one.result.levels.size(); ++i) {
        EXPECT_EQ(one.result.levels[i].faces, two.result.levels[i].faces) << "level " << i;
        EXPECT_EQ(one.result.levels[i].hausdorffMax, two.result.levels[i].hausdorffMax) << "level " << i;
    }
    for (std::size_t k = 0; k < one.levels.size(); ++k) {
        ASSERT_EQ(one.levels[k].vert.size(), two.levels[k].vert.size());
        for (std::size_t v = 0; v < one.levels[k].vert.size(); ++v)
            ASSERT_EQ(one.levels[k].vert[v].cP(), two.levels[k].vert[v].cP()) << "level " << k + 1 << " vertex " << v;
    }
}

TEST(LodBuilder, FaceCountLevels)
{
    Built b;
    LodSetOptions options;
    options.levels = "3000 1000 300";
    options.spec = LevelSpec::FaceCount;
    build(b, options);
    ASSERT_TRUE(b.result.ok()) << b.result.error;
    EXPECT_NEAR(b.result.levels[1].faces, 3000, 2);
    EXPECT_NEAR(b.result.levels[3].faces, 300, 2);
}

TEST(LodBuilder, LevelsThatWouldNeverBeShownAreDroppedAndRenumbered)
{
    // A flat square: every level is lossless, so only the lightest is worth keeping.
    Built b;
    vcg::tri::Grid(b.original, 21, 21, 1.0f, 1.0f, nullptr);
    LodSetOptions options;
    options.levels = "50 75";
    buildFrom(b, options);
    ASSERT_TRUE(b.result.ok()) << b.result.error;
    ASSERT_EQ(b.result.levels.size(), 2u);
    EXPECT_EQ(b.result.droppedLevels, std::vector<int>{1});
    ASSERT_EQ(b.result.warnings.size(), 1u);
    EXPECT_NE(b.result.warnings[0].find("never be shown"), std::string::npos) << b.result.warnings[0];
    EXPECT_EQ(b.result.levels[1].level, 1);
    EXPECT_EQ(lodLevelHandle(b.levels[1])().level, 1);
    EXPECT_FALSE(hasLodLevel(b.levels[0]));
    EXPECT_LT(b.result.levels[0].switchOut, b.result.levels[0].switchIn);
}

// What gave way for a level that is dropped is told by the next kept level, whose lines say
// what gave way since the level before it.
TEST(LodBuilder, ADroppedLevelsLogLinesGoToTheNextKeptLevel)
{
    LodSetResult r;
    r.modelSize = 1.0;
    std::vector<TestMesh> meshes(3);
    std::vector<TestMesh*> pointers{&meshes[0], &meshes[1], &meshes[2]};
    for (int k = 0; k < 3; ++k) {
        LodLevel l;
        l.level = k;
        l.faces = 100 - 40 * k;
        l.hausdorffMax = k == 1 ? 0.2 : 0.1 * k;  // level 1 is less accurate than level 2
        r.levels.push_back(l);
        r.compactness.emplace_back();
        if (k > 0) {
            r.steps.emplace_back();
            r.steps.back().relaxed = {"gave way for level " + std::to_string(k)};
            r.distance.emplace_back();
        }
    }
    detail::keepUsefulLevels(r, pointers);
    ASSERT_EQ(r.levels.size(), 2u);
    EXPECT_EQ(r.droppedLevels, std::vector<int>{1});
    // The note names the dropped candidate by the kept levels' numbers, the ones a user sees.
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].rfind("a candidate level after level 0 (60 faces) dropped: ", 0), 0u) << r.warnings[0];
    ASSERT_EQ(r.steps.size(), 1u);
    EXPECT_EQ(r.steps[0].relaxed, (std::vector<std::string>{"(dropped level 1) gave way for level 1", "gave way for level 2"}));
    EXPECT_EQ(pointers, (std::vector<TestMesh*>{&meshes[0], &meshes[2]}));
}

TEST(LodBuilder, ASingleTriangleIsASetOfOneLevelWithWarnings)
{
    Built b;
    auto v = vcg::tri::Allocator<TestMesh>::AddVertices(b.original, 3);
    v[1].P() = vcg::Point3f(1, 0, 0);
    v[2].P() = vcg::Point3f(0, 1, 0);
    vcg::tri::Allocator<TestMesh>::AddFace(b.original, &v[0], &v[1], &v[2]);
    buildFrom(b, LodSetOptions{});
    ASSERT_TRUE(b.result.ok()) << b.result.error;
    EXPECT_TRUE(b.levels.empty());
    ASSERT_EQ(b.result.levels.size(), 1u);
    EXPECT_EQ(b.result.warnings.size(), 5u);
    ASSERT_TRUE(hasLodLevel(b.original));
    EXPECT_LT(lodLevelHandle(b.original)().switchOut, lodLevelHandle(b.original)().switchIn);
}

TEST(LodBuilder, BadLevelListIsAClearErrorAndBuildsNothing)
{
    Built b;
    LodSetOptions options;
    options.levels = "50 40";
    build(b, options);
    EXPECT_FALSE(b.result.ok());
    EXPECT_NE(b.result.error.find("not coarser"), std::string::npos) << b.result.error;
    EXPECT_TRUE(b.levels.empty());
    EXPECT_FALSE(hasLodLevel(b.original));
}

// A level's faces that are level 0's stand at distance 0 all over: the points measuring the
// level's side go to the faces that moved. A level identical to level 0 measures 0 both
// ways; one with a single vertex moved measures that vertex's offset, whichever way.
TEST(DistanceToLevelZero, FacesALevelKeptAsTheyWereAreNotSampled)
{
    TestMesh original;
    vcg::tri::Sphere(original, 3);
    TestMesh same, bumped;
    vcg::tri::Append<TestMesh, TestMesh>::MeshCopy(same, original);
    vcg::tri::Append<TestMesh, TestMesh>::MeshCopy(bumped, original);
    const double diagonal = liveDiagonal(original);
    DistanceToLevelZero<TestMesh> distance(original, 20000, diagonal, runInSequence);
    const SymmetricHausdorff identical = distance(same, 20000);
    EXPECT_LT(identical.forward.max, 1e-12);
    EXPECT_LT(identical.backward.max, 1e-12);

    bumped.vert[0].P() *= 1.05f;  // out by 5 % of the radius (1)
    const SymmetricHausdorff h = distance(bumped, 20000);
    EXPECT_NEAR(h.backward.max, 0.05, 1e-4);
    EXPECT_GT(h.forward.max, 0.0);
    EXPECT_LT(h.forward.max, 0.05);
}

// A level that kept none of level 0's faces is measured from points drawn on all of level
// 0, drawn once for every such level: the same points a one-sided measure from level 0 with
// the same seed finds, whichever coarse level comes first, and a finer level in between
// (which kept some faces) does not change them.
TEST(DistanceToLevelZero, CoarseLevelsAreMeasuredFromTheSamePointsOnAllOfLevelZero)
{
    TestMesh original, coarse, coarser, kept;
    vcg::tri::Sphere(original, 4);
    vcg::tri::Sphere(coarse, 2);
    vcg::tri::Sphere(coarser, 1);
    vcg::tri::Append<TestMesh, TestMesh>::MeshCopy(kept, original);
    kept.vert[0].P() *= 1.05f;
    const std::size_t samples = 20000;
    const double diagonal = liveDiagonal(original);
    auto fromAll = [&](TestMesh& level) {
        return distancesToSurface(hausdorffSamples(original, samples, 1, 4 * std::size_t(original.fn) <= samples),
                                  detail::ClosestFace<TestMesh>(level), nullptr, runInSequence,
                                  DistanceToLevelZero<TestMesh>::kMeanEvery);
    };
    DistanceToLevelZero<TestMesh> distance(original, samples, diagonal, runInSequence);
    for (TestMesh* level : {&coarser, &kept, &coarse, &coarser}) {
        const HausdorffStats measured = distance(*level, samples).forward;
        if (level == &kept)
            continue;
        const HausdorffStats expected = fromAll(*level);
        EXPECT_EQ(measured.max, expected.max);
        EXPECT_EQ(measured.mean, expected.mean);
        EXPECT_EQ(measured.samples, expected.samples);
    }
}
