// A long part in chunks (part_chunks.h): every level's triangles are in exactly one chunk;
// each chunk switches where its own level holds at the chunk's nearest point, so the
// chunks switch far nearer than the whole part's one LOD node may; a chunk whose first
// simplified level waits for that floor is cut again, down to pieces of a draw call's
// triangles; triangles longer than a chunk, and what stands for them, are chunks of their
// own, cells only across the axes they are long on.
#include "assembly/part_chunks.h"

#include "assembly/hierarchical_lod.h"  // kDrawCallTriangles
#include "lod/cluster_tree.h"           // Box3
#include "lod/nearest_point.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

namespace cadlod::test {
namespace {

// A level of the one part `part`, named "bar", centred on `centre`.
flt::Level levelOf(flt::Part part, const flt::Vec3d& centre, double switchOut, double switchIn)
{
    flt::Level level;
    part.name = "bar";
    level.parts.push_back(std::move(part));
    level.center = centre;
    level.switchOut = switchOut;
    level.switchIn = switchIn;
    return level;
}

// A strip 1 m long and 1 cm wide along x, of `cells` quads.
flt::Level strip(int cells, double switchOut, double switchIn)
{
    flt::Part part;
    for (int i = 0; i <= cells; ++i) {
        part.positions.push_back({double(i) / cells, 0, 0});
        part.positions.push_back({double(i) / cells, 0.01, 0});
    }
    for (std::uint32_t i = 0; i < std::uint32_t(cells); ++i) {
        part.triangles.push_back({2 * i, 2 * i + 2, 2 * i + 3});
        part.triangles.push_back({2 * i, 2 * i + 3, 2 * i + 1});
    }
    return levelOf(std::move(part), {0.5, 0.005, 0}, switchOut, switchIn);
}

// A tube 2 m long along z and 1 m across, of `sides` pairs of slivers the length of the tube,
// as a CAD system tessellates a cylinder.
flt::Level tube(int sides, double switchOut, double switchIn)
{
    flt::Part part;
    for (int i = 0; i < sides; ++i) {
        const double angle = 2 * M_PI * i / sides;
        part.positions.push_back({0.5 * std::cos(angle), 0.5 * std::sin(angle), 0});
        part.positions.push_back({0.5 * std::cos(angle), 0.5 * std::sin(angle), 2});
    }
    for (std::uint32_t i = 0; i < std::uint32_t(sides); ++i) {
        const std::uint32_t next = (i + 1) % std::uint32_t(sides);
        part.triangles.push_back({2 * i, 2 * next, 2 * next + 1});
        part.triangles.push_back({2 * i, 2 * next + 1, 2 * i + 1});
    }
    return levelOf(std::move(part), {0, 0, 1}, switchOut, switchIn);
}

// How far a polygon of `sides` stands inside the tube's circle.
double chordError(int sides)
{
    return 0.5 * (1 - std::cos(M_PI / sides));
}

// The errors of levels that lie in their finest level's plane.
std::vector<double> exact(const std::vector<flt::Level>& levels)
{
    return std::vector<double>(levels.size(), 0.0);
}

// A plate 1 m by 0.5 m, 0.1 m below the strip, in two triangles.
flt::Level withPlate(flt::Level level)
{
    flt::Part plate;
    plate.name = "plate";
    plate.positions = {{0, 0, -0.1}, {1, 0, -0.1}, {1, 0.5, -0.1}, {0, 0.5, -0.1}};
    plate.triangles = {{0, 1, 2}, {0, 2, 3}};
    level.parts.push_back(plate);
    return level;
}

std::size_t trianglesOf(const flt::Level& level, const std::string& partName)
{
    std::size_t n = 0;
    for (const flt::Part& part : level.parts)
        n += part.name == partName ? part.triangles.size() : 0;
    return n;
}

// Whether a triangle of `level` in the plane of `p` holds it.
bool covers(const flt::Level& level, const flt::Vec3d& p)
{
    for (const flt::Part& part : level.parts)
        for (const flt::Triangle& t : part.triangles) {
            const flt::Vec3d &a = part.positions[t[0]], &b = part.positions[t[1]], &c = part.positions[t[2]];
            if (std::abs(a[2] - p[2]) > 1e-12 || std::abs(b[2] - p[2]) > 1e-12 || std::abs(c[2] - p[2]) > 1e-12)
                continue;
            const auto side = [&](const flt::Vec3d& u, const flt::Vec3d& v) {
                return (v[0] - u[0]) * (p[1] - u[1]) - (v[1] - u[1]) * (p[0] - u[0]);
            };
            const double d0 = side(a, b), d1 = side(b, c), d2 = side(c, a);
            if ((d0 >= -1e-15 && d1 >= -1e-15 && d2 >= -1e-15) || (d0 <= 1e-15 && d1 <= 1e-15 && d2 <= 1e-15))
                return true;
        }
    return false;
}

// Every level `chunk` holds covers the centroid of each of its finest triangles: whatever
// level its neighbours show, the chunk leaves no hole where its own finest level was.
void expectEveryLevelCoversItsFinest(const flt::PartChunk& chunk)
{
    ASSERT_TRUE(chunk.children.empty());
    for (const flt::Part& part : chunk.levels.front().parts)
        for (const flt::Triangle& t : part.triangles) {
            flt::Vec3d c{};
            for (int a = 0; a < 3; ++a)
                c[a] = (part.positions[t[0]][a] + part.positions[t[1]][a] + part.positions[t[2]][a]) / 3;
            for (std::size_t k = 1; k < chunk.levels.size(); ++k)
                EXPECT_TRUE(covers(chunk.levels[k], c)) << chunk.levels[k].name << " at x " << c[0];
        }
}

}  // namespace

TEST(PartChunks, EveryTriangleInOneChunkEachSwitchingAtItsOwnNearestPoint)
{
    const std::vector<flt::Level> levels{strip(256, 0, 1.0), strip(16, 1.0, 4.0), strip(4, 4.0, 1e30)};
    const auto chunks = chunkLevels("bar", levels, exact(levels), 0.0, kNeverCulled);
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
    for (const auto& chunk : chunks) {  // named after the part, so that a reader can tell whose they are
        EXPECT_EQ(chunk.name.rfind("bar chunk ", 0), 0u) << chunk.name;
        for (std::size_t k = 0; k < chunk.levels.size(); ++k)
            EXPECT_EQ(chunk.levels[k].name, chunk.name + " LOD" + std::to_string(k));
    }
    // Smaller than the smallest part cut:
    EXPECT_TRUE(chunkLevels("bar", levels, exact(levels), 1.0, kNeverCulled).empty());

    // Drawn only while the eye is nearer than the whole part's first simplified level (held at
    // its nearest point) to its centre, a chunk keeps the levels it shows there: level 2,
    // from 4.1 m off a chunk's centre, never is within 3.4 m of it.
    const double drawnTo = switchAtNearestPoint(1.0, wholeReach);
    for (const auto& chunk : chunkLevels("bar", levels, exact(levels), 0.0, drawnTo)) {
        ASSERT_EQ(chunk.levels.size(), 2u);
        EXPECT_LT(chunk.levels[1].switchOut, drawnTo);
        EXPECT_GE(chunk.levels[1].switchIn, kNeverCulled);
    }

    // 128 triangles would give each of the four chunks 32, fewer than kLeastChunkTriangles:
    // the strip is cut in halves instead, of 64 each.
    const std::vector<flt::Level> few{strip(64, 0, 1.0), strip(16, 1.0, 4.0), strip(4, 4.0, 1e30)};
    EXPECT_LT(few.front().triangleCount(), 4 * kLeastChunkTriangles);
    const auto halves = chunkLevels("bar", few, exact(few), 0.0, kNeverCulled);
    ASSERT_EQ(halves.size(), 2u);
    for (const auto& half : halves) {
        EXPECT_EQ(half.levels.front().triangleCount(), 64u);
        EXPECT_NEAR(half.levels[1].switchOut, switchAtNearestPoint(1.0, std::hypot(0.25, 0.005)), 1e-9);
    }
    // 64 triangles, 32 a half: four or two draw calls where one draws it all.
    const std::vector<flt::Level> fewer{strip(32, 0, 1.0), strip(16, 1.0, 4.0), strip(4, 4.0, 1e30)};
    EXPECT_TRUE(chunkLevels("bar", fewer, exact(fewer), 0.0, kNeverCulled).empty());
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
        for (const flt::Level& level : chunk.levels) {  // held at its own nearest point
            if (level.switchOut > 0) {
                EXPECT_GE(level.switchOut, kNearestPointReach * level.reachFrom(level.center) * (1 - 1e-9));
            }
        }
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
    const std::vector<flt::PartChunk> chunks = chunkLevels("bar", levels, exact(levels), 0.0, drawnTo);
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

// A plate's two triangles under a finely cut strip, as a CAD part holds a face's few long
// triangles beside many small ones. Taken by a cell, a plate triangle would give that chunk
// the whole part's reach: the chunk would hold its finest level as long as the part does.
// The plate is a chunk of its own on every level; the strip's coarse triangles, though
// longer than a cell, stand for short ones and stay with the cells, whose finest levels
// reach no farther than their own cell.
TEST(PartChunks, LongTrianglesAndWhatStandsForThemAreAChunkOfTheirOwn)
{
    const std::vector<flt::Level> levels{withPlate(strip(1024, 0, 1.0)), withPlate(strip(64, 1.0, 4.0)),
                                         withPlate(strip(2, 4.0, 1e30))};
    const std::vector<flt::PartChunk> chunks = chunkLevels("bar", levels, exact(levels), 0.0, kNeverCulled);
    ASSERT_EQ(chunks.size(), 5u);  // four along the strip, and the plate
    std::size_t longChunks = 0, finest = 0;
    for (const flt::PartChunk& chunk : chunks) {
        ASSERT_TRUE(chunk.children.empty());  // the strip's chunks switch by their error
        ASSERT_EQ(chunk.levels.size(), levels.size());
        const bool isLong = chunk.levels.front().name.find("chunk long") != std::string::npos;
        longChunks += isLong ? 1 : 0;
        finest += chunk.levels.front().triangleCount();
        for (const flt::Level& level : chunk.levels) {
            EXPECT_EQ(trianglesOf(level, "plate"), isLong ? 2u : 0u) << level.name;
            EXPECT_EQ(trianglesOf(level, "bar"), isLong ? 0u : level.triangleCount()) << level.name;
        }
        if (!isLong) {  // a quarter of the strip: the plate's 0.5 m width is not the chunk's
            EXPECT_LE(chunk.levels.front().reachFrom(chunk.levels.front().center), std::hypot(0.125, 0.005) + 1e-9);
        }
        expectEveryLevelCoversItsFinest(chunk);
    }
    EXPECT_EQ(longChunks, 1u);
    EXPECT_EQ(finest, levels.front().triangleCount());
}

// A coarse triangle across a chunk border stands for finest triangles on both sides. Given to
// the chunk of its centroid alone, it would leave a hole in its neighbour wherever the
// neighbour shows that level and the chunk of its centroid still its finest: it is in both,
// each time cut to the chunk's box, which its coarse levels then reach no farther than.
TEST(PartChunks, ACoarseTriangleAcrossABorderIsInEveryChunkItStandsForCutToItsBox)
{
    const std::vector<flt::Level> levels{strip(1024, 0, 1.0), strip(3, 1.0, 4.0), strip(1, 4.0, 1e30)};
    const std::vector<flt::PartChunk> chunks = chunkLevels("bar", levels, exact(levels), 0.0, kNeverCulled);
    ASSERT_EQ(chunks.size(), 4u);
    std::size_t finest = 0;
    for (const flt::PartChunk& chunk : chunks) {
        finest += chunk.levels.front().triangleCount();
        expectEveryLevelCoversItsFinest(chunk);
        const flt::Vec3d& centre = chunk.levels.front().center;
        for (const flt::Level& level : chunk.levels)
            EXPECT_LE(level.reachFrom(centre), chunk.levels.front().reachFrom(centre) * (1 + 1e-3)) << level.name;
    }
    EXPECT_EQ(finest, levels.front().triangleCount());  // each finest triangle in one chunk
}

// Every triangle of a tube is longer than a chunk along its axis. All in one long chunk, they
// would be as far-reaching as the tube, and the tube not cut at all: they go to columns along
// the axis, each a cell of the grid across it, by where they lie around the tube, and each
// column switches by its own reach.
TEST(PartChunks, ATubesSliversGoToColumnsByWhereTheyLieAroundIt)
{
    const std::vector<flt::Level> levels{tube(512, 0, 1.0), tube(64, 1.0, 4.0), tube(8, 4.0, 1e30)};
    const std::vector<double> errors{0.0, chordError(64), chordError(8)};
    const std::vector<flt::PartChunk> chunks = chunkLevels("bar", levels, errors, 0.0, kNeverCulled);
    ASSERT_GE(chunks.size(), 8u);  // the cells of a 4 x 4 grid that the circle crosses
    const double wholeReach = std::hypot(0.5, 0.5, 1.0);
    std::size_t finest = 0;
    for (const flt::PartChunk& chunk : chunks) {
        const flt::Level& first = chunk.levels.front();
        EXPECT_EQ(first.name.rfind("bar chunk long z ", 0), 0u) << first.name;
        finest += first.triangleCount();
        Box3 box;
        for (const flt::Vec3d& p : first.parts.front().positions)
            box.add(p);
        EXPECT_LE(box.hi[0] - box.lo[0], 0.25 + 0.01) << first.name;  // a quarter across, and a sliver
        EXPECT_LE(box.hi[1] - box.lo[1], 0.25 + 0.01) << first.name;
        ASSERT_GE(chunk.levels.size(), 2u);
        EXPECT_LT(chunk.levels[1].switchOut, switchAtNearestPoint(1.0, wholeReach) * 0.9) << first.name;
    }
    EXPECT_EQ(finest, levels.front().triangleCount());  // each finest triangle in one chunk
}

}  // namespace cadlod::test
