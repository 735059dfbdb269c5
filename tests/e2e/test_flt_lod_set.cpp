// meshlabserver -i part.ply -s lods.mlx -o part.flt: the LOD-set filter makes one layer
// per level and the exporter writes the whole set, which OpenSceneGraph reads as LOD
// nodes with outward-moving ranges, one center and fewer triangles per level.
#include "flt_e2e_meshes.h"
#include "openflight/flt_reader.h"
#include "meshlabserver_runner.h"
#include "osg_probe.h"

#include <gtest/gtest.h>

using namespace cadlod::test;

namespace {

const char* const kLodFilter = "Generate CAD LOD Set";

// The LOD-set filter's parameters for the paper's kind of set: a level list.
std::vector<std::string> listLevels(const std::string& levels)
{
    return {mlxParam("RichEnum", "levelMode", "1"), mlxParam("RichString", "levels", levels)};
}

// The filter list is dumped to a file of the test's own: ctest runs this binary's tests side
// by side, and two meshlabservers writing one file made one of them read it half written.
bool lodFilterAvailable()
{
    const std::string dump = scratchDir("flt_lod_set") + "/filters_" +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".txt";
    const ServerRun run = runMeshlabServer({"-d", dump});
    return run.ok() && readText(dump).find(kLodFilter) != std::string::npos;
}

}  // namespace

TEST(FltLodSet, WholeSetIsWrittenWithItsSwitchDistances)
{
    ASSERT_TRUE(lodFilterAvailable()) << "the staged meshlabserver does not list \"" << kLodFilter
                                      << "\": the filter_cadlod plugin is missing or failed to load";
    const std::string dir = scratchDir("flt_lod_set");
    TestMesh torus;
    makeTorusMesh(torus);
    ASSERT_TRUE(savePly(dir + "/torus.ply", torus, vcg::tri::io::Mask::IOM_VERTNORMAL));
    writeText(dir + "/lods.mlx",
              mlxScript({mlxFilter(kLodFilter, listLevels("50 75"))}));
    const std::string flt = dir + "/torus.flt";
    const ServerRun run = runMeshlabServer({"-i", dir + "/torus.ply", "-s", dir + "/lods.mlx", "-o", flt}, 300);
    ASSERT_TRUE(run.ok()) << run.output;
    EXPECT_NE(run.output.find("3 LOD level(s)"), std::string::npos) << run.output;

    const OsgProbe probe = probeWithOsg(flt);
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.lods.size(), 3u);
    EXPECT_TRUE(probe.outsideLods.empty());
    EXPECT_EQ(probe.lods[0].triangles.size(), std::size_t(torus.fn)) << "level 0 is the original";
    for (std::size_t l = 0; l < 3; ++l) {
        EXPECT_LT(probe.lods[l].minRange, probe.lods[l].maxRange) << "level " << l;
        EXPECT_EQ(probe.lods[l].center, probe.lods[0].center);
        if (l > 0) {
            EXPECT_LT(probe.lods[l].triangles.size(), probe.lods[l - 1].triangles.size());
            EXPECT_GE(probe.lods[l].minRange, probe.lods[l - 1].minRange);
            EXPECT_GE(probe.lods[l].maxRange, probe.lods[l - 1].maxRange);
        }
    }
    EXPECT_NEAR(double(probe.lods[1].triangles.size()), 0.5 * torus.fn, 0.05 * torus.fn);
    EXPECT_NEAR(double(probe.lods[2].triangles.size()), 0.25 * torus.fn, 0.05 * torus.fn);

    cadlod::flt::LodModel model;
    std::string error;
    ASSERT_TRUE(cadlod::flt::readOpenFlightFile(flt, model, error)) << error;
    ASSERT_EQ(model.levels.size(), 3u);
    EXPECT_EQ(cadlod::flt::finestLevel(model), 0u);
}

// The documented pipeline on the sample CAD assembly:
//   meshlabserver -i cad_assembly.wrl.gz -s lods.mlx -o assembly.flt
// every LOD level keeps one named Object per CAD part.
TEST(FltLodSet, CadAssemblyKeepsItsPartsInEveryLevel)
{
    ASSERT_TRUE(lodFilterAvailable()) << "the staged meshlabserver does not list \"" << kLodFilter
                                      << "\": the filter_cadlod plugin is missing or failed to load";
    const std::string dir = scratchDir("flt_lod_set_assembly");
    writeText(dir + "/lods.mlx",
              mlxScript({mlxFilter(kLodFilter, listLevels("50 80"))}));
    const std::string flt = dir + "/assembly.flt";
    const ServerRun run = runMeshlabServer(
        {"-i", std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz", "-s", dir + "/lods.mlx", "-o", flt},
        300);
    ASSERT_TRUE(run.ok()) << run.output;

    const OsgProbe probe = probeWithOsg(flt);
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.lods.size(), 3u);
    const std::vector<std::string> level0(probe.lods[0].names.begin(), probe.lods[0].names.end());
    std::vector<std::string> parts;
    for (const std::string& n : level0)
        if (n != "LOD child0" && std::find(parts.begin(), parts.end(), n) == parts.end())
            parts.push_back(n);
    ASSERT_GE(parts.size(), 3u) << "the sample assembly has several named parts";
    for (std::size_t l = 1; l < probe.lods.size(); ++l) {
        for (const std::string& part : parts)
            EXPECT_NE(std::find(probe.lods[l].names.begin(), probe.lods[l].names.end(), part),
                      probe.lods[l].names.end())
                << part << " missing from level " << l;
        EXPECT_LT(probe.lods[l].triangles.size(), probe.lods[l - 1].triangles.size());
    }
}

namespace {

const char* const kSimplifyFilter = "Simplification: CAD Quadric Edge Collapse (compactness)";

std::string currentLayer(int layer)
{
    return mlxFilter("Change the current layer", {mlxParam("RichMesh", "layer", std::to_string(layer))});
}

}  // namespace

// A second LOD set built from a layer that already is level 0 of a set must leave that
// set whole: it used to overwrite the layer's level record, so the first set lost its
// level 0 and could no longer be exported ("no layer holds level 0").
TEST(FltLodSet, SecondSetFromTheSameLayerLeavesTheFirstSetWhole)
{
    ASSERT_TRUE(lodFilterAvailable());
    const std::string dir = scratchDir("flt_lod_set_twice");
    TestMesh torus;
    makeTorusMesh(torus);
    ASSERT_TRUE(savePly(dir + "/torus.ply", torus, vcg::tri::io::Mask::IOM_VERTNORMAL));
    // Layer 1 is the first set's level 1 whatever the second set adds after it.
    writeText(dir + "/twice.mlx",
              mlxScript({mlxFilter(kLodFilter, listLevels("50")),
                         mlxFilter(kLodFilter, listLevels("75")), currentLayer(1)}));
    const std::string flt = dir + "/first_set.flt";
    const ServerRun run = runMeshlabServer({"-i", dir + "/torus.ply", "-s", dir + "/twice.mlx", "-o", flt}, 300);
    ASSERT_TRUE(run.ok()) << run.output;
    EXPECT_NE(run.output.find("2 LOD level(s)"), std::string::npos) << run.output;

    const OsgProbe probe = probeWithOsg(flt);
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.lods.size(), 2u);
    EXPECT_EQ(probe.lods[0].triangles.size(), std::size_t(torus.fn)) << "level 0 is the original";
    EXPECT_NEAR(double(probe.lods[1].triangles.size()), 0.5 * torus.fn, 0.05 * torus.fn) << "the first set's 50 %";
}

// A level simplified again is no longer what its LOD record says (faces, error, ranges):
// it must leave its set, so saving it writes that layer alone, not the stale set.
TEST(FltLodSet, ALevelSimplifiedAgainLeavesItsSet)
{
    ASSERT_TRUE(lodFilterAvailable());
    const std::string dir = scratchDir("flt_lod_set_resimplified");
    TestMesh torus;
    makeTorusMesh(torus);
    ASSERT_TRUE(savePly(dir + "/torus.ply", torus, vcg::tri::io::Mask::IOM_VERTNORMAL));
    const int target = torus.fn / 4;
    writeText(dir + "/again.mlx",
              mlxScript({mlxFilter(kLodFilter, listLevels("50")), currentLayer(1),
                         mlxFilter(kSimplifyFilter, {mlxParam("RichInt", "targetFaces", std::to_string(target)), mlxParam("RichFloat", "reductionPerc", "0")})}));
    const std::string flt = dir + "/level.flt";
    const ServerRun run = runMeshlabServer({"-i", dir + "/torus.ply", "-s", dir + "/again.mlx", "-o", flt}, 300);
    ASSERT_TRUE(run.ok()) << run.output;
    EXPECT_NE(run.output.find("1 LOD level(s)"), std::string::npos) << run.output;

    cadlod::flt::LodModel model;
    std::string error;
    ASSERT_TRUE(cadlod::flt::readOpenFlightFile(flt, model, error)) << error;
    ASSERT_EQ(model.levels.size(), 1u);
    EXPECT_NEAR(double(model.triangleCount()), target, 0.02 * torus.fn);
}
