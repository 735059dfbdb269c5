// The instanced writer read back by OpenSceneGraph: one shared subgraph per part and level,
// every placement a named node of its own, drawn where its matrix puts it, faces outward
// in a mirror too.
#include "osg_assembly_probe.h"
#include "byte_access.h"

#include "openflight/flt_reader.h"
#include "openflight/instanced_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <algorithm>
#include <iterator>
#include <set>

#include <unistd.h>

using namespace cadlod;
using namespace cadlod::test;

namespace {

// A closed cube of side 2 around `centre`, outward counter-clockwise faces.
flt::Part cube(const std::string& name, flt::Vec3d centre = {0, 0, 0})
{
    flt::Part p;
    p.name = name;
    for (int i = 0; i < 8; ++i)
        p.positions.push_back({centre[0] + (i & 1 ? 1 : -1), centre[1] + (i & 2 ? 1 : -1), centre[2] + (i & 4 ? 1 : -1)});
    const std::uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& f : faces) {
        p.triangles.push_back({f[0], f[1], f[2]});
        p.triangles.push_back({f[0], f[2], f[3]});
    }
    return p;
}

flt::PartDefinition twoLevelCube()
{
    flt::PartDefinition d;
    d.name = "cube";
    flt::Level fine, coarse;
    fine.parts.push_back(cube("box"));
    fine.switchIn = 10;
    coarse.parts.push_back(cube("box"));
    coarse.parts.back().triangles.resize(6);
    coarse.switchOut = 10;
    coarse.switchIn = 100;
    d.levels = {fine, coarse};
    return d;
}

flt::PartPlacement placed(const std::string& name, double x, double scaleX = 1)
{
    flt::PartPlacement p;
    p.name = name;
    p.matrix[0][0] = scaleX;
    p.matrix[0][3] = x;
    return p;
}

flt::InstancedModel threeCubesOneMirrored()
{
    flt::InstancedModel m;
    m.name = "asm";
    m.definitions = {twoLevelCube()};
    m.placements = {placed("Rack_1/A", 0), placed("Rack_1/B", 10), placed("Rack_2/A", 20), placed("Mirror/A", -10, -1)};
    return m;
}

// A name of its own per file: OSG's reader remembers what it read under a name.
std::string writeToTemp(const flt::InstancedModel& m, flt::InstancedWriteStats& stats)
{
    static int files = 0;
    const std::string path = (std::filesystem::temp_directory_path() /
                              ("cadlod_instanced_" + std::to_string(::getpid()) + "_" + std::to_string(++files) + ".flt"))
                                 .string();
    std::string error;
    EXPECT_TRUE(flt::writeInstancedOpenFlightFile(path, m, flt::WriteOptions{}, error, &stats)) << error;
    return path;
}

std::array<double, 3> sub(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

}  // namespace

TEST(InstancedWriter, OsgSharesOneSubgraphPerPartAndLevelAndNamesEveryPlacement)
{
    flt::InstancedWriteStats stats;
    const std::string path = writeToTemp(threeCubesOneMirrored(), stats);
    const OsgAssemblyProbe osg = probeAssemblyWithOsg(path);
    ASSERT_TRUE(osg.loaded);
    EXPECT_EQ(stats.instanceDefinitions, 1u);  // the mirror is placed once: written in place
    EXPECT_EQ(stats.instanceReferences, 3u);
    EXPECT_GE(osg.sharedNodes, 1u);
    EXPECT_EQ(osg.lodSubgraphs, 4u) << "two levels shared, two for the mirror";
    EXPECT_EQ(osg.finestTriangles.size(), 4u * 12);
    for (const char* name : {"Rack_1/A", "Rack_1/B", "Rack_2/A", "Mirror/A"}) {
        ASSERT_EQ(osg.named.count(name), 1u) << name;
        EXPECT_EQ(osg.named.at(name).visits, 1u) << name;
        EXPECT_EQ(osg.named.at(name).triangles, 12u) << name;
    }
    const OsgNamedNode& b = osg.named.at("Rack_1/B");
    EXPECT_NEAR(b.min[0], 9, 1e-5);
    EXPECT_NEAR(b.max[0], 11, 1e-5);
    const OsgNamedNode& mirror = osg.named.at("Mirror/A");
    EXPECT_NEAR(mirror.min[0], -11, 1e-5);
    EXPECT_NEAR(mirror.max[0], -9, 1e-5);
    std::remove(path.c_str());
}

TEST(InstancedWriter, EveryPlacedFaceStaysOutwardMirrorsIncluded)
{
    flt::InstancedModel m = threeCubesOneMirrored();
    m.placements.push_back(placed("Mirror/B", -30, -1));  // two mirrored: a shared mirrored definition
    flt::InstancedWriteStats stats;
    const std::string path = writeToTemp(m, stats);
    const OsgAssemblyProbe osg = probeAssemblyWithOsg(path);
    ASSERT_TRUE(osg.loaded);
    EXPECT_EQ(stats.instanceDefinitions, 2u);
    ASSERT_EQ(osg.finestTriangles.size(), 5u * 12);
    for (const auto& t : osg.finestTriangles) {
        const std::array<double, 3> centroid{(t[0][0] + t[1][0] + t[2][0]) / 3, (t[0][1] + t[1][1] + t[2][1]) / 3,
                                             (t[0][2] + t[1][2] + t[2][2]) / 3};
        const double cubeCentre = std::round(centroid[0] / 10) * 10;
        const auto u = sub(t[1], t[0]), v = sub(t[2], t[0]);
        const std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double outward = n[0] * (centroid[0] - cubeCentre) + n[1] * centroid[1] + n[2] * centroid[2];
        EXPECT_GT(outward, 0) << "a face of the cube at x = " << cubeCentre << " turns inward";
    }
    std::remove(path.c_str());
}

TEST(InstancedWriter, DefinitionsComeBeforeTheirFirstReference)
{
    std::vector<std::uint8_t> bytes;
    std::string error;
    ASSERT_TRUE(flt::writeInstancedOpenFlight(threeCubesOneMirrored(), flt::WriteOptions{}, bytes, error)) << error;
    std::size_t definitionAt = 0, firstReferenceAt = 0, matrices = 0;
    for (std::size_t at = 0; at + 4 <= bytes.size(); at += be16(bytes, at + 2)) {
        const std::uint16_t op = be16(bytes, at);
        if (op == flt::opcode::InstanceDefinition && !definitionAt) {
            definitionAt = at;
            EXPECT_EQ(be16(bytes, at + 6), 1);
        }
        if (op == flt::opcode::InstanceReference && !firstReferenceAt)
            firstReferenceAt = at;
        matrices += op == flt::opcode::Matrix;
        ASSERT_GE(be16(bytes, at + 2), 4);
    }
    EXPECT_GT(definitionAt, 0u);
    EXPECT_LT(definitionAt, firstReferenceAt);
    EXPECT_EQ(matrices, 4u);
}

TEST(InstancedWriter, FaceRecordsAreRefused)
{
    flt::WriteOptions faces;
    faces.geometry = flt::GeometryRecords::Faces;
    std::vector<std::uint8_t> bytes;
    std::string error;
    EXPECT_FALSE(flt::writeInstancedOpenFlight(threeCubesOneMirrored(), faces, bytes, error));
    EXPECT_NE(error.find("Mesh records"), std::string::npos) << error;
}

// A chunk with pieces of its own draws them nearer than its first level: one whose first level
// is drawn from 0 would never show them, and the model is refused, naming the part.
TEST(InstancedWriter, AChunkWhosePiecesAreNeverDrawnIsRefused)
{
    flt::InstancedModel m = threeCubesOneMirrored();
    flt::PartDefinition& cube = m.definitions.front();
    flt::PartChunk piece;
    piece.levels = {cube.levels.front()};
    flt::PartChunk chunk;
    chunk.levels = {cube.levels.back()};  // from 10 on: its piece is drawn nearer
    chunk.children = {piece};
    cube.chunks = {chunk};
    std::vector<std::uint8_t> bytes;
    std::string error;
    EXPECT_TRUE(flt::writeInstancedOpenFlight(m, flt::WriteOptions{}, bytes, error)) << error;

    cube.chunks.front().levels = {cube.levels.front()};  // from 0: nothing nearer
    EXPECT_FALSE(flt::writeInstancedOpenFlight(m, flt::WriteOptions{}, bytes, error));
    EXPECT_NE(error.find("part cube: a chunk's children are never drawn"), std::string::npos) << error;
}

// cadlod's own reader (the MeshLab import, `cadlod info`, `cadlod report`) reads every placement
// as a copy of its part where OSG draws it, the k-th level of every part as level k.
TEST(InstancedWriter, OurReaderPlacesEveryInstanceAsOsgDoes)
{
    flt::InstancedModel m = threeCubesOneMirrored();
    m.placements.push_back(placed("Mirror/B", -30, -1));
    flt::InstancedWriteStats written;
    const std::string path = writeToTemp(m, written);
    flt::LodModel read;
    flt::ReadStats stats;
    std::string error;
    ASSERT_TRUE(flt::readOpenFlightFile(path, read, error, &stats)) << error;
    EXPECT_EQ(stats.instanceReferences, written.instanceReferences);
    ASSERT_EQ(read.levels.size(), 2u);
    const flt::Level& finest = read.levels[flt::finestLevel(read)];
    EXPECT_EQ(finest.triangleCount(), 5u * 12);
    EXPECT_EQ(read.levels[1].triangleCount(), 5u * 6);
    const OsgAssemblyProbe osg = probeAssemblyWithOsg(path, "asm");
    std::multiset<std::array<long, 9>> ours, theirs;
    auto key = [](double x) { return std::lround(x * 1e4); };
    for (const flt::Part& p : finest.parts)
        for (const flt::Triangle& t : p.triangles) {
            std::array<long, 9> k{};
            for (int c = 0; c < 3; ++c)
                for (int d = 0; d < 3; ++d)
                    k[size_t(3 * c + d)] = key(p.positions[t[size_t(c)]][size_t(d)]);
            ours.insert(k);
        }
    for (const auto& t : osg.finestTriangles) {
        std::array<long, 9> k{};
        for (int c = 0; c < 3; ++c)
            for (int d = 0; d < 3; ++d)
                k[size_t(3 * c + d)] = key(t[size_t(c)][size_t(d)]);
        theirs.insert(k);
    }
    // The same triangles, the same corners in the same turn (strips may start a triangle
    // at another corner: compare each triangle from its smallest corner).
    auto canonical = [](std::multiset<std::array<long, 9>> in) {
        std::multiset<std::array<long, 9>> out;
        for (auto t : in) {
            std::array<long, 9> best = t;
            for (int r = 1; r < 3; ++r) {
                std::array<long, 9> turned{};
                for (int c = 0; c < 3; ++c)
                    for (int d = 0; d < 3; ++d)
                        turned[size_t(3 * c + d)] = t[size_t(3 * ((c + r) % 3) + d)];
                best = std::min(best, turned);
            }
            out.insert(best);
        }
        return out;
    };
    const auto a = canonical(ours), b = canonical(theirs);
    EXPECT_EQ(a.size(), b.size());
    std::vector<std::array<long, 9>> onlyOurs, onlyTheirs;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(onlyOurs));
    std::set_difference(b.begin(), b.end(), a.begin(), a.end(), std::back_inserter(onlyTheirs));
    EXPECT_TRUE(onlyOurs.empty() && onlyTheirs.empty())
        << onlyOurs.size() << " triangles only ours, " << onlyTheirs.size() << " only OSG's, the first at x = "
        << (onlyOurs.empty() ? 0 : onlyOurs[0][0]) << " / " << (onlyTheirs.empty() ? 0 : onlyTheirs[0][0]);
    std::remove(path.c_str());
}

// Two clusters of two cubes, the second a copy of the first turned half round about z and
// moved 20 along x, each drawn (from up close, for the probe) as one proxy shape: a box on
// x in [1, 3]. The shape is written once and OSG draws it where each cluster's move puts it.
flt::InstancedModel twoClustersOneProxyShape()
{
    flt::InstancedModel m;
    m.name = "asm";
    m.definitions = {twoLevelCube()};
    m.placements = {placed("A/1", 0), placed("A/2", 4), placed("B/1", 20), placed("B/2", 16)};
    flt::Level shape;
    shape.parts.push_back(cube("proxy", {2, 0, 0}));
    m.proxyShapes = {shape};
    m.clusters.resize(3);
    m.clusters[0].name = "c";
    m.clusters[0].clusters = {1, 2};
    for (std::size_t k : {1u, 2u}) {
        flt::PlacementCluster& c = m.clusters[k];
        c.name = "c." + std::to_string(k);
        c.placements = {2 * k - 2, 2 * k - 1};
        flt::Level range;
        range.name = c.name + " proxy 1";
        range.switchOut = 0;
        range.switchIn = 1e30;
        c.proxies = {range};
        c.shapes = {0};
    }
    m.clusters[2].move = {{{-1, 0, 0, 20}, {0, -1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    m.clusters[2].center = {18, 0, 0};
    m.clusters[2].proxies[0].center = {18, 0, 0};
    return m;
}

TEST(InstancedWriter, AProxyShapeOfACopyIsWrittenOnceAndDrawnWhereItsMovePutsIt)
{
    flt::InstancedWriteStats stats;
    const std::string path = writeToTemp(twoClustersOneProxyShape(), stats);
    EXPECT_EQ(stats.instanceDefinitions, 2u);      // the cube, the proxy shape
    EXPECT_EQ(stats.instanceReferences, 4u + 2u);  // the placements, the proxies
    const OsgAssemblyProbe osg = probeAssemblyWithOsg(path, "asm");
    ASSERT_TRUE(osg.loaded);
    ASSERT_EQ(osg.named.count("c.1 proxy 1"), 1u);
    ASSERT_EQ(osg.named.count("c.2 proxy 1"), 1u);
    const OsgNamedNode& original = osg.named.at("c.1 proxy 1");
    const OsgNamedNode& copy = osg.named.at("c.2 proxy 1");
    EXPECT_EQ(original.triangles, 12u);
    EXPECT_EQ(copy.triangles, 12u);
    EXPECT_NEAR(original.min[0], 1, 1e-5);
    EXPECT_NEAR(original.max[0], 3, 1e-5);
    EXPECT_NEAR(copy.min[0], 17, 1e-5);
    EXPECT_NEAR(copy.max[0], 19, 1e-5);
    std::remove(path.c_str());

    // Drawn by one cluster only, the shape is written in place.
    flt::InstancedModel one = twoClustersOneProxyShape();
    one.clusters[2].proxies.clear();
    one.clusters[2].shapes.clear();
    const std::string alone = writeToTemp(one, stats);
    EXPECT_EQ(stats.instanceDefinitions, 1u);
    EXPECT_EQ(stats.instanceReferences, 4u);
    const OsgAssemblyProbe osgAlone = probeAssemblyWithOsg(alone, "asm");
    ASSERT_EQ(osgAlone.named.count("c.1 proxy 1"), 1u);
    EXPECT_NEAR(osgAlone.named.at("c.1 proxy 1").max[0], 3, 1e-5);
    std::remove(alone.c_str());
}

// The second cluster seen in a mirror (x -> 20 - x): it draws the shape's mirrored form, its
// faces turned back, so that every face OSG draws of either proxy faces out of its cube.
// Two mirrored copies share that form, written once.
TEST(InstancedWriter, AProxyOfAMirroredCopyFacesOut)
{
    flt::InstancedModel m = twoClustersOneProxyShape();
    m.clusters[2].move = {{{-1, 0, 0, 20}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    flt::InstancedWriteStats stats;
    const std::string path = writeToTemp(m, stats);
    EXPECT_EQ(stats.instanceDefinitions, 1u);  // the cube; each form of the shape drawn once
    const OsgAssemblyProbe osg = probeAssemblyWithOsg(path, "asm");
    ASSERT_TRUE(osg.loaded);
    ASSERT_EQ(osg.finestTriangles.size(), 2u * 12);
    std::size_t nearCopy = 0;
    for (const auto& t : osg.finestTriangles) {
        const std::array<double, 3> centroid{(t[0][0] + t[1][0] + t[2][0]) / 3, (t[0][1] + t[1][1] + t[2][1]) / 3,
                                             (t[0][2] + t[1][2] + t[2][2]) / 3};
        const double cubeCentre = centroid[0] > 10 ? 18 : 2;
        nearCopy += centroid[0] > 10;
        const auto u = sub(t[1], t[0]), v = sub(t[2], t[0]);
        const std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double outward = n[0] * (centroid[0] - cubeCentre) + n[1] * centroid[1] + n[2] * centroid[2];
        EXPECT_GT(outward, 0) << "a face of the proxy at x = " << cubeCentre << " turns inward";
    }
    EXPECT_EQ(nearCopy, 12u);
    std::remove(path.c_str());

    m.clusters.push_back(m.clusters[2]);
    m.clusters.back().name = "c.3";
    m.clusters.back().placements.clear();
    m.clusters.back().proxies[0].name = "c.3 proxy 1";
    m.clusters[0].clusters.push_back(3);
    const std::string twice = writeToTemp(m, stats);
    EXPECT_EQ(stats.instanceDefinitions, 2u);  // the cube, the shape's mirrored form
    EXPECT_EQ(stats.instanceReferences, 4u + 2u);
    std::remove(twice.c_str());
}

TEST(InstancedWriter, AReferenceWithoutItsDefinitionIsAnError)
{
    std::vector<std::uint8_t> bytes;
    std::string error;
    ASSERT_TRUE(flt::writeInstancedOpenFlight(threeCubesOneMirrored(), flt::WriteOptions{}, bytes, error)) << error;
    for (std::size_t at = 0; at + 4 <= bytes.size(); at += be16(bytes, at + 2))
        if (be16(bytes, at) == flt::opcode::InstanceReference)
            bytes[at + 7] = 9;  // definition 9: none
    flt::LodModel read;
    EXPECT_FALSE(flt::readOpenFlight(bytes.data(), bytes.size(), read, error));
    EXPECT_NE(error.find("refers to definition 9"), std::string::npos) << error;
}
