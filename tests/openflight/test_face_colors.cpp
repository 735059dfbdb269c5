// Per-face colours of a CAD export survive the way to OpenFlight (issue 16, item 1):
// a VRML face set with one Color per face (colorPerVertex FALSE), as FreeCAD writes it,
// imported, welded, written as .flt (Mesh and Face records) and read back by
// OpenSceneGraph and by cadlod's own reader: every face keeps its colour.
#include "mesh/core_mesh.h"
#include "openflight/flt_reader.h"
#include "openflight/flt_writer.h"
#include "convert/lod_model_to_mesh.h"
#include "convert/mesh_to_lod_model.h"
#include "osg_probe.h"
#include "convert/scene_to_mesh.h"
#include "vrml/importer.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <map>

using namespace cadlod;

namespace {

// A unit cube, one body, two triangles per side; sides coloured gold, silver, red, gold,
// silver, red (face colours, not vertex colours), the Material gold.
const char* kCubeWithFaceColors = R"(#VRML V2.0 utf8
DEF Body Shape {
  appearance Appearance { material Material { diffuseColor 0.8 0.6 0.2 } }
  geometry IndexedFaceSet {
    coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, 0 0 1, 1 0 1, 1 1 1, 0 1 1 ] }
    coordIndex [ 0 2 1 -1 0 3 2 -1  4 5 6 -1 4 6 7 -1  0 1 5 -1 0 5 4 -1
                 1 2 6 -1 1 6 5 -1  2 3 7 -1 2 7 6 -1  3 0 4 -1 3 4 7 -1 ]
    colorPerVertex FALSE
    color Color { color [ 0.8 0.6 0.2, 0.75 0.75 0.75, 1 0 0 ] }
    colorIndex [ 0 0 1 1 2 2 0 0 1 1 2 2 ]
  }
}
)";

std::string scratch(const std::string& name)
{
    const auto dir = std::filesystem::temp_directory_path() / "cadlod_flt_tests";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

// Colour name by nearest of the three, or "?" when none is within 0.02.
std::string colorName(float r, float g, float b)
{
    auto near = [&](float R, float G, float B) {
        return std::abs(r - R) < 0.02f && std::abs(g - G) < 0.02f && std::abs(b - B) < 0.02f;
    };
    if (near(0.8f, 0.6f, 0.2f)) return "gold";
    if (near(0.75f, 0.75f, 0.75f)) return "silver";
    if (near(1, 0, 0)) return "red";
    return "?";
}

void importCube(CoreMesh& m)
{
    vrml::ImportResult r = vrml::importVrmlText(kCubeWithFaceColors, "cube.wrl");
    ASSERT_TRUE(r.ok()) << r.error;
    mesh_io::sceneToMesh(r.scene, m, {});
    ASSERT_EQ(m.fn, 12);
    ASSERT_EQ(m.vn, 8);
}

class FaceColors : public ::testing::TestWithParam<flt::GeometryRecords> {};

}  // namespace

TEST_P(FaceColors, SurviveExportAndOsgReadback)
{
    CoreMesh m;
    importCube(m);
    std::map<std::string, int> imported;
    for (const auto& f : m.face)
        ++imported[colorName(f.cC()[0] / 255.f, f.cC()[1] / 255.f, f.cC()[2] / 255.f)];
    ASSERT_EQ(imported, (std::map<std::string, int>{{"gold", 4}, {"silver", 4}, {"red", 4}}));

    mesh_io::LevelOptions options;
    options.label = "cube";
    options.faceColors = true;
    mesh_io::LevelStats stats;
    flt::LodModel model;
    model.levels.push_back(mesh_io::meshToLevel(m, options, stats));
    ASSERT_EQ(model.levels[0].parts.size(), 1u) << "one CAD part, one Object";
    flt::WriteOptions o;
    o.geometry = GetParam();
    const std::string path = scratch(std::string(GetParam() == flt::GeometryRecords::Meshes ? "m" : "f") +
                                     "_face_colors.flt");
    std::string error;
    ASSERT_TRUE(flt::writeOpenFlightFile(path, model, o, error)) << error;

    const test::OsgProbe probe = test::probeWithOsg(path);
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.outsideLods.size(), 12u);
    std::map<std::string, int> drawn;
    for (const test::OsgTriangle& t : probe.outsideLods)
        ++drawn[colorName(t.color[0], t.color[1], t.color[2])];
    EXPECT_EQ(drawn, imported);

    // cadlod's own reader gives the colours back too.
    flt::LodModel back;
    ASSERT_TRUE(flt::readOpenFlightFile(path, back, error)) << error;
    ASSERT_EQ(back.levels.size(), 1u);
    CoreMesh again;
    mesh_io::levelToMesh(back.levels[0], again);
    std::map<std::string, int> reread;
    for (const auto& f : again.face)
        ++reread[colorName(f.cC()[0] / 255.f, f.cC()[1] / 255.f, f.cC()[2] / 255.f)];
    EXPECT_EQ(reread, imported);
}

TEST_P(FaceColors, PartColourOnlyWhenAsked)
{
    CoreMesh m;
    importCube(m);
    mesh_io::LevelOptions options;
    options.label = "cube";
    options.faceColors = false;
    mesh_io::LevelStats stats;
    flt::LodModel model;
    model.levels.push_back(mesh_io::meshToLevel(m, options, stats));
    flt::WriteOptions o;
    o.geometry = GetParam();
    const std::string path = scratch("part_colors.flt");
    std::string error;
    ASSERT_TRUE(flt::writeOpenFlightFile(path, model, o, error)) << error;
    const test::OsgProbe probe = test::probeWithOsg(path);
    ASSERT_TRUE(probe.loaded);
    for (const test::OsgTriangle& t : probe.outsideLods)
        EXPECT_EQ(colorName(t.color[0], t.color[1], t.color[2]), "gold");
}

INSTANTIATE_TEST_SUITE_P(Geometry, FaceColors,
                         ::testing::Values(flt::GeometryRecords::Meshes, flt::GeometryRecords::Faces));

namespace {

// A square of two triangles with a colour per vertex (colorPerVertex TRUE): red, green,
// blue, white corners.
const char* kSquareWithVertexColors = R"(#VRML V2.0 utf8
Shape { geometry IndexedFaceSet {
  coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }
  coordIndex [ 0 1 2 -1 0 2 3 -1 ]
  color Color { color [ 1 0 0, 0 1 0, 0 0 1, 1 1 1 ] }
} }
)";

std::string cornerName(const std::array<float, 4>& c)
{
    auto is = [&](float r, float g, float b) {
        return std::abs(c[0] - r) < 0.01f && std::abs(c[1] - g) < 0.01f && std::abs(c[2] - b) < 0.01f;
    };
    return is(1, 0, 0) ? "red" : is(0, 1, 0) ? "green" : is(0, 0, 1) ? "blue" : is(1, 1, 1) ? "white" : "?";
}

}  // namespace

// Per-vertex colours, where the input has them, reach OpenSceneGraph as vertex colours.
TEST_P(FaceColors, VertexColorsSurviveWhereTheInputHasThem)
{
    vrml::ImportResult r = vrml::importVrmlText(kSquareWithVertexColors, "square.wrl");
    ASSERT_TRUE(r.ok()) << r.error;
    CoreMesh m;
    mesh_io::sceneToMesh(r.scene, m, {});
    mesh_io::LevelOptions options;
    options.label = "square";
    options.faceColors = true;
    options.vertexColors = true;
    mesh_io::LevelStats stats;
    flt::LodModel model;
    model.levels.push_back(mesh_io::meshToLevel(m, options, stats));
    flt::WriteOptions o;
    o.geometry = GetParam();
    const std::string path = scratch("vertex_colors.flt");
    std::string error;
    ASSERT_TRUE(flt::writeOpenFlightFile(path, model, o, error)) << error;
    const test::OsgProbe probe = test::probeWithOsg(path);
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.outsideLods.size(), 2u);
    std::map<std::string, std::string> cornerOf;  // "x,y" -> colour name
    for (const test::OsgTriangle& t : probe.outsideLods) {
        ASSERT_TRUE(t.hasCornerColors);
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(t.cornerColor[k][3], 1.0f, 0.01f) << "opaque";
        for (int k = 0; k < 3; ++k)
            cornerOf[std::to_string(int(t.position[k][0])) + "," + std::to_string(int(t.position[k][1]))] =
                cornerName(t.cornerColor[k]);
    }
    EXPECT_EQ(cornerOf, (std::map<std::string, std::string>{
                            {"0,0", "red"}, {"1,0", "green"}, {"1,1", "blue"}, {"0,1", "white"}}));

    flt::LodModel back;
    ASSERT_TRUE(flt::readOpenFlightFile(path, back, error)) << error;
    ASSERT_EQ(back.levels.size(), 1u);
    ASSERT_EQ(back.levels[0].parts.size(), 1u);
    const flt::Part& p = back.levels[0].parts[0];
    ASSERT_TRUE(p.hasVertexColors());
    for (std::size_t i = 0; i < p.positions.size(); ++i)
        if (p.positions[i][0] == 0 && p.positions[i][1] == 0) {
            EXPECT_EQ(cornerName(p.vertexColors[i]), "red");
        }
}
