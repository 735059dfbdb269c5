// meshlabserver -i shaft.ply -s simplify.mlx -o out.ply: the CAD Quadric Edge Collapse
// filter meets its target and logs faces, compactness and the largest collapse error.
#include "cad_meshes.h"
#include "meshlabserver_runner.h"
#include "test_mesh.h"

#include "measure/compactness.h"

#include <gtest/gtest.h>

#include <regex>

using namespace cadlod::test;

namespace {

const char* const kFilter = "Simplification: CAD Quadric Edge Collapse (compactness)";

std::string saveShaft(const std::string& dir, int& faces)
{
    TestMesh shaft;
    CadBuilder b;
    revolve(b, shaftProfile(), shaftSpec(160));
    b.build(shaft);
    faces = shaft.fn;
    const std::string path = dir + "/shaft.ply";
    EXPECT_TRUE(savePly(path, shaft));
    return path;
}

}  // namespace

TEST(SimplifyFilter, MlxScriptMeetsTheTargetFaceCount)
{
    const std::string dir = scratchDir("simplify_filter_target");
    int faces = 0;
    const std::string in = saveShaft(dir, faces);
    const int target = faces / 10;
    writeText(dir + "/simplify.mlx",
              mlxScript({mlxFilter(kFilter, {mlxParam("RichInt", "targetFaces", std::to_string(target)), mlxParam("RichFloat", "reductionPerc", "0")})}));
    const ServerRun run = runMeshlabServer({"-i", in, "-o", dir + "/out.ply", "-s", dir + "/simplify.mlx"});
    ASSERT_TRUE(run.ok()) << run.output;

    TestMesh out;
    int mask = 0;
    std::string error;
    ASSERT_TRUE(loadPly(dir + "/out.ply", out, mask, error)) << error;
    EXPECT_NEAR(out.fn, target, 2);
    EXPECT_GT(cadlod::meshCompactness(out).mean, 0.3);

    std::smatch m;
    ASSERT_TRUE(std::regex_search(run.output, m, std::regex("CAD Quadric Edge Collapse on .*: ([0-9]+) -> ([0-9]+) faces")))
        << run.output;
    EXPECT_EQ(std::stoi(m[1]), faces);
    EXPECT_EQ(std::stoi(m[2]), out.fn);
    EXPECT_TRUE(std::regex_search(run.output, std::regex("Compactness mean [0-9.]+ -> [0-9.]+"))) << run.output;
    EXPECT_TRUE(std::regex_search(run.output, std::regex("Largest collapse error [0-9.e+-]+"))) << run.output;
}

TEST(SimplifyFilter, ReductionAndMaxErrorFromMlx)
{
    const std::string dir = scratchDir("simplify_filter_reduction");
    int faces = 0;
    const std::string in = saveShaft(dir, faces);
    writeText(dir + "/simplify.mlx",
              mlxScript({mlxFilter(kFilter, {mlxParam("RichInt", "targetFaces", "0"),
                                             mlxParam("RichFloat", "reductionPerc", "50"),
                                             mlxParam("RichFloat", "maxError", "0.0001")})}));
    const ServerRun run = runMeshlabServer({"-i", in, "-o", dir + "/out.ply", "-s", dir + "/simplify.mlx"});
    ASSERT_TRUE(run.ok()) << run.output;
    TestMesh out;
    ASSERT_TRUE(loadPly(dir + "/out.ply", out));
    EXPECT_GE(out.fn, faces / 2 - 2);  // never below the reduction target
    EXPECT_LT(out.fn, faces);
    std::smatch m;
    ASSERT_TRUE(std::regex_search(run.output, m, std::regex("\\(([0-9.e+-]+)% of the bbox diagonal"))) << run.output;
    EXPECT_LE(std::stod(m[1]), 0.01 + 1e-9);  // 0.0001 of the diagonal
}
