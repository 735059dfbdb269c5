// The model's pieces simplified side by side (core/collapse_buckets.h): how components
// are dealt into buckets, and what the sessions may remove.
#include "cad_meshes.h"
#include "test_mesh.h"

#include "lod/collapse_buckets.h"

#include <gtest/gtest.h>

#include <deque>
#include <map>
#include <set>

using namespace cadlod;
using namespace cadlod::test;

namespace {

// The board assembly plus an unwelded copy of its first chip (a separate component whose
// vertices stand where the chip's stand: the two touch) as a part of its own.
void boardWithTouchingCopy(TestMesh& m, int& chipPart, int& copyPart)
{
    CadBuilder b;
    circuitBoard(b);
    chipPart = 1;
    copyPart = b.currentPart + 1;
    b.currentPart = copyPart;
    const std::size_t triangles = b.triangles.size();
    std::map<int, int> copyOf;
    for (std::size_t t = 0; t < triangles; ++t) {
        if (b.part[t] != chipPart)
            continue;
        std::array<int, 3> v{};
        for (int j = 0; j < 3; ++j) {
            const int p = b.triangles[t][std::size_t(j)];
            if (!copyOf.count(p))
                copyOf[p] = b.addPoint(b.points[std::size_t(p)][0], b.points[std::size_t(p)][1], b.points[std::size_t(p)][2]);
            v[std::size_t(j)] = copyOf[p];
        }
        b.addTriangle(v[0], v[2], v[1]);  // the other side of the same surface
    }
    b.build(m, true);
}

struct Dealt {
    TestMesh model;
    std::deque<TestMesh> meshes;
    CollapseBuckets<TestMesh> buckets{[this]() -> TestMesh& { return meshes.emplace_back(); }};
    int chipPart = 0, copyPart = 0;

    explicit Dealt(const SimplifyParams& params = {})
    {
        boardWithTouchingCopy(model, chipPart, copyPart);
        std::string error;
        EXPECT_TRUE(buckets.prepare(model, params, error)) << error;
    }
    // The removed components, after collapsing every bucket.
    int removedAfterCollapse(double maxErrorAbs, double maxDistance)
    {
        buckets.collapse(maxErrorAbs, maxDistance, runOnTwoThreads);
        SimplifyStats stats;
        buckets.addStatsTo(stats);
        return stats.removedComponents;
    }
    // The parts the buckets still hold, one per connected component left.
    std::set<int> partsLeft()
    {
        TestMesh all;
        buckets.appendTo(all);
        vcg::tri::UpdateTopology<TestMesh>::VertexFace(all);
        std::set<int> parts;
        auto part = facePartHandle(all);
        for (const auto& c : connectedComponents(all))
            parts.insert(part[c.faces.front()]);
        return parts;
    }
    // Per part, the buckets holding its faces.
    std::map<int, std::set<std::size_t>> bucketsOfPart()
    {
        std::map<int, std::set<std::size_t>> where;
        for (std::size_t i = 0; i < meshes.size(); ++i) {
            auto part = facePartHandle(meshes[i]);
            for (auto& f : meshes[i].face)
                if (!f.IsD())
                    where[part[f]].insert(i);
        }
        return where;
    }
};

}  // namespace

TEST(CollapseBuckets, EveryComponentGoesWholeIntoOneBucketAndTouchingOnesShareIt)
{
    Dealt d;
    ASSERT_EQ(d.meshes.size(), kMaxCollapseBuckets);  // 40 parts, more than the buckets
    int faces = 0;
    for (const TestMesh& m : d.meshes)
        faces += m.fn;
    EXPECT_EQ(faces, d.model.fn);
    EXPECT_EQ(d.buckets.faces(), d.model.fn);
    const auto where = d.bucketsOfPart();
    EXPECT_EQ(int(where.size()), d.copyPart + 1);
    for (const auto& [part, buckets] : where)
        EXPECT_EQ(buckets.size(), 1u) << "part " << part;  // each part here is one component
    EXPECT_EQ(where.at(d.chipPart), where.at(d.copyPart));

    // Dealt by size: no bucket but the board's more than twice as heavy as an even share
    // of the rest.
    const auto boardBucket = *where.at(0).begin();
    const int rest = d.model.fn - d.meshes[boardBucket].fn;
    for (std::size_t i = 0; i < d.meshes.size(); ++i)
        if (i != boardBucket)
            EXPECT_LE(d.meshes[i].fn, 2 * rest / int(kMaxCollapseBuckets - 1)) << "bucket " << i;

    TestMesh all;
    d.buckets.appendTo(all);
    EXPECT_EQ(all.fn, d.model.fn);
    EXPECT_TRUE(hasParts(all));
}

// The board stays; the chip and its touching copy go too, but only together (one alone would
// open a hole in the other).
TEST(CollapseBuckets, OnlyTheModelsLargestComponentIsNeverRemovedWholeAndTouchingOnesGoTogether)
{
    Dealt d;
    // A bound far above the model's size: every removal is within it.
    EXPECT_EQ(d.removedAfterCollapse(10 * liveDiagonal(d.model), 0.0), d.copyPart);  // every part but the board
    EXPECT_EQ(d.partsLeft(), (std::set<int>{0}));
    d.buckets.release();
}

// In the far field of an LOD chain's pieces a removal is held to the distance bound, not to
// the error bound: a part goes only where its size and the gap it leaves are within it.
TEST(CollapseBuckets, InTheFarFieldAPartIsRemovedOnlyWhereItsGapIsWithinTheDistanceBound)
{
    SimplifyParams params;
    params.farFieldWithinBound = true;
    {
        Dealt d(params);
        d.buckets.startFarField();
        ASSERT_TRUE(d.buckets.inFarField());
        const double diagonal = liveDiagonal(d.model);
        // The error bound is far above the model's size: in the far field the distance rules.
        EXPECT_EQ(d.removedAfterCollapse(10 * diagonal, 1e-4 * diagonal), 0);
        d.buckets.release();
    }
    {
        // Topology kept (tunnels too): collapses within that distance part the touching pair,
        // which may then go, and only the board is left. (A part may also be cut in two at a
        // tunnel first: no fewer removals than parts.)
        SimplifyParams keepTopology = params;
        keepTopology.closeTunnels = false;
        Dealt d(keepTopology);
        d.buckets.startFarField();
        const double diagonal = liveDiagonal(d.model);
        EXPECT_GE(d.removedAfterCollapse(1e-4 * diagonal, 10 * diagonal), d.copyPart);
        EXPECT_EQ(d.partsLeft(), (std::set<int>{0}));
        d.buckets.release();
    }
    // With the topology giving way in the far field (the default), the touching pair may
    // collapse into one another instead: every other part goes.
    Dealt d(params);
    d.buckets.startFarField();
    const double diagonal = liveDiagonal(d.model);
    EXPECT_GE(d.removedAfterCollapse(1e-4 * diagonal, 10 * diagonal), d.copyPart - 2);
    const std::set<int> left = d.partsLeft();
    EXPECT_TRUE(left.count(0));
    for (int part : left)
        EXPECT_TRUE(part == 0 || part == d.chipPart || part == d.copyPart) << "part " << part << " left";
    d.buckets.release();
}

// A small part floating off the rest of the model leaves a gap as wide as its distance from
// the rest when removed, not as wide as itself. It is alone in its bucket, and the part
// nearest it is in another: the gap is measured against the whole model as it was dealt.
TEST(CollapseBuckets, ASmallPartStandingOffTheRestGoesOnlyWhereItsGapIsWithinTheBound)
{
    CadBuilder b;
    b.currentPart = 0;
    stripPlate(b, 100, 80, 1.6, 20);  // the largest: never removed
    b.currentPart = 1;
    b.translate(stripPlate(b, 20, 20, 2, 4), 30, 30, 1.6);  // a block on it
    b.currentPart = 2;
    const double size = std::sqrt(3 * 0.5 * 0.5), gap = 5.0;
    b.translate(stripPlate(b, 0.5, 0.5, 0.5, 2), 40, 40, 3.6 + gap);  // a chip floating above the block
    TestMesh model;
    b.build(model, true);
    auto removedWithin = [&](double bound) {
        std::deque<TestMesh> meshes;
        CollapseBuckets<TestMesh> buckets{[&]() -> TestMesh& { return meshes.emplace_back(); }};
        std::string error;
        EXPECT_TRUE(buckets.prepare(model, SimplifyParams(), error)) << error;
        EXPECT_EQ(meshes.size(), 3u);  // one part per bucket
        buckets.collapse(bound, 0.0, runOnTwoThreads);
        SimplifyStats stats;
        buckets.addStatsTo(stats);
        buckets.release();
        return stats.removedComponents;
    };
    EXPECT_EQ(removedWithin(2 * size), 0);    // its size is within the bound, its gap is not
    EXPECT_EQ(removedWithin(1.2 * gap), 1);   // both are
}

// A part removed at one level is gone from the next: the gap another part's removal leaves
// is measured to what is left. A chip sits just above a block that floats high above the
// board; the chip goes first, and then the block would leave a gap as wide as its height
// above the board, not as wide as its gap to the chip. The three are in three pieces.
TEST(CollapseBuckets, APartRemovedAtOneLevelIsGoneForTheGapsOfTheNext)
{
    CadBuilder b;
    b.currentPart = 0;
    stripPlate(b, 100, 80, 1.6, 20);  // the largest: never removed
    const double height = 10.0;       // the block's gap to the board
    b.currentPart = 1;
    b.translate(stripPlate(b, 2, 2, 2, 2), 40, 40, 1.6 + height);
    b.currentPart = 2;
    b.translate(stripPlate(b, 0.5, 0.5, 0.5, 2), 40, 40, 1.6 + height + 2 + 0.5);  // 0.5 above the block
    TestMesh model;
    b.build(model, true);
    std::deque<TestMesh> meshes;
    CollapseBuckets<TestMesh> buckets{[&]() -> TestMesh& { return meshes.emplace_back(); }};
    std::string error;
    ASSERT_TRUE(buckets.prepare(model, SimplifyParams(), error)) << error;
    ASSERT_EQ(meshes.size(), 3u);  // one part per bucket
    SimplifyStats stats;
    buckets.collapse(1.5, 0.0, runOnTwoThreads);  // above the chip's size and gap, below the block's size
    buckets.addStatsTo(stats);
    EXPECT_EQ(stats.removedComponents, 1);
    buckets.collapse(5.0, 0.0, runOnTwoThreads);  // above the block's size, below its gap to the board
    buckets.addStatsTo(stats);
    EXPECT_EQ(stats.removedComponents, 1);
    buckets.collapse(2 * height, 0.0, runOnTwoThreads);  // above its top's distance to the board too
    buckets.addStatsTo(stats);
    EXPECT_EQ(stats.removedComponents, 2);
    buckets.release();
}

namespace {

// A block (side × side × height) with a blind round pocket `depth` deep in its top: a
// jack's socket. Each flat face is a strip between its outline and the pocket's rim, as
// drilledPlate's are; the pocket's floor and the block's bottom are fans.
void pocketedBlock(TestMesh& m, double side, double height, double radius, double depth, int segments)
{
    CadBuilder b;
    auto ring = [&](double z, bool square) {
        std::vector<int> r(static_cast<std::size_t>(segments));
        for (int j = 0; j < segments; ++j) {
            const double t = 2 * M_PI * j / segments, c = std::cos(t), s = std::sin(t);
            const double scale = square ? 0.5 * side / std::max(std::abs(c), std::abs(s)) : radius;
            r[std::size_t(j)] = b.addPoint(scale * c, scale * s, z);
        }
        return r;
    };
    auto fan = [&](const std::vector<int>& r, double z, bool up) {
        const int centre = b.addPoint(0, 0, z);
        for (std::size_t j = 0; j < r.size(); ++j) {
            const int k = r[(j + 1) % r.size()];
            up ? b.addTriangle(centre, r[j], k) : b.addTriangle(centre, k, r[j]);
        }
    };
    const std::vector<int> outerBottom = ring(0, true), outerTop = ring(height, true);
    const std::vector<int> rimTop = ring(height, false), rimFloor = ring(height - depth, false);
    ringBand(b, outerTop, rimTop);       // the top, facing +z
    ringBand(b, outerBottom, outerTop);  // the sides, facing out
    ringBand(b, rimTop, rimFloor);       // the pocket's wall, facing its axis
    fan(rimFloor, height - depth, true);
    fan(outerBottom, 0, false);
    b.build(m, true);
}

// `result`: `input` after one far-field session of its pieces held to `bound` (the error
// bound far above it), as an LOD chain's far level is made.
void farFieldSession(TestMesh& input, SimplifyParams params, double bound, TestMesh& result)
{
    std::deque<TestMesh> meshes;
    CollapseBuckets<TestMesh> buckets{[&]() -> TestMesh& { return meshes.emplace_back(); }};
    params.farFieldWithinBound = true;
    std::string error;
    ASSERT_TRUE(buckets.prepare(input, params, error)) << error;
    buckets.startFarField();
    buckets.collapse(10 * liveDiagonal(input), bound, runOnTwoThreads);
    buckets.appendTo(result);
    buckets.release();
}

// `result`: `input` after one session of its pieces before the far field, with an error
// bound far above the model and a distance bound of `bound`, held to it
// (holdToDistanceBeforeFarField) or not, as an LOD chain's nearer levels are made.
void midRangeSession(TestMesh& input, double bound, bool heldToDistance, TestMesh& result)
{
    std::deque<TestMesh> meshes;
    CollapseBuckets<TestMesh> buckets{[&]() -> TestMesh& { return meshes.emplace_back(); }};
    SimplifyParams params;
    params.farFieldWithinBound = true;
    std::string error;
    ASSERT_TRUE(buckets.prepare(input, params, error)) << error;
    if (heldToDistance)
        buckets.holdToDistanceBeforeFarField();
    buckets.collapse(10 * liveDiagonal(input), bound, runOnTwoThreads);
    EXPECT_FALSE(buckets.inFarField());
    buckets.appendTo(result);
    buckets.release();
}

}  // namespace

// Before the far field, an LOD chain's collapses are ranked by their quadric error but held
// to the level's budget by the distance they open too: with the error bound far above the
// model, the distance bound alone keeps the result within it, measured independently both
// ways; without it the same session goes far beyond.
TEST(CollapseBuckets, BeforeTheFarFieldCollapsesAreHeldToTheDistanceTheyOpen)
{
    for (const double share : {0.005, 0.02}) {
        TestMesh block;
        pocketedBlock(block, 10, 8, 3, 6, 32);
        const double bound = share * liveDiagonal(block);
        TestMesh held, free;
        midRangeSession(block, bound, true, held);
        midRangeSession(block, bound, false, free);
        const double heldError = symmetricHausdorff(held, block, 200000).max();
        const double freeError = symmetricHausdorff(free, block, 200000).max();
        EXPECT_LT(held.fn, block.fn) << "share " << share;
        EXPECT_LE(heldError, 1.05 * bound) << "share " << share << ", " << held.fn << " of " << block.fn << " faces left";
        EXPECT_GT(freeError, 2 * bound) << "share " << share << ", " << free.fn << " faces left";
    }
}

// In the far field a piece is held to the distance bound both ways: the faces a collapse
// makes stand within it of the input surface in their middles too, not only at their
// corners (a face across the pocket's mouth has its corners on the rim). Measured here
// independently, from 200 000 points on the result.
TEST(CollapseBuckets, InTheFarFieldTheFacesACollapseMakesStayWithinTheDistanceBound)
{
    for (const double share : {0.02, 0.05, 0.1, 0.2}) {
        TestMesh block;
        pocketedBlock(block, 10, 8, 3, 6, 32);
        const double bound = share * liveDiagonal(block);
        TestMesh result;
        farFieldSession(block, SimplifyParams(), bound, result);
        const HausdorffStats back = oneSidedHausdorff(result, block, 200000);
        EXPECT_LE(back.max, 1.05 * bound) << "bound " << 100 * share << " % of the diagonal, " << result.fn << " of "
                                          << block.fn << " faces left";
    }
}

// In the far field of a session held to a distance the topology gives way like the other
// locks: a drilled plate whose hole is within the bound (radius 3 of a 40 x 40 x 2 plate, the
// bound a tenth of its diagonal) closes it and flattens into a two-sided sheet of four faces.
// With tunnels kept (--keep-tunnels) its hole stays open. Both stay within the bound,
// measured independently both ways.
TEST(CollapseBuckets, InTheFarFieldTheTopologyGivesWayUnlessTunnelsAreKept)
{
    for (const bool keepTunnels : {false, true}) {
        TestMesh plate;
        {
            CadBuilder b;
            drilledPlate(b, 40, 2, 3, 16);
            b.build(plate, true);
        }
        SimplifyParams params;
        params.closeTunnels = !keepTunnels;
        const double bound = 0.1 * liveDiagonal(plate);
        TestMesh result;
        farFieldSession(plate, params, bound, result);
        if (keepTunnels)
            EXPECT_GT(result.fn, 8) << "the hole stays open";
        else
            EXPECT_LE(result.fn, 4);
        EXPECT_LE(oneSidedHausdorff(result, plate, 200000).max, 1.05 * bound) << result.fn << " faces";
        EXPECT_LE(oneSidedHausdorff(plate, result, 200000).max, 1.05 * bound) << result.fn << " faces";
    }
}
