// The staged meshlabserver loads cadlod's plugins next to the system ones.
#include "meshlabserver_runner.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace fs = std::filesystem;
using namespace cadlod::test;

TEST(Stage, PluginDirectoryHoldsSystemAndCadlodPlugins)
{
    const fs::path plugins =
        fs::path(CADLOD_STAGE_MESHLABSERVER).parent_path().parent_path() / "lib/x86_64-linux-gnu/meshlab/plugins";
    EXPECT_TRUE(fs::exists(plugins / "libfilter_cadlod.so"));
    EXPECT_TRUE(fs::exists(plugins / "libio_vrml_flt.so"));
    ASSERT_TRUE(fs::is_symlink(plugins / "libfilter_meshing.so"));
    EXPECT_EQ(fs::read_symlink(plugins / "libfilter_meshing.so").parent_path(),
              fs::path(CADLOD_SYSTEM_PLUGIN_DIR));
    // The system's own plugin directory is not where ours come from.
    EXPECT_NE(fs::read_symlink(plugins / "libfilter_cadlod.so").parent_path(),
              fs::path(CADLOD_SYSTEM_PLUGIN_DIR));
}

TEST(Stage, FilterDumpListsCadlodFilters)
{
    const std::string dump = scratchDir("stage") + "/filters.txt";
    const ServerRun run = runMeshlabServer({"-d", dump});
    ASSERT_TRUE(run.ok()) << run.output;
    const std::string text = readText(dump);
    EXPECT_NE(text.find("Compute Triangle Compactness"), std::string::npos) << text.substr(0, 2000);
    // MeshLab's own filters load beside ours.
    EXPECT_NE(text.find("Quadric Edge Collapse Decimation"), std::string::npos);
}

TEST(MlxComplete, FillsEveryParameterInTheFiltersOrder)
{
    const std::string dir = scratchDir("mlx_complete");
    writeText(dir + "/partial.mlx",
              mlxScript({mlxFilter("Generate CAD LOD Set", {mlxParam("RichString", "levels", "50 90")})}));
    const ServerRun run = completeMlx(dir + "/partial.mlx", dir + "/full.mlx");
    ASSERT_TRUE(run.ok()) << run.output;
    const std::string full = readText(dir + "/full.mlx");
    const std::size_t levels = full.find("name=\"levels\"");
    const std::size_t unit = full.find("name=\"levelUnit\"");
    const std::size_t feature = full.find("name=\"featureAngle\"");
    ASSERT_NE(levels, std::string::npos) << full;
    ASSERT_NE(unit, std::string::npos) << full;
    ASSERT_NE(feature, std::string::npos) << full;
    EXPECT_LT(levels, unit);
    EXPECT_LT(unit, feature);
    EXPECT_NE(full.find("value=\"50 90\""), std::string::npos) << full;
}

TEST(MlxComplete, UnknownFilterOrParameterIsAClearError)
{
    const std::string dir = scratchDir("mlx_complete");
    writeText(dir + "/typo.mlx",
              mlxScript({mlxFilter("Generate CAD LOD Set", {mlxParam("RichString", "levles", "50")})}));
    ServerRun run = completeMlx(dir + "/typo.mlx", dir + "/typo.full.mlx");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.output.find("has no parameter \"levles\""), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("levels"), std::string::npos) << run.output;

    writeText(dir + "/nofilter.mlx", mlxScript({mlxFilter("No Such Filter")}));
    run = completeMlx(dir + "/nofilter.mlx", dir + "/nofilter.full.mlx");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.output.find("no filter named \"No Such Filter\""), std::string::npos) << run.output;
}
