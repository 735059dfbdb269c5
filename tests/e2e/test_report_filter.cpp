// "Simplification Report" through meshlabserver: its Hausdorff distance agrees with
// MeshLab's own "Hausdorff Distance" filter run both ways on the same pair, and it stores
// distance and compactness as vertex and face quality.
#include "meshlabserver_runner.h"
#include "test_mesh.h"

#include <gtest/gtest.h>

#include <vcg/complex/algorithms/create/platonic.h>

#include <map>
#include <regex>

using namespace cadlod::test;

namespace {

struct MeshLabDistance {
    double max = 0, mean = 0;
};

// "Sampled N pts (rng: 0) on A searched closest on B" + "min : x   max y   mean : z   RMS : w",
// by sampled layer (meshlabserver repeats its log, so each result shows up more than once).
std::map<std::string, MeshLabDistance> meshlabHausdorffLines(const std::string& log)
{
    std::map<std::string, MeshLabDistance> found;
    const std::regex line("Sampled [0-9]+ pts \\(rng: 0\\) on (\\S+) searched closest on \\S+\\n[^\\n]*"
                          "min : [-0-9.e]+ +max ([-0-9.e]+) +mean : ([-0-9.e]+)");
    for (std::sregex_iterator it(log.begin(), log.end(), line), end; it != end; ++it)
        found[(*it)[1]] = {std::stod((*it)[2]), std::stod((*it)[3])};
    return found;
}

std::string meshlabHausdorff(int sampled, int target)
{
    return mlxFilter("Hausdorff Distance", {mlxParam("RichMesh", "SampledMesh", std::to_string(sampled)),
                                            mlxParam("RichMesh", "TargetMesh", std::to_string(target)),
                                            mlxParam("RichBool", "SampleVert", "true"),
                                            mlxParam("RichBool", "SampleFace", "true"),
                                            mlxParam("RichInt", "SampleNum", "40000"),
                                            mlxParam("RichAbsPerc", "MaxDist", "10")});
}

}  // namespace

TEST(ReportFilter, HausdorffAgreesWithMeshLabsFilterAndQualityIsStored)
{
    const std::string dir = scratchDir("report_filter");
    TestMesh fine, coarse;
    vcg::tri::Sphere(fine, 4);
    vcg::tri::Sphere(coarse, 2);
    ASSERT_TRUE(savePly(dir + "/fine.ply", fine));
    ASSERT_TRUE(savePly(dir + "/coarse.ply", coarse));
    // Layer 0 = fine (the original), layer 1 = coarse (current, loaded last).
    writeText(dir + "/report.mlx",
              mlxScript({mlxFilter("Simplification Report", {mlxParam("RichMesh", "original", "0"),
                                                             mlxParam("RichInt", "samples", "40000")}),
                         meshlabHausdorff(0, 1), meshlabHausdorff(1, 0)}));
    const ServerRun run = runMeshlabServer({"-i", dir + "/fine.ply", "-i", dir + "/coarse.ply", "-s",
                                            dir + "/report.mlx", "-o", dir + "/out.ply", "-m", "vq", "fq"});
    ASSERT_TRUE(run.ok()) << run.output;

    std::smatch m;
    const std::regex ours("Hausdorff \\(symmetric, [0-9]+ samples\\): max ([-0-9.e]+) \\([-0-9.e]+% of diagonal\\), "
                          "mean ([-0-9.e]+)");
    ASSERT_TRUE(std::regex_search(run.output, m, ours)) << run.output;
    const double ourMax = std::stod(m[1]), ourMean = std::stod(m[2]);
    std::map<std::string, MeshLabDistance> theirs = meshlabHausdorffLines(run.output);
    ASSERT_EQ(theirs.size(), 2u) << run.output;
    const double theirMax = std::max(theirs["fine.ply"].max, theirs["coarse.ply"].max);
    const double theirMean = 0.5 * (theirs["fine.ply"].mean + theirs["coarse.ply"].mean);
    EXPECT_GT(theirMax, 0.01);
    EXPECT_NEAR(ourMax, theirMax, 0.05 * theirMax);
    EXPECT_NEAR(ourMean, theirMean, 0.15 * theirMean);
    EXPECT_NE(run.output.find("faces 5120 -> 320 (-93.8%)"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("compactness after, share of the faces per tenth"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("0.9-1.0 |"), std::string::npos) << run.output;

    TestMesh out;
    int mask = 0;
    std::string error;
    ASSERT_TRUE(loadPly(dir + "/out.ply", out, mask, error)) << error;
    ASSERT_EQ(out.fn, 320);
    ASSERT_TRUE(mask & vcg::tri::io::Mask::IOM_VERTQUALITY);
    ASSERT_TRUE(mask & vcg::tri::io::Mask::IOM_FACEQUALITY);
    for (const auto& v : out.vert)
        EXPECT_LT(v.cQ(), 0.01);  // coarse vertices lie on the fine sphere, nearly
    for (const auto& f : out.face)
        EXPECT_GT(f.cQ(), 0.8);   // icosphere triangles are close to equilateral
}

TEST(ReportFilter, SameLayerAsOriginalIsAClearError)
{
    const std::string dir = scratchDir("report_filter_same");
    TestMesh one;
    vcg::tri::Sphere(one, 1);
    ASSERT_TRUE(savePly(dir + "/one.ply", one));
    writeText(dir + "/report.mlx",
              mlxScript({mlxFilter("Simplification Report", {mlxParam("RichMesh", "original", "0")})}));
    const ServerRun run = runMeshlabServer({"-i", dir + "/one.ply", "-s", dir + "/report.mlx"});
    EXPECT_FALSE(run.ok());
    EXPECT_NE(run.output.find("Simplification Report failed: choose as Original a layer other than the current one"),
              std::string::npos)
        << run.output;
}

// A layer that was never simplified, against a mesh it has nothing to do with, is refused
// with the reason; a pair cadlod has no record of is reported with a clear warning
// (issue 16, item 10: it used to compare with layer 0 without a word).
TEST(ReportFilter, UnrelatedLayersAreRefusedAndUnrecordedPairsWarned)
{
    const std::string dir = scratchDir("report_filter_unrelated");
    TestMesh sphere, far, fine;
    vcg::tri::Sphere(sphere, 2);
    vcg::tri::Sphere(far, 2);
    for (auto& v : far.vert)
        v.P() += vcg::Point3f(100, 0, 0);
    vcg::tri::Sphere(fine, 3);
    ASSERT_TRUE(savePly(dir + "/sphere.ply", sphere));
    ASSERT_TRUE(savePly(dir + "/far.ply", far));
    ASSERT_TRUE(savePly(dir + "/fine.ply", fine));
    writeText(dir + "/report.mlx",
              mlxScript({mlxFilter("Simplification Report", {mlxParam("RichMesh", "original", "0")})}));

    const ServerRun refused = runMeshlabServer({"-i", dir + "/sphere.ply", "-i", dir + "/far.ply", "-s",
                                                dir + "/report.mlx"});
    EXPECT_FALSE(refused.ok());
    EXPECT_NE(refused.output.find("\"far.ply\" cannot have been simplified from \"sphere.ply\": their bounding "
                                  "boxes do not overlap"),
              std::string::npos)
        << refused.output;

    const ServerRun warned = runMeshlabServer({"-i", dir + "/fine.ply", "-i", dir + "/sphere.ply", "-s",
                                               dir + "/report.mlx"});
    ASSERT_TRUE(warned.ok()) << warned.output;
    EXPECT_NE(warned.output.find("are not levels of one LOD set; cadlod has no record"), std::string::npos)
        << warned.output;
    EXPECT_EQ(warned.output.find("more faces"), std::string::npos) << warned.output;
}
