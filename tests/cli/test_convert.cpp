// cadlod convert end to end: the demo assembly (mm) and a VRML 1.0 file to .flt, read back
// with OpenSceneGraph: one LOD node per level, contiguous ranges from 0, finest first. Both
// share parts: expanded here, for one chain (test_assembly_convert.cpp keeps instances).
#include "cli_runner.h"
#include "osg_probe.h"

#include <vcg/space/point3.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace cadlod::test {
namespace {

const std::string kDemo = std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz";
const std::string kVrml1 = std::string(CADLOD_CORPUS_DIR) + "/castle-demo-models/vrml_1/kings_head.wrl";

// Levels read back by OSG: contiguous switch ranges starting at 0, finer levels closer,
// and as many LOD children as the report lists levels.
void expectChain(const OsgProbe& probe, std::size_t levels)
{
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.lods.size(), levels);
    EXPECT_FLOAT_EQ(probe.lods.front().minRange, 0.0f);
    for (std::size_t k = 0; k + 1 < probe.lods.size(); ++k) {
        EXPECT_FLOAT_EQ(probe.lods[k].maxRange, probe.lods[k + 1].minRange) << "level " << k;
        EXPECT_LT(probe.lods[k].minRange, probe.lods[k].maxRange) << "level " << k;
        EXPECT_GT(probe.lods[k].triangles.size(), probe.lods[k + 1].triangles.size()) << "level " << k;
    }
}

TEST(CliConvert, DemoAssemblyInMillimetresGivesAnOsgReadableChain)
{
    const std::string dir = freshDirectory("demo");
    const CliRun run = runCadlod({"convert", kDemo, "-o", dir + "/demo.flt", "--unit", "mm", "--instances", "expand", "--report",
                                  dir + "/report.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/report.json"));
    const auto& levels = report.at("levels");
    ASSERT_GE(levels.size(), 4u);
    expectChain(probeWithOsg(dir + "/demo.flt", "noUnitsConversion"), levels.size());
    // mm scaled to metres: the assembly is a few tenths of a metre across.
    EXPECT_GT(report.at("modelSize").get<double>(), 0.1);
    EXPECT_LT(report.at("modelSize").get<double>(), 1.0);
}

// Every level keeps its sharp edges as OpenSceneGraph lights them: a vertex where faces fold
// past 30° is written once per smooth fan (metadata/crease_fans.h). One averaged normal per
// welded vertex drew the demo's boxes as soft blobs, their corners' normals 55° off each side.
TEST(CliConvert, EveryLevelIsLitWithItsCreasesSharp)
{
    const std::string dir = freshDirectory("creases");
    const CliRun run = runCadlod({"convert", kDemo, "-o", dir + "/demo.flt", "--unit", "mm", "--lod", "50 90",
                                  "--instances", "expand"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const OsgProbe probe = probeWithOsg(dir + "/demo.flt", "noUnitsConversion");
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.lods.size(), 3u);
    for (std::size_t k = 0; k < probe.lods.size(); ++k) {
        std::size_t corners = 0, offTheirFace = 0;
        for (const OsgTriangle& t : probe.lods[k].triangles) {
            ASSERT_TRUE(t.hasNormals);
            const auto at = [&](int i) { return vcg::Point3d(t.position[i][0], t.position[i][1], t.position[i][2]); };
            vcg::Point3d face = (at(1) - at(0)) ^ (at(2) - at(0));
            if (!(face.Norm() > 0))
                continue;
            face.Normalize();
            for (int i = 0; i < 3; ++i) {
                const vcg::Point3d n(t.normal[i][0], t.normal[i][1], t.normal[i][2]);
                ++corners;
                offTheirFace += n * face < std::cos(45 * M_PI / 180) * n.Norm();
            }
        }
        EXPECT_LT(double(offTheirFace), 0.01 * double(corners)) << "level " << k << ": " << offTheirFace << " of "
                                                                << corners << " corners lit more than 45° off their face";
    }
}

// An OpenFlight file is welded on reading, as VRML is: a box written with a vertex per side
// at its creases (24) reads back as one closed box of 8 vertices, not six loose squares.
TEST(CliConvert, AnOpenFlightInputIsWelded)
{
    const std::string dir = freshDirectory("flt_weld");
    {
        std::ofstream wrl(dir + "/box.wrl");
        wrl << "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, "
               "0 1 0, 0 0 1, 1 0 1, 1 1 1, 0 1 1] } coordIndex [0 3 2 1 -1, 4 5 6 7 -1, 0 1 5 4 -1, "
               "1 2 6 5 -1, 2 3 7 6 -1, 3 0 4 7 -1] } }\n";
    }
    const CliRun convert = runCadlod({"convert", dir + "/box.wrl", "-o", dir + "/box.flt"});
    ASSERT_EQ(convert.exitCode, 0) << convert.stderrText;
    const OsgProbe probe = probeWithOsg(dir + "/box.flt", "noUnitsConversion");
    ASSERT_TRUE(probe.loaded);
    ASSERT_FALSE(probe.lods.empty());
    ASSERT_EQ(probe.lods.front().triangles.size(), 12u);  // the finest level: the box itself
    const CliRun report = runCadlod({"report", dir + "/box.wrl", dir + "/box.flt", "--json"});
    ASSERT_EQ(report.exitCode, 0) << report.stderrText;
    const nlohmann::json r = nlohmann::json::parse(report.stdoutText);
    EXPECT_EQ(r.at("facesAfter").get<int>(), 12);
    EXPECT_EQ(r.at("verticesAfter").get<int>(), 8);
}

// --merge-tolerance merges close points of an OpenFlight input as it does a VRML input's: two
// squares whose shared side is 1e-4 apart become one piece of 6 vertices.
TEST(CliConvert, AnOpenFlightInputHonoursTheMergeTolerance)
{
    const std::string dir = freshDirectory("flt_merge");
    {
        std::ofstream wrl(dir + "/two.wrl");
        wrl << "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, "
               "0 1 0, 1.0001 0 0, 2 0 0, 2 1 0, 1.0001 1 0] } coordIndex [0 1 2 3 -1, 4 5 6 7 -1] } }\n";
    }
    const CliRun convert = runCadlod({"convert", dir + "/two.wrl", "-o", dir + "/two.flt", "--merge-tolerance", "0"});
    ASSERT_EQ(convert.exitCode, 0) << convert.stderrText;
    for (const std::string tolerance : {"0", "0.001"}) {
        const CliRun report =
            runCadlod({"report", dir + "/two.flt", dir + "/two.flt", "--json", "--merge-tolerance", tolerance});
        ASSERT_EQ(report.exitCode, 0) << report.stderrText;
        const nlohmann::json r = nlohmann::json::parse(report.stdoutText);
        EXPECT_EQ(r.at("verticesBefore").get<int>(), tolerance == "0" ? 8 : 6) << tolerance;
    }
}

TEST(CliConvert, Vrml1FileConverts)
{
    const std::string dir = freshDirectory("vrml1");
    const CliRun run = runCadlod({"convert", kVrml1, "-o", dir + "/head.flt", "--instances", "expand", "--report",
                                  dir + "/r.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/r.json"));
    EXPECT_EQ(report.at("input").at("format"), "VRML");
    expectChain(probeWithOsg(dir + "/head.flt", "noUnitsConversion"), report.at("levels").size());
}

TEST(CliConvert, PercentageListBuildsThePapersLevels)
{
    const std::string dir = freshDirectory("list");
    const CliRun run = runCadlod({"convert", kDemo, "-o", dir + "/list.flt", "--unit", "mm", "--lod", "50 90",
                                  "--instances", "expand", "--report", dir + "/r.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/r.json"));
    const auto& levels = report.at("levels");
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_NEAR(levels[1].at("reductionPercent").get<double>(), 50.0, 1.0);
    EXPECT_NEAR(levels[2].at("reductionPercent").get<double>(), 90.0, 1.0);
    expectChain(probeWithOsg(dir + "/list.flt", "noUnitsConversion"), 3);
}

TEST(CliConvert, ReportHasInputOptionsLevelsAndTimings)
{
    const std::string dir = freshDirectory("report");
    const CliRun run = runCadlod({"convert", kDemo, "-o", dir + "/d.flt", "--unit", "mm", "--instances", "expand", "--pixel-error", "2",
                                  "--report", dir + "/r.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json r = nlohmann::json::parse(readFile(dir + "/r.json"));
    EXPECT_EQ(r.at("input").at("path"), kDemo);
    EXPECT_EQ(r.at("input").at("parts").get<int>(), 8);
    EXPECT_EQ(r.at("options").at("pixelError").get<double>(), 2.0);
    EXPECT_EQ(r.at("options").at("import").at("unitScale").get<double>(), 0.001);
    for (const char* t : {"importSeconds", "lodSeconds", "lodMeasureSeconds", "writeSeconds", "totalSeconds"})
        EXPECT_TRUE(r.at("timings").contains(t)) << t;
    // Measuring the levels is part of building them.
    EXPECT_GT(r.at("timings").at("lodMeasureSeconds").get<double>(), 0.0);
    EXPECT_LE(r.at("timings").at("lodMeasureSeconds").get<double>(), r.at("timings").at("lodSeconds").get<double>());
    const auto& levels = r.at("levels");
    for (std::size_t k = 1; k < levels.size(); ++k) {
        const auto& l = levels[k];
        for (const char* f : {"faces", "hausdorffMax", "hausdorffMaxPercentDiag", "errorPixelsAtSwitchOut",
                              "switchOut", "switchIn", "compactness", "simplification"})
            EXPECT_TRUE(l.contains(f)) << "level " << k << " " << f;
        EXPECT_LT(l.at("faces").get<int>(), levels[k - 1].at("faces").get<int>());
        // Switched in where its error projects to at most the pixel error.
        EXPECT_LE(l.at("errorPixelsAtSwitchOut").get<double>(), 2.0 * 1.001) << "level " << k;
        EXPECT_TRUE(l.at("simplification").contains("relaxed"));
    }
    EXPECT_EQ(levels.back().at("switchIn"), "never");
}

TEST(CliConvert, OneAndTwoThreadsWriteTheSameBytes)
{
    // Same file name (the model is named after it), one directory per thread count.
    const std::string one = freshDirectory("threads_1") + "/out.flt", two = freshDirectory("threads_2") + "/out.flt";
    for (const auto& [n, out] : {std::pair{"1", one}, std::pair{"2", two}}) {
        const CliRun run = runCadlod({"convert", kDemo, "-o", out, "--unit", "mm", "--threads", n});
        ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    }
    const std::string bytes1 = readFile(one), bytes2 = readFile(two);
    ASSERT_GT(bytes1.size(), 1000u);
    EXPECT_TRUE(bytes1 == bytes2);
}

}  // namespace
}  // namespace cadlod::test
