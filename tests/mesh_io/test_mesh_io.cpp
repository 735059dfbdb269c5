// The MeshLab-free conversions (lib/convert/) on cadlod::CoreMesh: what the
// plugin does on a CMeshO, a command-line tool does on this mesh.
#include "mesh/core_mesh.h"
#include "mesh/layer_metadata.h"
#include "convert/lod_model_to_mesh.h"
#include "convert/mesh_to_lod_model.h"
#include "convert/scene_to_mesh.h"

#include <gtest/gtest.h>

#include <vcg/complex/algorithms/update/normal.h>

#include <cmath>
#include <map>

using namespace cadlod;

namespace {

// Two parts that share the edge (1,0,0)-(0,1,0) without sharing vertices, as a CAD
// exporter writes one face set per body.
vrml::Scene twoPartScene()
{
    vrml::Scene scene;
    vrml::Part a;
    a.name = "BASE";
    a.color = {1, 0, 0, 1};
    a.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    a.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    a.triangles = {0, 1, 2};
    vrml::Part b;
    b.name = "LID";
    b.color = {0, 0, 1, 1};
    b.positions = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    b.triangles = {0, 1, 2};
    scene.parts = {a, b};
    return scene;
}

void makeLevelMesh(CoreMesh& m, float z)
{
    auto v = vcg::tri::Allocator<CoreMesh>::AddVertices(m, 4);
    v[0].P() = {0, 0, z};
    v[1].P() = {1, 0, z};
    v[2].P() = {1, 1, z};
    v[3].P() = {0, 1, z};
    vcg::tri::Allocator<CoreMesh>::AddFace(m, &m.vert[0], &m.vert[1], &m.vert[2]);
    vcg::tri::Allocator<CoreMesh>::AddFace(m, &m.vert[0], &m.vert[2], &m.vert[3]);
}

}  // namespace

TEST(MeshIo, SceneBecomesAWeldedMeshWithItsPartTable)
{
    vrml::Scene scene = twoPartScene();
    CoreMesh m;
    const int merged = mesh_io::sceneToMesh(scene, m, {});
    EXPECT_EQ(merged, 2);  // the two shared corners
    EXPECT_EQ(m.vn, 4);
    EXPECT_EQ(m.fn, 2);
    ASSERT_TRUE(hasParts(m));
    const PartTable& table = partTableHandle(m)();
    ASSERT_EQ(table.size(), 2u);
    EXPECT_EQ(table[0].name, "BASE");
    EXPECT_EQ(table[1].name, "LID");
    EXPECT_EQ(table[1].color, (Rgba{0, 0, 1, 1}));
    auto part = facePartHandle(m);
    EXPECT_EQ(part[0], 0);
    EXPECT_EQ(part[1], 1);
    EXPECT_EQ(m.face[0].cC(), vcg::Color4b(255, 0, 0, 255));
    EXPECT_EQ(m.face[1].cC(), vcg::Color4b(0, 0, 255, 255));
    EXPECT_TRUE(scene.parts[0].positions.empty()) << "the scene's arrays are freed once copied";

    vrml::Scene unwelded = twoPartScene();
    CoreMesh soup;
    mesh_io::SceneToMeshOptions keep;
    keep.mergeVertices = false;
    EXPECT_EQ(mesh_io::sceneToMesh(unwelded, soup, keep), 0);
    EXPECT_EQ(soup.vn, 6);
}

TEST(MeshIo, MeshBecomesALevelWithOneObjectPerPartAndUsableNormals)
{
    vrml::Scene scene = twoPartScene();
    CoreMesh m;
    mesh_io::sceneToMesh(scene, m, {});
    mesh_io::LevelStats stats;
    mesh_io::LevelOptions options;
    options.label = "layer";
    const flt::Level level = mesh_io::meshToLevel(m, options, stats);
    ASSERT_EQ(level.parts.size(), 2u);
    EXPECT_EQ(level.parts[0].name, "BASE");
    EXPECT_EQ(level.parts[1].name, "LID");
    EXPECT_EQ(level.parts[1].color, (Rgba{0, 0, 1, 1}));
    for (const flt::Part& p : level.parts) {
        ASSERT_TRUE(p.hasNormals());
        ASSERT_EQ(p.triangles.size(), 1u);
        for (const flt::Vec3f& n : p.normals)  // LID had no normals: the face normal stands in
            EXPECT_NEAR(n[2], 1.0f, 1e-6f);
    }
    EXPECT_EQ(stats.skippedFaces, 0u);
}

// A strip of four triangles whose faces belong to two parts in turn, over shared vertices, as
// a simplified assembly leaves its parts' faces interleaved: each part is written whole, with
// its own copy of each vertex it uses, in the order its faces first use them.
TEST(MeshIo, PartsWhoseFacesInterleaveAreEachWrittenWithTheirOwnVertices)
{
    CoreMesh m;
    auto v = vcg::tri::Allocator<CoreMesh>::AddVertices(m, 6);
    for (int i = 0; i < 6; ++i) {
        v[i].P() = {float(i / 2), float(i % 2), 0};
        v[i].N() = {0, 0, 1};
    }
    for (int i = 0; i < 4; ++i)  // faces 0 and 2 are the first part's, 1 and 3 the second's, all facing -z
        vcg::tri::Allocator<CoreMesh>::AddFace(m, &m.vert[i + i % 2], &m.vert[i + 1 - i % 2], &m.vert[i + 2]);
    auto part = facePartHandle(m);
    for (int i = 0; i < 4; ++i)
        part[i] = i % 2;
    partTableHandle(m)() = {PartIdentity{"EVEN"}, PartIdentity{"ODD"}};
    mesh_io::LevelStats stats;
    const flt::Level level = mesh_io::meshToLevel(m, {}, stats);
    ASSERT_EQ(level.parts.size(), 2u);
    const std::vector<std::vector<int>> used{{0, 1, 2, 3, 4}, {2, 1, 3, 4, 5}};  // first use, in order
    const std::vector<std::vector<flt::Triangle>> triangles{{{0, 1, 2}, {2, 3, 4}}, {{0, 1, 2}, {3, 2, 4}}};
    for (std::size_t p = 0; p < 2; ++p) {
        const flt::Part& written = level.parts[p];
        EXPECT_EQ(written.name, p == 0 ? "EVEN" : "ODD");
        ASSERT_EQ(written.positions.size(), used[p].size());
        for (std::size_t k = 0; k < used[p].size(); ++k) {
            const auto& want = m.vert[used[p][k]].cP();
            EXPECT_EQ(written.positions[k], (flt::Vec3d{want[0], want[1], want[2]})) << "part " << p << " vertex " << k;
        }
        EXPECT_EQ(written.triangles, triangles[p]) << "part " << p;
    }
}

// A welded box (8 vertices, as the importer and the simplifier leave it) is written with one
// vertex per corner of each side, lit by that side's normal: its edges stay sharp. Each
// vertex's averaged normal would draw the box as a soft blob.
TEST(MeshIo, AWeldedBoxIsWrittenWithSharpEdges)
{
    vrml::Scene scene;
    vrml::Part box;
    box.name = "BOX";
    box.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    box.triangles = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                     1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};
    scene.parts = {box};
    CoreMesh m;
    mesh_io::sceneToMesh(scene, m, {});
    ASSERT_EQ(m.vn, 8);
    vcg::tri::UpdateNormal<CoreMesh>::PerVertexNormalized(m);  // what a filter leaves: averaged corners
    mesh_io::LevelStats stats;
    const flt::Level level = mesh_io::meshToLevel(m, {"layer"}, stats);
    ASSERT_EQ(level.parts.size(), 1u);
    const flt::Part& p = level.parts[0];
    ASSERT_EQ(p.triangles.size(), 12u);
    EXPECT_EQ(p.positions.size(), 24u);  // four corners per side
    for (const flt::Triangle& t : p.triangles) {
        const auto at = [&](int k) {
            const auto& q = p.positions[t[k]];
            return vcg::Point3d(q[0], q[1], q[2]);
        };
        vcg::Point3d face = (at(1) - at(0)) ^ (at(2) - at(0));
        face.Normalize();
        for (int k = 0; k < 3; ++k) {
            const flt::Vec3f& n = p.normals[t[k]];
            EXPECT_NEAR(n[0] * face[0] + n[1] * face[1] + n[2] * face[2], 1.0, 1e-6) << "corner " << k;
        }
    }
}

// Faces meeting at less than the crease angle (an octagonal prism's sides, 45° apart, are
// creases; a 24-sided one's, 15° apart, are not) share their vertices and normals.
TEST(MeshIo, AShallowFoldSharesItsVertices)
{
    for (const int sides : {8, 24}) {
        vrml::Scene scene;
        vrml::Part prism;
        prism.name = "PRISM";
        for (int i = 0; i < sides; ++i) {
            const double a = 2 * M_PI * i / sides;
            prism.positions.push_back({float(std::cos(a)), float(std::sin(a)), 0.0f});
            prism.positions.push_back({float(std::cos(a)), float(std::sin(a)), 3.0f});
        }
        for (int i = 0; i < sides; ++i) {  // the mantle only: an open tube
            const std::uint32_t a = 2 * i, b = 2 * i + 1, c = 2 * ((i + 1) % sides), d = c + 1;
            prism.triangles.insert(prism.triangles.end(), {a, c, d, a, d, b});
        }
        scene.parts = {prism};
        CoreMesh m;
        mesh_io::sceneToMesh(scene, m, {});
        mesh_io::LevelStats stats;
        const flt::Level level = mesh_io::meshToLevel(m, {"layer"}, stats);
        EXPECT_EQ(level.parts[0].positions.size(), std::size_t(sides == 8 ? 4 * sides : 2 * sides)) << sides;
    }
}

TEST(MeshIo, LevelBecomesAMeshAndBack)
{
    vrml::Scene scene = twoPartScene();
    CoreMesh m;
    mesh_io::sceneToMesh(scene, m, {});
    mesh_io::LevelStats stats;
    const flt::Level level = mesh_io::meshToLevel(m, {"layer"}, stats);
    CoreMesh back;
    mesh_io::levelToMesh(level, back);
    EXPECT_EQ(back.fn, 2);
    EXPECT_EQ(back.vn, 6);  // one vertex pool per Object
    const PartTable& table = partTableHandle(back)();
    ASSERT_EQ(table.size(), 2u);
    EXPECT_EQ(table[0].name, "BASE");
    EXPECT_EQ(table[1].name, "LID");
    EXPECT_EQ(back.face[1].cC(), vcg::Color4b(0, 0, 255, 255));
    EXPECT_FLOAT_EQ(back.bbox.max[0], 1.0f);
}

TEST(MeshIo, TheMeshesOfOneLodSetBecomeOneModel)
{
    CoreMesh level0, level1, other;
    makeLevelMesh(level0, 0);
    makeLevelMesh(level1, 1);
    makeLevelMesh(other, 2);
    LodLevel r0;
    r0.setId = 3;
    r0.switchIn = 10;
    LodLevel r1 = r0;
    r1.level = 1;
    r1.switchOut = 10;
    r1.switchIn = 100;
    LodLevel r2;
    r2.setId = 4;
    r2.switchIn = 5;
    lodLevelHandle(level1)() = r1;  // out of order on purpose
    lodLevelHandle(level0)() = r0;
    lodLevelHandle(other)() = r2;
    std::vector<mesh_io::LodLayer<CoreMesh>> layers{{&level1, {"one"}}, {&other, {"other"}}, {&level0, {"zero"}}};
    flt::LodModel model;
    mesh_io::LevelStats stats;
    std::string error;
    ASSERT_TRUE(mesh_io::lodSetToModel(layers, 3, model, stats, error)) << error;
    ASSERT_EQ(model.levels.size(), 2u);
    EXPECT_EQ(model.levels[0].parts.at(0).name, "zero");
    EXPECT_EQ(model.levels[1].parts.at(0).name, "one");
    EXPECT_EQ(model.levels[1].switchIn, 100);

    std::vector<mesh_io::LodLayer<CoreMesh>> noLevel0{{&level1, {"one"}}};
    EXPECT_FALSE(mesh_io::lodSetToModel(noLevel0, 3, model, stats, error));
    EXPECT_EQ(error, "LOD set 3: no layer holds level 0 (the original)");
}

namespace {

// Boundary half-edges: directed edges whose opposite no face has.
int boundaryEdges(const CoreMesh& m)
{
    std::map<std::pair<const CoreVertex*, const CoreVertex*>, int> directed;
    for (const auto& f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k)
                ++directed[{f.cV(k), f.cV((k + 1) % 3)}];
    int open = 0;
    for (const auto& [edge, count] : directed)
        if (edge.first != edge.second && !directed.count({edge.second, edge.first}))
            open += count;
    return open;
}

}  // namespace

// A closed tetrahedron exported with one corner split in two (0 and 4) and two slivers
// between them, as a CAD mesher writes it; coordinates rounded by the exporter put both
// corners on one point. Welding makes the slivers repeat a vertex: the importer removes
// them (issue 16, item 5), counts them, and the mesh stays closed.
TEST(MeshIo, FacesRepeatingAVertexAfterWeldingAreRemovedAndCounted)
{
    vrml::Scene scene;
    vrml::Part body;
    body.name = "BODY";
    body.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 0}};
    body.triangles = {0, 2, 1, 4, 1, 3, 4, 3, 2, 1, 2, 3, /* slivers */ 0, 1, 4, 0, 4, 2};
    scene.parts = {body};
    CoreMesh m;
    mesh_io::SceneToMeshStats stats;
    mesh_io::sceneToMesh(scene, m, {}, nullptr, &stats);
    EXPECT_EQ(stats.facesRepeatingVertex, 2);
    EXPECT_EQ(stats.mergedVertices, 1);
    EXPECT_EQ(m.fn, 4);
    EXPECT_EQ(int(m.face.size()), 4) << "compacted";
    for (const auto& f : m.face)
        EXPECT_TRUE(f.cV(0) != f.cV(1) && f.cV(1) != f.cV(2) && f.cV(2) != f.cV(0));
    EXPECT_EQ(boundaryEdges(m), 0) << "still closed";
    auto part = facePartHandle(m);
    for (std::size_t i = 0; i < m.face.size(); ++i)
        EXPECT_EQ(part[i], 0) << "part ids follow the compaction";

    // Without welding nothing repeats a vertex and nothing is removed.
    vrml::Scene again;
    again.parts = {body};
    CoreMesh soup;
    mesh_io::SceneToMeshOptions keep;
    keep.mergeVertices = false;
    mesh_io::sceneToMesh(again, soup, keep, nullptr, &stats);
    EXPECT_EQ(stats.facesRepeatingVertex, 0);
    EXPECT_EQ(soup.fn, 6);
}
