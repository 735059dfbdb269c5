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
