// The two headless routes build the same chain: `cadlod convert` and the staged
// meshlabserver with docs/examples/cad_to_flt.mlx give OpenFlight files with the same levels
// (triangles and switch ranges) for the demo assembly. (With a unit conversion they differ a
// little: the example script scales with MeshLab's Transform filter after import, in float,
// the command in the importer; README and docs/benchmarks.md say so.) A MeshLab layer is one
// mesh, so the MeshLab route expands the demo's shared parts: the command does too, here.
// With Hierarchy "per part and cluster" the filter reads the layer's VRML file again and
// writes the command's hierarchical LOD itself: the same file.
#include "flt_bytes.h"
#include "meshlabserver_runner.h"
#include "osg_probe.h"

#include "openflight/flt_reader.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

using namespace cadlod;
using namespace cadlod::test;

TEST(HeadlessRoutes, CommandAndMeshlabserverGiveTheSameChain)
{
    const std::string dir = scratchDir("routes");
    const std::string demo = std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz";
    const std::string viaServer = dir + "/server.flt", viaCommand = dir + "/command.flt";
    std::remove(viaServer.c_str());
    std::remove(viaCommand.c_str());
    const ServerRun server = runMeshlabServer(
        {"-i", demo, "-s", std::string(CADLOD_SOURCE_DIR) + "/docs/examples/cad_to_flt.mlx", "-o", viaServer}, 300);
    ASSERT_TRUE(server.ok()) << server.output;
    const std::string command = "env -u DISPLAY " + std::string(CADLOD_CLI) + " convert '" + demo + "' --instances expand -o '" +
                                viaCommand + "' > '" + dir + "/command.log' 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << readText(dir + "/command.log");

    flt::LodModel a, b;
    std::string error;
    ASSERT_TRUE(flt::readOpenFlightFile(viaServer, a, error)) << error;
    ASSERT_TRUE(flt::readOpenFlightFile(viaCommand, b, error)) << error;
    ASSERT_GE(a.levels.size(), 5u);
    ASSERT_EQ(a.levels.size(), b.levels.size());
    for (std::size_t k = 0; k < a.levels.size(); ++k) {
        EXPECT_EQ(a.levels[k].triangleCount(), b.levels[k].triangleCount()) << "level " << k;
        EXPECT_DOUBLE_EQ(a.levels[k].switchOut, b.levels[k].switchOut) << "level " << k;
        EXPECT_DOUBLE_EQ(a.levels[k].switchIn, b.levels[k].switchIn) << "level " << k;
    }
}

namespace {

const char* const kLodFilter = "Generate CAD LOD Set";

// Hierarchy 1: per part and cluster; 2: the same with the fewest draw calls.
std::string perPartAndCluster(const std::string& file, const std::string& hierarchy = "1")
{
    return mlxScript({mlxFilter(kLodFilter, {mlxParam("RichEnum", "hierarchy", hierarchy),
                                             mlxParam("RichSaveFile", "hierarchyFile", file)})});
}

// The filter's file for `input` (Hierarchy `hierarchy`) against `cadlod convert --hlod
// option`'s, in `dir`: the same bytes after the header. Returns the filter's log and file.
struct FilterRun {
    std::string log;
    std::string file;
};

FilterRun expectTheCommandsFileOf(const std::string& input, const std::string& dir, const std::string& hierarchy,
                                  const std::string& option)
{
    const std::string name = std::filesystem::path(input).stem().stem().string();  // cad_assembly.wrl.gz
    std::filesystem::create_directories(dir + "/server");
    std::filesystem::create_directories(dir + "/command");
    const std::string viaServer = dir + "/server/" + name + ".flt", viaCommand = dir + "/command/" + name + ".flt";
    std::remove(viaServer.c_str());
    std::remove(viaCommand.c_str());
    writeText(dir + "/hlod.mlx", perPartAndCluster(viaServer, hierarchy));
    const ServerRun server = runMeshlabServer({"-i", input, "-s", dir + "/hlod.mlx"}, 300);
    EXPECT_TRUE(server.ok()) << server.output;
    const std::string command = "env -u DISPLAY " + std::string(CADLOD_CLI) + " convert '" + input + "' --hlod " +
                                option + " -o '" + viaCommand + "' > '" + dir + "/command.log' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << readText(dir + "/command.log");
    const std::string a = afterHeader(readText(viaServer)), b = afterHeader(readText(viaCommand));
    EXPECT_TRUE(!a.empty() && a == b) << "the filter's file differs from the command's: " << a.size() << " against "
                                      << b.size() << " bytes after the header";
    return {server.output, viaServer};
}

// The same for the bundled demo: its parts' levels and its clusters' proxies.
void expectTheCommandsFile(const std::string& hierarchy, const std::string& option)
{
    const std::string demo = std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz";
    const FilterRun run = expectTheCommandsFileOf(demo, scratchDir("routes_hlod_" + option), hierarchy, option);
    EXPECT_NE(run.log.find("clusters of up to"), std::string::npos) << run.log;
    EXPECT_GT(readText(run.file).size(), 100000u);
    const OsgProbe probe = probeWithOsg(run.file);
    ASSERT_TRUE(probe.loaded);
    EXPECT_GE(probe.lods.size(), 10u);  // the parts' levels and the clusters' proxies
}

}  // namespace

TEST(HeadlessRoutes, PerPartAndClusterWritesTheCommandsHierarchicalLod)
{
    expectTheCommandsFile("1", "auto");
}

TEST(HeadlessRoutes, FewestDrawCallsWritesTheCommandsToo)
{
    expectTheCommandsFile("2", "calls");
}

// Hierarchy 1 chooses as `--hlod auto` does: on a board of 420 chips, more placements than a
// frame's draw calls, the fewest draw calls; Hierarchy 3 keeps the instances, as `--hlod
// instances`.
TEST(HeadlessRoutes, PerPartAndClusterChoosesTheTreeAsTheCommandDoes)
{
    const std::string dir = scratchDir("routes_hlod_budget");
    const std::string input = dir + "/chips.wrl";
    std::string text = "#VRML V2.0 utf8\n";
    for (int n = 0; n < 420; ++n)
        text += "DEF C" + std::to_string(n) + " Transform { translation " + std::to_string(0.01 * (n % 21)) + " " +
                std::to_string(0.01 * (n / 21)) + " 0 children " +
                (n == 0 ? "DEF CHIP Shape { geometry Box { size 0.006 0.004 0.002 } }" : "USE CHIP") + " }\n";
    writeText(input, text);
    const FilterRun chosen = expectTheCommandsFileOf(input, dir + "/auto", "1", "calls");
    EXPECT_NE(chosen.log.find("the fewest draw calls near the viewer"), std::string::npos) << chosen.log;
    const FilterRun instances = expectTheCommandsFileOf(input, dir + "/instances", "3", "instances");
    EXPECT_NE(instances.log.find("every part its own instance near the viewer"), std::string::npos)
        << instances.log;
    EXPECT_FALSE(readText(chosen.file) == readText(instances.file));
}

TEST(HeadlessRoutes, PerPartAndClusterRefusesALayerNotReadFromVrml)
{
    const std::string dir = scratchDir("routes_hlod_ply");
    writeText(dir + "/tetra.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                                  "property float z\nelement face 4\nproperty list uchar int vertex_indices\n"
                                  "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 0 3 2\n");
    const std::string out = dir + "/tetra_hlod.flt";
    std::remove(out.c_str());
    writeText(dir + "/hlod.mlx", perPartAndCluster(""));
    const ServerRun run = runMeshlabServer({"-i", dir + "/tetra.ply", "-s", dir + "/hlod.mlx"}, 120);
    EXPECT_FALSE(run.ok());
    EXPECT_NE(run.output.find("open the assembly from its .wrl file"), std::string::npos) << run.output;
    EXPECT_FALSE(std::filesystem::exists(out));
}

// Only a .flt name is taken: a slip of the file name cannot write over the VRML input.
TEST(HeadlessRoutes, PerPartAndClusterNeverWritesOverItsInput)
{
    const std::string dir = scratchDir("routes_hlod_input");
    const std::string input = dir + "/demo.wrl.gz";
    std::filesystem::copy_file(std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz", input,
                               std::filesystem::copy_options::overwrite_existing);
    const std::string before = readText(input);
    writeText(dir + "/hlod.mlx", perPartAndCluster(input));
    const ServerRun run = runMeshlabServer({"-i", input, "-s", dir + "/hlod.mlx"}, 120);
    EXPECT_FALSE(run.ok());
    EXPECT_NE(run.output.find("give it the .flt extension"), std::string::npos) << run.output;
    EXPECT_TRUE(readText(input) == before);
}

// A file of one part (shapes no DEF names): the filter writes it as the command does, that
// part placed once, its levels held at its nearest point, where it used to refuse it.
TEST(HeadlessRoutes, PerPartAndClusterWritesAFileOfOnePartAsTheCommandDoes)
{
    const std::string dir = scratchDir("routes_hlod_one_part");
    const std::string input = dir + "/one.wrl";
    writeText(input, "#VRML V2.0 utf8\nShape { geometry Sphere { radius 0.5 } }\n"
                     "Transform { translation 2 0 0 children Shape { geometry Box { size 1 0.2 0.2 } } }\n");
    const FilterRun run = expectTheCommandsFileOf(input, dir, "1", "auto");
    EXPECT_GT(readText(run.file).size(), 1000u);
    const OsgProbe probe = probeWithOsg(run.file);
    ASSERT_TRUE(probe.loaded);
    ASSERT_FALSE(probe.lods.empty());
}
