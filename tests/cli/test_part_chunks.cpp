// A long part in chunks (part_chunks.h): every level's triangles are in exactly one chunk;
// each chunk switches where its own level holds at the chunk's nearest point, so the
// chunks switch far nearer than the whole part's one LOD node may; a chunk whose first
// simplified level waits for that floor is cut again, down to pieces of a draw call's
// triangles.
#include "assembly/part_chunks.h"

#include "assembly/hierarchical_lod.h"  // kDrawCallTriangles
#include "lod/nearest_point.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cadlod::test {
namespace {

// A strip 1 m long and 1 cm wide along x, of `cells` quads.
flt::Level strip(int cells, double switchOut, double switchIn)
{
    flt::Level level;
    flt::Part part;
    part.name = "bar";
    for (int i = 0; i <= cells; ++i) {
        part.positions.push_back({double(i) / cells, 0, 0});
        part.positions.push_back({double(i) / cells, 0.01, 0});
    }
    for (std::uint32_t i = 0; i < std::uint32_t(cells); ++i) {
        part.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
        part.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
    }
    level.parts.push_back(part);
    level.center = {0.5, 0.005, 0};
    level.switchOut = switchOut;
    level.switchIn = switchIn;
    return level;
}

}  // namespace

TEST(PartChunks, EveryTriangleInOneChunkEachSwitchingAtItsOwnNearestPoint)
{
    const std::vector<flt::Level> levels{strip(256, 0, 1.0), strip(16, 1.0, 4.0), strip(4, 4.0, 1e30)};
    const auto chunks = chunkLevels(levels, 0.0, kNeverCulled);
    ASSERT_EQ(chunks.size(), 4u);  // four along x; the strip is flat in y and z
    for (std::size_t k = 0; k < levels.size(); ++k) {
        std::size_t triangles = 0;
        for (const auto& chunk : chunks)
            triangles += chunk.levels[k].triangleCount();
        EXPECT_EQ(triangles, levels[k].triangleCount()) << "level " << k;
    }
    const double wholeReach = std::hypot(0.5, 0.005);
    for (const auto& chunk : chunks) {
        ASSERT_EQ(chunk.levels.size(), 3u);
        EXPECT_TRUE(chunk.children.empty());  // its first level is switched by its error, not the floor
        const double reach = std::hypot(0.125, 0.005);
        EXPECT_NEAR(chunk.levels[1].switchOut, switchAtNearestPoint(1.0, reach), 1e-9);
        EXPECT_NEAR(chunk.levels[2].switchOut, switchAtNearestPoint(4.0, reach), 1e-9);
        EXPECT_DOUBLE_EQ(chunk.levels[0].switchIn, chunk.levels[1].switchOut);
        EXPECT_LT(chunk.levels[1].switchOut, switchAtNearestPoint(1.0, wholeReach) / 2);
    }
    EXPECT_TRUE(chunkLevels(levels, 1.0, kNeverCulled).empty());  // smaller than the smallest part cut

    // Drawn only while the eye is nearer than the whole part's first simplified level (held at
    // its nearest point) to its centre, a chunk keeps the levels it shows there: level 2,
    // from 4.1 m off a chunk's centre, never is within 3.4 m of it.
    const double drawnTo = switchAtNearestPoint(1.0, wholeReach);
    for (const auto& chunk : chunkLevels(levels, 0.0, drawnTo)) {
        ASSERT_EQ(chunk.levels.size(), 2u);
        EXPECT_LT(chunk.levels[1].switchOut, drawnTo);
        EXPECT_GE(chunk.levels[1].switchIn, kNeverCulled);
    }

    // 128 triangles would give each of the four chunks 32, fewer than kLeastChunkTriangles:
    // four draw calls where one draws it all.
    const std::vector<flt::Level> few{strip(64, 0, 1.0), strip(16, 1.0, 4.0), strip(4, 4.0, 1e30)};
    EXPECT_LT(few.front().triangleCount(), 4 * kLeastChunkTriangles);
    EXPECT_TRUE(chunkLevels(few, 0.0, kNeverCulled).empty());
}

namespace {

struct ChunkTally {
    std::size_t finestTriangles = 0;  // in the leaves' finest levels
    std::size_t deepest = 0;
    double smallestFirstSwitch = 1e300;  // where a leaf's first simplified level switches in
};

// Walks `chunks` below an owner whose near range is `drawnTo`, checking each chunk's ranges.
void walk(const std::vector<flt::PartChunk>& chunks, double drawnTo, std::size_t depth, ChunkTally& tally)
{
    for (const flt::PartChunk& chunk : chunks) {
        ASSERT_FALSE(chunk.levels.empty());
        for (std::size_t k = 0; k + 1 < chunk.levels.size(); ++k)
            EXPECT_DOUBLE_EQ(chunk.levels[k].switchIn, chunk.levels[k + 1].switchOut);
        EXPECT_GE(chunk.levels.back().switchIn, kNeverCulled);
        EXPECT_LT(chunk.levels.front().switchOut, drawnTo);
        for (const flt::Level& level : chunk.levels)  // held at its own nearest point
            if (level.switchOut > 0)
                EXPECT_GE(level.switchOut, kNearestPointReach * level.reachFrom(level.center) * (1 - 1e-9));
        if (chunk.children.empty()) {
            EXPECT_EQ(chunk.levels.front().switchOut, 0.0);
            tally.finestTriangles += chunk.levels.front().triangleCount();
            tally.deepest = std::max(tally.deepest, depth);
            if (chunk.levels.size() > 1)
                tally.smallestFirstSwitch = std::min(tally.smallestFirstSwitch, chunk.levels[1].switchOut);
            continue;
        }
        EXPECT_GT(chunk.childrenDrawnTo(), 0.0);
        ChunkTally below;
        walk(chunk.children, chunk.childrenDrawnTo(), depth + 1, below);
        EXPECT_GE(double(below.finestTriangles), kDrawCallTriangles * double(chunk.children.size()));
        tally.finestTriangles += below.finestTriangles;
        tally.deepest = std::max(tally.deepest, below.deepest);
        tally.smallestFirstSwitch = std::min(tally.smallestFirstSwitch, below.smallestFirstSwitch);
    }
}

}  // namespace

// A strip whose first simplified level is finer than a pixel from a centimetre off: a chunk a
// quarter of it long would still hold that level back to six times its reach, so each chunk
// is cut in halves, and they again, until a piece would hold fewer triangles than a draw call
// costs. The finest level is drawn once, in the leaves; every piece switches where its own
// level holds at its nearest point, the smallest ones far nearer than the first chunks.
TEST(PartChunks, AChunkWaitingForTheNearestPointFloorIsCutAgain)
{
    const std::vector<flt::Level> levels{strip(4096, 0, 0.01), strip(256, 0.01, 4.0), strip(4, 4.0, 1e30)};
    const double wholeReach = std::hypot(0.5, 0.005);
    const double drawnTo = switchAtNearestPoint(0.01, wholeReach);
    const std::vector<flt::PartChunk> chunks = chunkLevels(levels, 0.0, drawnTo);
    ASSERT_EQ(chunks.size(), 4u);
    ChunkTally tally;
    walk(chunks, drawnTo, 0, tally);
    EXPECT_EQ(tally.finestTriangles, levels.front().triangleCount());
    // 2048 triangles a chunk, halved while the halves hold 256 or more: three depths below.
    EXPECT_EQ(tally.deepest, 3u);
    EXPECT_EQ(chunkCount(chunks), 4u * (1 + 2 + 4 + 8));
    const double leafReach = std::hypot(0.125 / 8, 0.005);
    EXPECT_NEAR(tally.smallestFirstSwitch, switchAtNearestPoint(0.01, leafReach), 1e-9);
    EXPECT_LT(tally.smallestFirstSwitch, chunks.front().childrenDrawnTo() / 4);
}

}  // namespace cadlod::test
