// The command line's OBJ reader: every triangle kept (vcglib 2020.09's importer lost those
// using vertex 1 in a later corner), corner forms, polygons, parts, and errors that say where.
#include "cli_errors.h"
#include "cli_runner.h"
#include "mesh/layer_metadata.h"
#include "obj_reader.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

namespace cadlod::test {
namespace {

std::string writeObj(const std::string& test, const std::string& text)
{
    const std::string path = freshDirectory("obj_" + test) + "/" + test + ".obj";
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

// The file's indices (0-based) of face `f`'s corners.
std::array<int, 3> cornersOf(const CoreMesh& m, std::size_t f)
{
    const CoreFace& face = m.face[f];
    return {int(vcg::tri::Index(m, face.cV(0))), int(vcg::tri::Index(m, face.cV(1))),
            int(vcg::tri::Index(m, face.cV(2)))};
}

using Triangles = std::vector<std::array<int, 3>>;

Triangles trianglesOf(const CoreMesh& m)
{
    Triangles all;
    for (std::size_t f = 0; f < m.face.size(); ++f)
        all.push_back(cornersOf(m, f));
    return all;
}

std::string errorReading(const std::string& path)
{
    CoreMesh m;
    try {
        cli::readObjFile(path, m);
    } catch (const cli::InputError& e) {
        return e.what();
    }
    return "no error";
}

// A closed bipyramid: apex 1 on top, apex 2 below, a ring of `ring` vertices between;
// vertex 1 takes the first, second and third corner in turn.
std::string bipyramid(int ring)
{
    std::ostringstream obj;
    obj << "v 0 0 1\nv 0 0 -1\n";
    for (int i = 0; i < ring; ++i)
        obj << "v " << std::cos(6.283185 * i / ring) << " " << std::sin(6.283185 * i / ring) << " 0\n";
    for (int i = 0; i < ring; ++i) {
        const int a = 3 + i, b = 3 + (i + 1) % ring;
        const int turn = i % 3;
        if (turn == 0) obj << "f 1 " << a << " " << b << "\n";
        if (turn == 1) obj << "f " << b << " 1 " << a << "\n";
        if (turn == 2) obj << "f " << a << " " << b << " 1\n";
        obj << "f 2 " << b << " " << a << "\n";
    }
    return obj.str();
}

TEST(ObjReader, KeepsEveryTriangleUsingTheFirstVertex)
{
    CoreMesh m;
    cli::readObjFile(writeObj("bipyramid", bipyramid(128)), m);
    EXPECT_EQ(m.fn, 256);
    EXPECT_EQ(m.vn, 130);
    // Face 254 is "f 3 1 130": vertex 1 in the second corner, the ring's first vertex before it.
    EXPECT_EQ(cornersOf(m, 254), (std::array<int, 3>{2, 0, 129}));
    EXPECT_EQ(m.face[254].cP(0), vcg::Point3f(1, 0, 0));
    EXPECT_EQ(m.face[254].cP(1), vcg::Point3f(0, 0, 1));
}

TEST(ObjReader, VertexOneInTheLastCorner)
{
    CoreMesh m;
    cli::readObjFile(writeObj("last", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 1\n"), m);
    ASSERT_EQ(m.fn, 1);
    EXPECT_EQ(m.face[0].cP(0), vcg::Point3f(1, 0, 0));
    EXPECT_EQ(m.face[0].cP(1), vcg::Point3f(0, 1, 0));
    EXPECT_EQ(m.face[0].cP(2), vcg::Point3f(0, 0, 0));
}

TEST(ObjReader, CornerFormsAndNegativeIndices)
{
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                             "f 1/1/1 2/2/1 3/3/1\n"
                             "f 2//1 4//1 3//1\n"
                             "f 4/2 3/3 1/1\n"
                             "f -1 -3 -4\n";
    CoreMesh m;
    cli::readObjFile(writeObj("corners", text), m);
    EXPECT_EQ(trianglesOf(m), (Triangles{{0, 1, 2}, {1, 3, 2}, {3, 2, 0}, {3, 1, 0}}));
}

TEST(ObjReader, PolygonsAreFannedFromTheirFirstCorner)
{
    const std::string text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 3 1 0\nv 2 2 0\nv 2 1 0\n"
                             "f 1 2 3 4\nf 5 6 \\\n 7 8 9\n";
    CoreMesh m;
    cli::readObjFile(writeObj("polygons", text), m);
    EXPECT_EQ(trianglesOf(m), (Triangles{{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}, {4, 7, 8}}));
}

TEST(ObjReader, ObjectsBecomeParts)
{
    const std::string text = "mtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\ng ignored\n"
                             "o Bolt M6\nusemtl steel\ns 1\nf 1 2 3\no Nut\nf 2 4 3\ng also_ignored\no Bolt M6\nf 1 4 2\n";
    CoreMesh m;
    EXPECT_EQ(cli::readObjFile(writeObj("objects", text), m), 2u);
    ASSERT_TRUE(hasParts(m));
    const PartTable& table = partTableHandle(m)();
    ASSERT_EQ(table.size(), 2u);
    EXPECT_EQ(table[0].name, "Bolt M6");
    EXPECT_EQ(table[1].name, "Nut");
    auto part = facePartHandle(m);
    ASSERT_EQ(m.fn, 3);
    EXPECT_EQ(part[0], 0);
    EXPECT_EQ(part[1], 1);
    EXPECT_EQ(part[2], 0);
}

TEST(ObjReader, GroupsBecomePartsWithoutObjects)
{
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\ng lid\nf 2 4 3\n";
    CoreMesh m;
    EXPECT_EQ(cli::readObjFile(writeObj("groups", text), m), 2u);
    const PartTable& table = partTableHandle(m)();
    ASSERT_EQ(table.size(), 2u);
    EXPECT_EQ(table[0].name, "default");
    EXPECT_EQ(table[1].name, "lid");
    EXPECT_EQ(facePartHandle(m)[1], 1);
}

TEST(ObjReader, OneNameMakesNoPartTable)
{
    CoreMesh m;
    EXPECT_EQ(cli::readObjFile(writeObj("onename", "o only\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), m), 1u);
    EXPECT_FALSE(hasParts(m));
}

TEST(ObjReader, VertexColoursAndDegenerateFacesAreKept)
{
    const std::string text = "v 0 0 0 1 0 0\nv 1 0 0 0 0 255\nv 0 1 0 1.0\nf 1 2 3\nf 1 1 2\n";
    CoreMesh m;
    cli::readObjFile(writeObj("colours", text), m);
    EXPECT_EQ(m.fn, 2);
    EXPECT_EQ(m.vert[0].cC(), vcg::Color4b(255, 0, 0, 255));
    EXPECT_EQ(m.vert[1].cC(), vcg::Color4b(0, 0, 255, 255));
    EXPECT_EQ(m.vert[2].cP(), vcg::Point3f(0, 1, 0));  // w ignored
}

TEST(ObjReader, ErrorsNameTheFileLineAndColumn)
{
    EXPECT_NE(errorReading(writeObj("zero", "v 0 0 0\nv 1 0 0\nv 0 1 0\n# x\nf 2 3 0\n")).find("zero.obj:5:7: vertex index 0"),
              std::string::npos);
    const std::string beyond = errorReading(writeObj("beyond", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"));
    EXPECT_NE(beyond.find("beyond.obj:4:7: vertex index 4 out of range"), std::string::npos) << beyond;
    const std::string relative = errorReading(writeObj("relative", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n"));
    EXPECT_NE(relative.find("relative.obj:4:"), std::string::npos) << relative;
    const std::string garbage = errorReading(writeObj("garbage", "v 0 0 0\n\nv 1 0x1 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_NE(garbage.find("garbage.obj:3:5: malformed number '0x1'"), std::string::npos) << garbage;
    const std::string index = errorReading(writeObj("badindex", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/x 3\n"));
    EXPECT_NE(index.find("badindex.obj:4:"), std::string::npos) << index;
    const std::string tooFew = errorReading(writeObj("toofew", "v 0 0 0\nv 1 0 0\nf 1 2\n"));
    EXPECT_NE(tooFew.find("toofew.obj:3:1: face with 2 vertices"), std::string::npos) << tooFew;
}

TEST(ObjReader, CadlodInfoCountsEveryTriangle)
{
    const CliRun run = runCadlod({"info", writeObj("info", bipyramid(128))});
    EXPECT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_NE(run.stdoutText.find("triangles    256"), std::string::npos) << run.stdoutText;
    EXPECT_NE(run.stdoutText.find("format       OBJ"), std::string::npos) << run.stdoutText;
}

TEST(ObjReader, CadlodInfoReportsABadIndexWithExitCodeOne)
{
    const CliRun run = runCadlod({"info", writeObj("infobad", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 0\n")});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.stderrText.find("infobad.obj:4:7:"), std::string::npos) << run.stderrText;
}

}  // namespace
}  // namespace cadlod::test
