// Every file the writer makes is read back by OpenSceneGraph's OpenFlight loader and
// checked: LOD nodes, ranges, centers, triangles per level, positions and normals,
// colors, names, culling and units.
#include "openflight/flt_reader.h"
#include "openflight/flt_writer.h"
#include "model_fixtures.h"
#include "osg_probe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace cadlod::flt;
using namespace cadlod::test;

namespace {

std::string scratch(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() / "cadlod_flt_tests";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

std::string writeModel(const LodModel& model, const WriteOptions& o, const std::string& name)
{
    const std::string path =
        scratch((o.geometry == GeometryRecords::Meshes ? "meshes_" : "faces_") + name);
    std::string error;
    EXPECT_TRUE(writeOpenFlightFile(path, model, o, error)) << error;
    return path;
}

bool contains(const std::vector<std::string>& names, const std::string& name)
{
    return std::find(names.begin(), names.end(), name) != names.end();
}

class OsgReadback : public ::testing::TestWithParam<GeometryRecords> {};

}  // namespace

TEST_P(OsgReadback, LodSetRangesCentersTrianglesAndNames)
{
    const LodModel model = threeLevelModel();
    WriteOptions o;
    o.geometry = GetParam();
    const OsgProbe probe = probeWithOsg(writeModel(model, o, "lodset.flt"));
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.lods.size(), 3u);
    EXPECT_TRUE(probe.outsideLods.empty());
    for (std::size_t l = 0; l < 3; ++l) {
        const Level& level = model.levels[l];
        const OsgLodChild& lod = probe.lods[l];
        EXPECT_FLOAT_EQ(lod.minRange, float(level.switchOut));
        EXPECT_FLOAT_EQ(lod.maxRange, float(level.switchIn));
        for (int c = 0; c < 3; ++c)
            EXPECT_FLOAT_EQ(lod.center[c], float(level.center[c]));
        const auto expected = flatTriangles(level);
        const auto got = osgTriangles(lod.triangles);
        ASSERT_EQ(got.size(), expected.size()) << "level " << l;
        const TriangleDiff d = compareTriangles(expected, got);
        EXPECT_LT(d.position, 1e-5f) << "level " << l;
        EXPECT_LT(d.normal, 1e-5f) << "level " << l;
        EXPECT_TRUE(contains(lod.names, level.parts[0].name)) << "long part name under level " << l;
        EXPECT_TRUE(contains(lod.names, level.parts[1].name));
    }
    EXPECT_TRUE(contains(probe.names, "lod_level_1"));
}

TEST_P(OsgReadback, SingleLevelHasNoLodNodeAndKeepsColors)
{
    const LodModel model = singleLevelModel(6);
    WriteOptions o;
    o.geometry = GetParam();
    const OsgProbe probe = probeWithOsg(writeModel(model, o, "single.flt"));
    ASSERT_TRUE(probe.loaded);
    EXPECT_TRUE(probe.lods.empty());
    const auto expected = flatTriangles(model.levels[0]);
    const auto got = osgTriangles(probe.outsideLods);
    ASSERT_EQ(got.size(), expected.size());
    EXPECT_LT(compareTriangles(expected, got).position, 1e-5f);
    int red = 0, blue = 0;
    for (const OsgTriangle& t : probe.outsideLods) {
        red += t.color[0] > 0.85f && t.color[2] < 0.15f;
        blue += t.color[2] > 0.85f && t.color[0] < 0.15f;
    }
    EXPECT_EQ(red, int(model.levels[0].parts[0].triangles.size()));
    EXPECT_EQ(blue, int(model.levels[0].parts[1].triangles.size()));
}

TEST_P(OsgReadback, DrawTypeControlsBackFaceCulling)
{
    WriteOptions o;
    o.geometry = GetParam();
    const OsgProbe single = probeWithOsg(writeModel(singleLevelModel(2), o, "single_sided.flt"));
    ASSERT_TRUE(single.loaded);
    EXPECT_TRUE(single.cullsBackFaces);
    EXPECT_FALSE(single.disablesCulling);
    o.drawType = DrawType::TwoSided;
    const OsgProbe both = probeWithOsg(writeModel(singleLevelModel(2), o, "two_sided.flt"));
    ASSERT_TRUE(both.loaded);
    EXPECT_TRUE(both.disablesCulling);
    EXPECT_FALSE(both.cullsBackFaces);
}

TEST_P(OsgReadback, HeaderUnitsAreHonoured)
{
    LodModel model = singleLevelModel(3);
    model.units = Units::Inches;
    WriteOptions o;
    o.geometry = GetParam();
    const std::string path = writeModel(model, o, "inches.flt");
    // A second path: OpenSceneGraph 3.6 reuses a file's first load within a process.
    const std::string copy = path + ".copy.flt";
    std::filesystem::copy_file(path, copy, std::filesystem::copy_options::overwrite_existing);
    const OsgProbe raw = probeWithOsg(path, "noUnitsConversion");
    const OsgProbe meters = probeWithOsg(copy, "convertToMeters");
    ASSERT_TRUE(raw.loaded && meters.loaded);
    ASSERT_EQ(raw.outsideLods.size(), meters.outsideLods.size());
    float rawMax = 0, meterMax = 0;
    for (std::size_t t = 0; t < raw.outsideLods.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            rawMax = std::max(rawMax, raw.outsideLods[t].position[k][0]);
            meterMax = std::max(meterMax, meters.outsideLods[t].position[k][0]);
        }
    EXPECT_FLOAT_EQ(rawMax, 4.0f);
    EXPECT_NEAR(meterMax, 4.0f * 0.0254f, 1e-6);
}

TEST_P(OsgReadback, ObjectPerLevelGroupsAllParts)
{
    WriteOptions o;
    o.geometry = GetParam();
    o.objects = ObjectGrouping::PerLevel;
    const LodModel model = threeLevelModel();
    const OsgProbe probe = probeWithOsg(writeModel(model, o, "per_level.flt"));
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.lods.size(), 3u);
    for (std::size_t l = 0; l < 3; ++l) {
        EXPECT_EQ(probe.lods[l].triangles.size(), model.levels[l].triangleCount());
        EXPECT_FALSE(contains(probe.lods[l].names, model.levels[l].parts[0].name));
    }
}

INSTANTIATE_TEST_SUITE_P(Geometry, OsgReadback,
                         ::testing::Values(GeometryRecords::Meshes, GeometryRecords::Faces),
                         [](const auto& info) { return info.param == GeometryRecords::Meshes ? "Meshes" : "Faces"; });

// More than 65535 vertices in one part: Local Vertex Pool and strip primitive go on in
// Continuation records, indices are 32-bit.
TEST(OsgReadbackLarge, PartWithMoreThan65535VerticesInMeshRecords)
{
    LodModel model;
    model.levels.emplace_back();
    model.levels[0].parts.push_back(wavySheet(260, 10.0, "big_part", {0.5f, 0.5f, 0.5f, 1.0f}));
    ASSERT_GT(model.levels[0].parts[0].positions.size(), 65535u);
    const OsgProbe probe = probeWithOsg(writeModel(model, {}, "large.flt"));
    ASSERT_TRUE(probe.loaded);
    const auto expected = flatTriangles(model.levels[0]);
    const auto got = osgTriangles(probe.outsideLods);
    ASSERT_EQ(got.size(), expected.size());
    const TriangleDiff d = compareTriangles(expected, got);
    EXPECT_LT(d.position, 1e-5f);
    EXPECT_LT(d.normal, 1e-5f);
}

// A polygon with more vertices than one Vertex List record holds: the list is split
// over several records, which OpenSceneGraph and our reader join into one face.
TEST(OsgReadbackLarge, SplitVertexListIsOnePolygon)
{
    constexpr int n = 20000;
    static_assert(n > int(cadlod::flt::size::MaxVertexListEntries), "must overflow one record");
    std::vector<std::uint8_t> bytes;
    ByteWriter w(bytes);
    writeHeader(w, HeaderFields{});
    writeColorPalette(w);
    writeMaterial(w, MaterialFields{});
    writeVertexPalette(w, std::uint32_t(8 + n * size::VertexNormal));
    const Vec3f up{0, 0, 1};
    std::vector<std::uint32_t> offsets;
    for (int i = 0; i < n; ++i) {
        const double a = 2.0 * M_PI * i / n;
        writeVertex(w, {std::cos(a), std::sin(a), 0.0}, &up, nullptr);
        offsets.push_back(std::uint32_t(8 + i * size::VertexNormal));
    }
    writePush(w);
    writeGroup(w, "g");
    writePush(w);
    writeObject(w, "disc");
    writePush(w);
    writeFace(w, Appearance{});
    writePush(w);
    writeVertexList(w, offsets);
    writePop(w);
    writePop(w);
    writePop(w);
    writePop(w);
    const std::string path = scratch("big_polygon.flt");
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), long(bytes.size()));

    const OsgProbe probe = probeWithOsg(path);
    ASSERT_TRUE(probe.loaded);
    EXPECT_EQ(probe.outsideLods.size(), std::size_t(n - 2)) << "one convex polygon, tessellated";

    LodModel model;
    std::string error;
    ASSERT_TRUE(readOpenFlightFile(path, model, error)) << error;
    ASSERT_EQ(model.levels.size(), 1u);
    EXPECT_EQ(model.triangleCount(), std::size_t(n - 2));
    EXPECT_EQ(model.levels[0].parts[0].positions.size(), std::size_t(n));
}
