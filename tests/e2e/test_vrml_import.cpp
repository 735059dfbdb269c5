// `meshlabserver -i x.wrl -o x.ply` through the stage reaches cadlod's VRML importer:
// a VRML 1.0 file (MeshLab's io_x3d cannot read VRML 1.0) and a gzip file named .wrl
// come out with the triangles the test computed; bad input fails or warns, never hangs.
#include "meshlabserver_runner.h"
#include "test_mesh.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <regex>

using namespace cadlod::test;

namespace {

// Two separated quads (4 triangles) with per-face materials, then a unit cube (12).
const char* kVrml1 = R"(#VRML V1.0 ascii
DEF Bracket Separator {
  Material { diffuseColor [ 1 0 0, 0 0 1 ] }
  MaterialBinding { value PER_FACE }
  Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, 0 0 1, 1 0 1, 1 1 1, 0 1 1 ] }
  IndexedFaceSet { coordIndex [ 0, 1, 2, 3, -1, 4, 5, 6, 7, -1 ] }
}
DEF Block Separator {
  Translation { translation 10 0 0 }
  Cube { width 1 height 1 depth 1 }
}
)";

// A grid of n x n quads in VRML97, one Shape sharing a DEF'd Coordinate via USE.
std::string gridVrml97(int n)
{
    std::string s = "#VRML V2.0 utf8\nDEF Grid Transform { translation 0 0 2 children [\n"
                    "Shape { geometry IndexedFaceSet { coord DEF P Coordinate { point [\n";
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) s += std::to_string(i) + " " + std::to_string(j) + " 0,\n";
    s += "] } coordIndex [\n";
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i;
            s += std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + n + 2) + " " +
                 std::to_string(a + n + 1) + " -1\n";
        }
    s += "] } }\n] }\n";
    return s;
}

void writeGzip(const std::string& path, const std::string& text)
{
    gzFile f = gzopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    ASSERT_EQ(gzwrite(f, text.data(), unsigned(text.size())), int(text.size()));
    gzclose(f);
}

ServerRun convert(const std::string& in, const std::string& out)
{
    return runMeshlabServer({"-i", in, "-o", out, "-m", "vc", "fc"}, 120);
}

}  // namespace

TEST(VrmlImportE2E, Vrml1FileIsReadByCadlod)
{
    const std::string dir = scratchDir("vrml_e2e_v1");
    writeText(dir + "/bracket.wrl", kVrml1);
    const ServerRun run = convert(dir + "/bracket.wrl", dir + "/bracket.ply");
    ASSERT_TRUE(run.ok()) << run.output;
    EXPECT_NE(run.output.find("VRML 1 import of"), std::string::npos) << run.output;

    TestMesh m;
    int mask = 0;
    std::string error;
    ASSERT_TRUE(loadPly(dir + "/bracket.ply", m, mask, error)) << error;
    EXPECT_EQ(m.fn, 4 + 12);
    EXPECT_EQ(m.vn, 8 + 8);  // cube corners merged across its faces
    int red = 0, blue = 0;
    for (const auto& f : m.face) {
        if (f.cC() == vcg::Color4b(255, 0, 0, 255)) ++red;
        if (f.cC() == vcg::Color4b(0, 0, 255, 255)) ++blue;
    }
    EXPECT_EQ(red, 2);
    EXPECT_EQ(blue, 2);
    float maxX = -1;
    for (const auto& v : m.vert) maxX = std::max(maxX, v.cP()[0]);
    EXPECT_FLOAT_EQ(maxX, 10.5f);  // the Translation applied
}

TEST(VrmlImportE2E, GzipFileNamedWrlIsInflated)
{
    const std::string dir = scratchDir("vrml_e2e_gzip");
    const int n = 20;
    writeGzip(dir + "/grid.wrl", gridVrml97(n));
    const ServerRun run = convert(dir + "/grid.wrl", dir + "/grid.ply");
    ASSERT_TRUE(run.ok()) << run.output;
    TestMesh m;
    ASSERT_TRUE(loadPly(dir + "/grid.ply", m));
    EXPECT_EQ(m.fn, 2 * n * n);
    EXPECT_EQ(m.vn, (n + 1) * (n + 1));
    for (const auto& v : m.vert) EXPECT_FLOAT_EQ(v.cP()[2], 2.0f);
}

TEST(VrmlImportE2E, BadFaceIsSkippedAndReportedWithLocation)
{
    const std::string dir = scratchDir("vrml_e2e_bad_face");
    writeText(dir + "/bad.wrl",
              "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet {\n"
              "  coord Coordinate { point [ 0 0 0, 1 0 0, 1 1 0 ] }\n"
              "  coordIndex [ 0 1 2 -1, 0 1 7 -1, 2 1 0 -1 ] } }\n");
    const ServerRun run = convert(dir + "/bad.wrl", dir + "/bad.ply");
    ASSERT_TRUE(run.ok()) << run.output;
    TestMesh m;
    ASSERT_TRUE(loadPly(dir + "/bad.ply", m));
    EXPECT_EQ(m.fn, 2);
    EXPECT_TRUE(std::regex_search(run.output, std::regex("bad\\.wrl:2:18: bad index: face 1 skipped: coordIndex\\[6\\] = 7 out of range"))) << run.output;
}

TEST(VrmlImportE2E, NonVrmlFileFailsWithAClearMessage)
{
    const std::string dir = scratchDir("vrml_e2e_not_vrml");
    writeText(dir + "/notes.wrl", "solid cube\nfacet normal 0 0 1\n");
    const ServerRun run = convert(dir + "/notes.wrl", dir + "/notes.ply");
    EXPECT_FALSE(run.timedOut);
    EXPECT_FALSE(run.ok());
    EXPECT_NE(run.output.find("not a VRML file"), std::string::npos) << run.output;
}

// A MeshLab layer is one mesh: a file that places shared parts is expanded into it, and the
// log says so (and where the instances are kept) instead of losing them silently.
TEST(VrmlImportE2E, SharedPartsAreExpandedAndTheLogSaysSo)
{
    const std::string dir = scratchDir("vrml_e2e_shared");
    writeText(dir + "/shared.wrl", "#VRML V2.0 utf8\nDEF BOLT Transform { children Shape { geometry Box {} } }\n"
                                   "Transform { translation 5 0 0 children USE BOLT }\n"
                                   "Transform { translation 10 0 0 children USE BOLT }\n");
    const ServerRun run = convert(dir + "/shared.wrl", dir + "/shared.ply");
    ASSERT_TRUE(run.ok()) << run.output;
    EXPECT_NE(run.output.find("places shared parts (USE, Inline) 2 more times"), std::string::npos) << run.output;
    TestMesh m;
    int mask = 0;
    std::string error;
    ASSERT_TRUE(loadPly(dir + "/shared.ply", m, mask, error)) << error;
    EXPECT_EQ(m.fn, 3 * 12);
}
