// "meshlabserver -i mesh.ply -o mesh.flt" with cadlod's exporter; every file is read
// back with OpenSceneGraph: triangles, positions, normals, names, culling, units.
#include "flt_e2e_meshes.h"
#include "meshlabserver_runner.h"
#include "osg_probe.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace cadlod::test;

namespace {

std::string torusPly(const std::string& dir, TestMesh& torus)
{
    makeTorusMesh(torus);
    const std::string path = dir + "/torus.ply";
    EXPECT_TRUE(savePly(path, torus, vcg::tri::io::Mask::IOM_VERTNORMAL));
    return path;
}

// An .mlx whose only job is to let meshlabserver apply save parameters is not possible
// in 2020.09 (-o takes no parameters), so options are tested through the core; here the
// defaults: meters, single-sided, one Object per part, Mesh records.
}  // namespace

TEST(FltExport, SingleLayerIsReadByOpenSceneGraph)
{
    const std::string dir = scratchDir("flt_export_single");
    TestMesh torus;
    const std::string ply = torusPly(dir, torus);
    const std::string flt = dir + "/torus.flt";
    std::filesystem::remove(flt);
    const ServerRun run = runMeshlabServer({"-i", ply, "-o", flt});
    ASSERT_TRUE(run.ok()) << run.output;
    ASSERT_TRUE(std::filesystem::exists(flt)) << run.output;

    const OsgProbe probe = probeWithOsg(flt);
    ASSERT_TRUE(probe.loaded);
    EXPECT_TRUE(probe.lods.empty()) << "a single layer is written without LOD nodes";
    const auto expected = meshTriangles(torus);
    const auto got = osgTriangles(probe.outsideLods);
    ASSERT_EQ(got.size(), expected.size());
    const TriangleDiff d = compareTriangles(expected, got);
    EXPECT_LT(d.position, 1e-5f);
    EXPECT_LT(d.normal, 1e-4f);
    EXPECT_TRUE(probe.cullsBackFaces);
    EXPECT_NE(std::find(probe.names.begin(), probe.names.end(), "torus"), probe.names.end())
        << "the Object carries the layer name";
    EXPECT_NE(run.output.find("OpenFlight " + flt), std::string::npos) << run.output;
}

TEST(FltExport, FaceColorsBecomePartColors)
{
    const std::string dir = scratchDir("flt_export_colors");
    TestMesh m;
    makeTorusMesh(m);
    for (std::size_t i = 0; i < m.face.size(); ++i)
        m.face[i].C() = i < m.face.size() / 2 ? vcg::Color4b(255, 0, 0, 255) : vcg::Color4b(0, 0, 255, 255);
    const std::string ply = dir + "/colored.ply";
    ASSERT_TRUE(savePly(ply, m, vcg::tri::io::Mask::IOM_VERTNORMAL | vcg::tri::io::Mask::IOM_FACECOLOR));
    const std::string flt = dir + "/colored.flt";
    const ServerRun run = runMeshlabServer({"-i", ply, "-o", flt, "-m", "fc", "vn"});
    ASSERT_TRUE(run.ok()) << run.output;
    const OsgProbe probe = probeWithOsg(flt);
    ASSERT_TRUE(probe.loaded);
    std::size_t red = 0, blue = 0;
    for (const OsgTriangle& t : probe.outsideLods) {
        red += t.color[0] > 0.99f && t.color[2] < 0.01f;
        blue += t.color[2] > 0.99f && t.color[0] < 0.01f;
    }
    EXPECT_EQ(red, m.face.size() / 2);
    EXPECT_EQ(blue, m.face.size() - m.face.size() / 2);
}

// CAD parts from the VRML importer become one named Object each (long names in Long ID
// records) with their material colors: meshlabserver -i part.wrl -o part.flt.
TEST(FltExport, VrmlPartsBecomeNamedObjects)
{
    const std::string dir = scratchDir("flt_export_parts");
    writeText(dir + "/assembly.wrl", R"(#VRML V2.0 utf8
DEF LEFT_BRACKET_ASSEMBLY Transform { children [
  Shape { appearance Appearance { material Material { diffuseColor 1 0 0 } }
          geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }
                                    coordIndex [ 0 1 2 3 -1 ] } } ] }
DEF Pin Transform { translation 5 0 0 children [
  Shape { appearance Appearance { material Material { diffuseColor 0 0 1 } }
          geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 2 0 0, 2 2 0, 0 2 0, 0 0 2 ] }
                                    coordIndex [ 0 1 2 3 -1, 0 1 4 -1 ] } } ] }
)");
    const std::string flt = dir + "/assembly.flt";
    const ServerRun run = runMeshlabServer({"-i", dir + "/assembly.wrl", "-o", flt});
    ASSERT_TRUE(run.ok()) << run.output;
    // Without "preserveObject" OpenSceneGraph folds Object nodes directly under a Group
    // into their parent, names and all.
    const OsgProbe probe = probeWithOsg(flt, "preserveObject");
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.outsideLods.size(), 5u);
    auto named = [&](const std::string& n) {
        return std::find(probe.names.begin(), probe.names.end(), n) != probe.names.end();
    };
    EXPECT_TRUE(named("LEFT_BRACKET_ASSEMBLY")) << "long part name kept through a Long ID record";
    EXPECT_TRUE(named("Pin"));
    std::size_t red = 0, blue = 0;
    for (const OsgTriangle& t : probe.outsideLods) {
        red += t.color[0] > 0.99f && t.color[2] < 0.01f && t.position[0][0] < 2.0f;
        blue += t.color[2] > 0.99f && t.color[0] < 0.01f && t.position[0][0] >= 5.0f;
    }
    EXPECT_EQ(red, 2u);
    EXPECT_EQ(blue, 3u);
}

// One body with a colour per face (colorPerVertex FALSE), as FreeCAD exports it: the
// .flt keeps every face's colour, not the part's (issue 16: "one grey", "all gold").
TEST(FltExport, VrmlFaceColorsSurviveInOneObject)
{
    const std::string dir = scratchDir("flt_export_face_colors");
    writeText(dir + "/body.wrl", R"(#VRML V2.0 utf8
DEF Body Shape {
  appearance Appearance { material Material { diffuseColor 0.8 0.6 0.2 } }
  geometry IndexedFaceSet {
    coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, 0 0 1, 1 0 1, 1 1 1, 0 1 1 ] }
    coordIndex [ 0 2 1 -1 0 3 2 -1  4 5 6 -1 4 6 7 -1  0 1 5 -1 0 5 4 -1
                 1 2 6 -1 1 6 5 -1  2 3 7 -1 2 7 6 -1  3 0 4 -1 3 4 7 -1 ]
    colorPerVertex FALSE
    color Color { color [ 0.8 0.6 0.2, 0.75 0.75 0.75 ] }
    colorIndex [ 0 0 1 1 0 0 1 1 0 0 1 1 ]
  }
}
)");
    const std::string flt = dir + "/body.flt";
    const ServerRun run = runMeshlabServer({"-i", dir + "/body.wrl", "-o", flt});
    ASSERT_TRUE(run.ok()) << run.output;
    const OsgProbe probe = probeWithOsg(flt);
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.outsideLods.size(), 12u);
    std::size_t gold = 0, silver = 0;
    for (const OsgTriangle& t : probe.outsideLods) {
        gold += std::abs(t.color[0] - 0.8f) < 0.01f && std::abs(t.color[2] - 0.2f) < 0.01f;
        silver += std::abs(t.color[0] - 0.75f) < 0.01f && std::abs(t.color[2] - 0.75f) < 0.01f;
    }
    EXPECT_EQ(gold, 6u);
    EXPECT_EQ(silver, 6u);
}

// A colour per vertex (colorPerVertex TRUE) is written per vertex; a file without one gets
// no vertex colours, so face colours stay what OpenSceneGraph draws.
TEST(FltExport, VrmlVertexColorsSurviveOnlyWhereTheFileHasThem)
{
    const std::string dir = scratchDir("flt_export_vertex_colors");
    writeText(dir + "/square.wrl", R"(#VRML V2.0 utf8
Shape { geometry IndexedFaceSet {
  coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }
  coordIndex [ 0 1 2 -1 0 2 3 -1 ]
  color Color { color [ 1 0 0, 0 1 0, 0 0 1, 1 1 1 ] }
} }
)");
    const std::string flt = dir + "/square.flt";
    const ServerRun run = runMeshlabServer({"-i", dir + "/square.wrl", "-o", flt});
    ASSERT_TRUE(run.ok()) << run.output;
    const OsgProbe probe = probeWithOsg(flt);
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.outsideLods.size(), 2u);
    int red = 0;
    for (const OsgTriangle& t : probe.outsideLods) {
        ASSERT_TRUE(t.hasCornerColors);
        for (int k = 0; k < 3; ++k)
            red += t.position[k][0] == 0 && t.position[k][1] == 0 && t.cornerColor[k][0] > 0.99f &&
                   t.cornerColor[k][1] < 0.01f;
    }
    EXPECT_EQ(red, 2) << "the corner at the origin is red in both triangles";

    writeText(dir + "/plain.wrl", R"(#VRML V2.0 utf8
Shape { appearance Appearance { material Material { diffuseColor 0 0 1 } }
  geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0 ] } coordIndex [ 0 1 2 ] } }
)");
    const ServerRun plain = runMeshlabServer({"-i", dir + "/plain.wrl", "-o", dir + "/plain.flt"});
    ASSERT_TRUE(plain.ok()) << plain.output;
    const OsgProbe p = probeWithOsg(dir + "/plain.flt");
    ASSERT_TRUE(p.loaded);
    ASSERT_EQ(p.outsideLods.size(), 1u);
    EXPECT_FALSE(p.outsideLods[0].hasCornerColors);
    EXPECT_GT(p.outsideLods[0].color[2], 0.99f);
}
