// A long part in chunks (part_chunks.h): every level's triangles are in exactly one chunk;
// each chunk switches where its own level holds at the chunk's nearest point, so the
// chunks switch far nearer than the whole part's one LOD node may.
#include "assembly/part_chunks.h"

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
            triangles += chunk[k].triangleCount();
        EXPECT_EQ(triangles, levels[k].triangleCount()) << "level " << k;
    }
    const double wholeReach = std::hypot(0.5, 0.005);
    for (const auto& chunk : chunks) {
        ASSERT_EQ(chunk.size(), 3u);
        const double reach = std::hypot(0.125, 0.005);
        EXPECT_NEAR(chunk[1].switchOut, switchAtNearestPoint(1.0, reach), 1e-9);
        EXPECT_NEAR(chunk[2].switchOut, switchAtNearestPoint(4.0, reach), 1e-9);
        EXPECT_DOUBLE_EQ(chunk[0].switchIn, chunk[1].switchOut);
        EXPECT_LT(chunk[1].switchOut, switchAtNearestPoint(1.0, wholeReach) / 2);
    }
    EXPECT_TRUE(chunkLevels(levels, 1.0, kNeverCulled).empty());  // smaller than the smallest part cut

    // Drawn only while the eye is nearer than the whole part's first simplified level (held at
    // its nearest point) to its centre, a chunk keeps the levels it shows there: level 2,
    // from 4.1 m off a chunk's centre, never is within 3.4 m of it.
    const double drawnTo = switchAtNearestPoint(1.0, wholeReach);
    for (const auto& chunk : chunkLevels(levels, 0.0, drawnTo)) {
        ASSERT_EQ(chunk.size(), 2u);
        EXPECT_LT(chunk[1].switchOut, drawnTo);
        EXPECT_GE(chunk[1].switchIn, kNeverCulled);
    }

    // 128 triangles would give each of the four chunks 32, fewer than kLeastChunkTriangles:
    // four draw calls where one draws it all.
    const std::vector<flt::Level> few{strip(64, 0, 1.0), strip(16, 1.0, 4.0), strip(4, 4.0, 1e30)};
    EXPECT_LT(few.front().triangleCount(), 4 * kLeastChunkTriangles);
    EXPECT_TRUE(chunkLevels(few, 0.0, kNeverCulled).empty());
}

}  // namespace cadlod::test
