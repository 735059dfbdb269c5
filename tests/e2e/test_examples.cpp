// The scripts in docs/examples/ are what users copy: each must already list every parameter
// in order (stock meshlabserver 2020.09 aborts otherwise) and must run.
#include "meshlabserver_runner.h"
#include "osg_probe.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>

namespace fs = std::filesystem;
using namespace cadlod::test;

namespace {

std::vector<std::string> parameterNames(const std::string& script)
{
    std::vector<std::string> names;
    const std::regex param("<Param [^>]*name=\"([^\"]+)\"");
    for (std::sregex_iterator it(script.begin(), script.end(), param), end; it != end; ++it)
        names.push_back((*it)[1]);
    return names;
}

std::vector<std::string> exampleScripts()
{
    std::vector<std::string> scripts;
    for (const auto& entry : fs::directory_iterator(fs::path(CADLOD_SOURCE_DIR) / "docs/examples"))
        if (entry.path().extension() == ".mlx")
            scripts.push_back(entry.path().string());
    std::sort(scripts.begin(), scripts.end());
    return scripts;
}

}  // namespace

TEST(Examples, EveryScriptListsEveryParameterInOrder)
{
    const std::vector<std::string> scripts = exampleScripts();
    ASSERT_GE(scripts.size(), 2u);
    const std::string dir = scratchDir("examples");
    for (const std::string& script : scripts) {
        const std::string completed = dir + "/" + fs::path(script).filename().string();
        const ServerRun run = completeMlx(script, completed);
        ASSERT_TRUE(run.ok()) << script << "\n" << run.output;
        EXPECT_EQ(parameterNames(readText(script)), parameterNames(readText(completed)))
            << script << " is not complete: regenerate it with scripts/complete_mlx.sh";
    }
}

TEST(Examples, MillimetrePartBecomesAnOpenFlightLodSetInMeters)
{
    const std::string dir = scratchDir("examples_run");
    const std::string flt = dir + "/shaft.flt";
    const ServerRun run = runMeshlabServer({"-i", std::string(CADLOD_SOURCE_DIR) + "/docs/sample/shaft.wrl", "-s",
                                            std::string(CADLOD_SOURCE_DIR) + "/docs/examples/cad_mm_to_flt.mlx",
                                            "-o", flt},
                                           300);
    ASSERT_TRUE(run.ok()) << run.output;
    const OsgProbe probe = probeWithOsg(flt);
    ASSERT_TRUE(probe.loaded);
    ASSERT_GE(probe.lods.size(), 2u);
    EXPECT_EQ(probe.lods[0].triangles.size(), 23716u);
    // The shaft is 200 mm long: in meters its LOD center lies within 0.2 of the origin.
    for (double c : probe.lods[0].center)
        EXPECT_LT(std::abs(c), 0.2);
    for (std::size_t l = 1; l < probe.lods.size(); ++l) {
        EXPECT_LT(probe.lods[l].triangles.size(), probe.lods[l - 1].triangles.size());
        EXPECT_EQ(probe.lods[l].minRange, probe.lods[l - 1].maxRange);
    }
}

TEST(Examples, AssemblyBecomesAHierarchicalLodBesideIt)
{
    const std::string dir = scratchDir("examples_hlod");
    const std::string input = dir + "/cad_assembly.wrl.gz", written = dir + "/cad_assembly_hlod.flt";
    fs::copy_file(std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz", input,
                  fs::copy_options::overwrite_existing);
    fs::remove(written);
    const ServerRun run = runMeshlabServer(
        {"-i", input, "-s", std::string(CADLOD_SOURCE_DIR) + "/docs/examples/cad_to_hlod_flt.mlx"}, 300);
    ASSERT_TRUE(run.ok()) << run.output;
    const OsgProbe probe = probeWithOsg(written);
    ASSERT_TRUE(probe.loaded) << written;
    // The parts' levels and the proxies, below a cluster's Group.
    EXPECT_GE(probe.lods.size(), 10u);
    EXPECT_TRUE(std::any_of(probe.names.begin(), probe.names.end(),
                            [](const std::string& name) { return name.rfind("cluster", 0) == 0; }));
}
