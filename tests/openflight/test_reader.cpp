// Our OpenFlight reader: round trips of the writer's output, files written by
// OpenSceneGraph, and corrupt or truncated input (errors with offsets, never a crash).
#include "byte_access.h"
#include "openflight/flt_reader.h"
#include "openflight/flt_writer.h"
#include "model_fixtures.h"

#include <gtest/gtest.h>

#include <osg/Geode>
#include <osg/Geometry>
#include <osgDB/WriteFile>

#include <filesystem>
#include <random>

using namespace cadlod::flt;
using namespace cadlod::test;

namespace {

Bytes writeBytes(const LodModel& model, const WriteOptions& o = {})
{
    Bytes b;
    std::string error;
    EXPECT_TRUE(writeOpenFlight(model, o, b, error)) << error;
    return b;
}

bool readBytes(const Bytes& b, LodModel& model, std::string& error, ReadStats* stats = nullptr)
{
    return readOpenFlight(b.data(), b.size(), model, error, stats);
}

void expectSameModel(const LodModel& a, const LodModel& b)
{
    EXPECT_EQ(a.units, b.units);
    ASSERT_EQ(a.levels.size(), b.levels.size());
    for (std::size_t l = 0; l < a.levels.size(); ++l) {
        const Level& x = a.levels[l];
        const Level& y = b.levels[l];
        EXPECT_DOUBLE_EQ(x.switchIn, y.switchIn);
        EXPECT_DOUBLE_EQ(x.switchOut, y.switchOut);
        EXPECT_EQ(x.center, y.center);
        ASSERT_EQ(x.parts.size(), y.parts.size());
        for (std::size_t p = 0; p < x.parts.size(); ++p) {
            EXPECT_EQ(x.parts[p].name, y.parts[p].name);
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(x.parts[p].color[c], y.parts[p].color[c], 1.0 / 255);
            auto tx = flatTriangles(x.parts[p]);
            auto ty = flatTriangles(y.parts[p]);
            std::sort(tx.begin(), tx.end());  // strips may reorder triangles
            std::sort(ty.begin(), ty.end());
            ASSERT_EQ(tx.size(), ty.size());
            EXPECT_EQ(compareTriangles(tx, ty).position, 0.0f);  // doubles survive exactly
            EXPECT_EQ(compareTriangles(tx, ty).normal, 0.0f);
            EXPECT_EQ(x.parts[p].positions.size(), y.parts[p].positions.size()) << "vertices stay shared";
        }
    }
}

class RoundTrip : public ::testing::TestWithParam<GeometryRecords> {};

}  // namespace

TEST_P(RoundTrip, LodModelSurvivesWriteAndRead)
{
    LodModel model = threeLevelModel();
    model.units = Units::Feet;
    model.levels[1].parts[0].color[3] = 0.5f;
    WriteOptions o;
    o.geometry = GetParam();
    LodModel back;
    std::string error;
    ReadStats stats;
    ASSERT_TRUE(readBytes(writeBytes(model, o), back, error, &stats)) << error;
    EXPECT_EQ(stats.formatRevision, 1610);
    EXPECT_EQ(stats.skippedFaces, 0u);
    EXPECT_EQ(back.levels[0].name, "lod_level_0");
    expectSameModel(model, back);
    EXPECT_EQ(finestLevel(back), 0u);
}

TEST_P(RoundTrip, TextureCoordinatesSurvive)
{
    LodModel model = singleLevelModel(3);
    for (Part& p : model.levels[0].parts)
        for (const Vec3d& v : p.positions)
            p.uvs.push_back({float(v[0] / 4), float(v[1] / 4)});
    WriteOptions o;
    o.geometry = GetParam();
    LodModel back;
    std::string error;
    ASSERT_TRUE(readBytes(writeBytes(model, o), back, error)) << error;
    ASSERT_EQ(back.levels.size(), 1u);
    ASSERT_TRUE(back.levels[0].parts[0].hasUvs());
    const Part& p = back.levels[0].parts[0];
    for (std::size_t i = 0; i < p.positions.size(); ++i)
        EXPECT_FLOAT_EQ(p.uvs[i][0], float(p.positions[i][0] / 4));
}

// Every strict prefix of a file is an error naming an offset; no prefix crashes.
TEST_P(RoundTrip, EveryTruncationIsAnError)
{
    WriteOptions o;
    o.geometry = GetParam();
    const Bytes full = writeBytes(singleLevelModel(2), o);
    for (std::size_t n = 0; n < full.size(); ++n) {
        const Bytes prefix(full.begin(), full.begin() + long(n));
        LodModel m;
        std::string error;
        ASSERT_FALSE(readBytes(prefix, m, error)) << "prefix of " << n << " bytes read as a whole file";
        ASSERT_TRUE(error.find("offset") != std::string::npos || n == 0) << n << ": " << error;
    }
}

// Random byte corruption with a fixed seed: the reader returns (true or false) with a
// consistent model, never crashes or hangs.
TEST_P(RoundTrip, RandomCorruptionNeverCrashes)
{
    WriteOptions o;
    o.geometry = GetParam();
    const Bytes full = writeBytes(threeLevelModel(), o);
    std::mt19937 rng(20261122);
    std::uniform_int_distribution<std::size_t> where(0, full.size() - 1);
    std::uniform_int_distribution<int> byte(0, 255), flips(1, 8);
    int failures = 0;
    for (int run = 0; run < 400; ++run) {
        Bytes b = full;
        for (int k = flips(rng); k > 0; --k)
            b[where(rng)] = std::uint8_t(byte(rng));
        LodModel m;
        std::string error;
        if (!readBytes(b, m, error)) {
            ++failures;
            EXPECT_FALSE(error.empty());
            continue;
        }
        for (const Level& l : m.levels)
            for (const Part& p : l.parts)
                for (const Triangle& t : p.triangles)
                    for (std::uint32_t i : t)
                        ASSERT_LT(i, p.positions.size());
    }
    EXPECT_GT(failures, 0);  // some corruptions hit record headers
}

INSTANTIATE_TEST_SUITE_P(Geometry, RoundTrip, ::testing::Values(GeometryRecords::Meshes, GeometryRecords::Faces),
                         [](const auto& info) { return info.param == GeometryRecords::Meshes ? "Meshes" : "Faces"; });

TEST(Reader, ZeroLengthAndForeignFilesAreErrors)
{
    LodModel m;
    std::string error;
    EXPECT_FALSE(readBytes({}, m, error));
    EXPECT_NE(error.find("empty"), std::string::npos) << error;
    const std::string ply = "ply\nformat binary_little_endian 1.0\n";
    EXPECT_FALSE(readBytes(Bytes(ply.begin(), ply.end()), m, error));
    EXPECT_FALSE(error.empty());
}

TEST(Reader, FacesOutsideThePaletteAreSkippedAndCounted)
{
    WriteOptions o;
    o.geometry = GeometryRecords::Faces;
    Bytes b = writeBytes(singleLevelModel(1), o);
    int broken = 0;
    for (const auto& s : recordSpans(b))
        if (s.opcode == 72 && broken < 2) {
            for (std::size_t k = 0; k < 3; ++k)  // all three corners point nowhere
                b[s.offset + 4 + 4 * k] = 0x70;
            ++broken;
        }
    LodModel m;
    std::string error;
    ReadStats stats;
    ASSERT_TRUE(readBytes(b, m, error, &stats)) << error;
    EXPECT_EQ(stats.skippedFaces, 2u);
    EXPECT_EQ(m.triangleCount(), singleLevelModel(1).triangleCount() - 2);
}

// A file written by OpenSceneGraph's own OpenFlight exporter.
TEST(Reader, ReadsOpenSceneGraphOutput)
{
    const Part sheet = wavySheet(5, 3.0, "sheet", {1, 1, 1, 1});
    osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
    osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
    osg::ref_ptr<osg::Vec3Array> n = new osg::Vec3Array;
    for (const Triangle& t : sheet.triangles)
        for (std::uint32_t i : t) {
            v->push_back(osg::Vec3(float(sheet.positions[i][0]), float(sheet.positions[i][1]),
                                   float(sheet.positions[i][2])));
            n->push_back(osg::Vec3(sheet.normals[i][0], sheet.normals[i][1], sheet.normals[i][2]));
        }
    g->setVertexArray(v.get());
    g->setNormalArray(n.get(), osg::Array::BIND_PER_VERTEX);
    g->addPrimitiveSet(new osg::DrawArrays(GL_TRIANGLES, 0, GLsizei(v->size())));
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    geode->addDrawable(g.get());
    const auto path = (std::filesystem::temp_directory_path() / "cadlod_osg_written.flt").string();
    ASSERT_TRUE(osgDB::writeNodeFile(*geode, path));

    LodModel m;
    std::string error;
    ASSERT_TRUE(readOpenFlightFile(path, m, error)) << error;
    ASSERT_EQ(m.levels.size(), 1u);
    const auto expected = flatTriangles(Level{"", 0, 0, {}, {sheet}});
    Level all = m.levels[0];
    const auto got = flatTriangles(all);
    ASSERT_EQ(got.size(), expected.size());
    const TriangleDiff d = compareTriangles(expected, got);
    EXPECT_LT(d.position, 1e-5f);
    EXPECT_LT(d.normal, 1e-5f);
}

TEST(Reader, FinestLevelIsTheNearestRangeWhateverTheFileOrder)
{
    LodModel model = threeLevelModel();
    std::swap(model.levels[0], model.levels[2]);  // coarsest first in the file
    LodModel back;
    std::string error;
    ASSERT_TRUE(readBytes(writeBytes(model), back, error)) << error;
    ASSERT_EQ(back.levels.size(), 3u);
    EXPECT_EQ(finestLevel(back), 2u);
    EXPECT_EQ(back.levels[2].name, "lod_level_0");
    EXPECT_EQ(back.levels[2].triangleCount(), threeLevelModel().levels[0].triangleCount());
}
