// The two headless routes build the same chain: `cadlod convert` and the staged
// meshlabserver with docs/examples/cad_to_flt.mlx give OpenFlight files with the same levels
// (triangles and switch ranges) for the demo assembly. (With a unit conversion they differ a
// little: the example script scales with MeshLab's Transform filter after import, in float,
// the command in the importer; README and docs/benchmarks.md say so.) A MeshLab layer is one
// mesh, so the MeshLab route expands the demo's shared parts: the command does too, here.
#include "meshlabserver_runner.h"

#include "openflight/flt_reader.h"

#include <gtest/gtest.h>

#include <cstdlib>

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
