// An input that loses geometry (the rest of a file, an Inline, a node) fails the conversion:
// exit 1, no output, the place in the file. --allow-partial converts what was read and the
// report names what was lost. Every warning is counted in the report and the summary.
#include "cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>

namespace cadlod::test {
namespace {

const std::string kBox = "Shape { geometry Box { size 10 10 10 } }\n";

struct Broken {
    const char* name;
    std::string text;
    const char* where;  // file:line:col of the loss
    const char* kind;
};

std::vector<Broken> brokenInputs()
{
    const std::string head = "#VRML V2.0 utf8\n" + kBox;
    return {
        {"truncated", head + "Transform { translation 20 0 0 children Shape { geometry IndexedFaceSet { coord "
                             "Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] } coordIndex [ 0 1",
         "truncated.wrl:3:", "syntax error"},
        {"syntax", head + "Transform { translation 20 0 0 ] }\n" + kBox, "syntax.wrl:3:", "syntax error"},
        {"missing_inline", head + "Inline { url \"nothere.wrl\" }\n", "missing_inline.wrl:3:1", "missing inline"},
        {"cycle", head + "Inline { url \"cycle.wrl\" }\n", "cycle.wrl:3:1", "recursive inline"},
        {"bad_inline", head + "Inline { url \"broken.wrz\" }\n", "bad_inline.wrl:3:1", "bad inline"},
        {"undefined_use", head + "Transform { children USE NOPE }\n", "undefined_use.wrl:3:", "undefined USE"},
        {"missing_brace", head + "Transform { translation 20 0 0 children " + kBox, "missing_brace.wrl:4:1",
         "syntax error"},
        {"unknown_node", head + "FancyNode { size 3 }\n", "unknown_node.wrl:3:1", "unknown node"},
    };
}

std::string writeBroken(const std::string& dir, const Broken& b)
{
    std::ofstream(dir + "/broken.wrz", std::ios::binary) << "\x1f\x8b\x08\x00 not gzip";
    const std::string path = dir + "/" + b.name + ".wrl";
    std::ofstream(path) << b.text;
    return path;
}

TEST(CliInputLosses, AnInputThatLosesGeometryFailsWithoutOutput)
{
    for (const Broken& b : brokenInputs()) {
        const std::string dir = freshDirectory(std::string("loss_") + b.name);
        const std::string in = writeBroken(dir, b);
        const CliRun run = runCadlod({"convert", in, "-o", dir + "/out.flt", "--report", dir + "/out.json", "-q"});
        EXPECT_EQ(run.exitCode, 1) << b.name << ": " << run.stderrText;
        EXPECT_NE(run.stderrText.find(std::string(b.where)), std::string::npos) << b.name << ": " << run.stderrText;
        EXPECT_NE(run.stderrText.find(std::string(b.kind)), std::string::npos) << b.name << ": " << run.stderrText;
        EXPECT_NE(run.stderrText.find("--allow-partial"), std::string::npos) << b.name << ": " << run.stderrText;
        EXPECT_FALSE(fileExists(dir + "/out.flt")) << b.name;
        EXPECT_FALSE(fileExists(dir + "/out.json")) << b.name;
        const CliRun simplified = runCadlod({"simplify", in, "-o", dir + "/out.ply", "-q"});
        EXPECT_EQ(simplified.exitCode, 1) << b.name << ": " << simplified.stderrText;
        EXPECT_FALSE(fileExists(dir + "/out.ply")) << b.name;
    }
}

TEST(CliInputLosses, AllowPartialConvertsWhatWasReadAndTheReportNamesTheLoss)
{
    const Broken b = brokenInputs()[2];  // a missing Inline
    const std::string dir = freshDirectory("loss_partial");
    const std::string in = writeBroken(dir, b);
    const CliRun run = runCadlod({"convert", in, "-o", dir + "/out.flt", "--report", dir + "/out.json",
                                  "--lod", "50", "--allow-partial"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_NE(run.stderrText.find("partial input (--allow-partial): 1 missing inline"), std::string::npos)
        << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/out.json"));
    const nlohmann::json& input = report.at("input");
    EXPECT_FALSE(input.at("complete").get<bool>());
    ASSERT_EQ(input.at("lost").size(), 1u);
    EXPECT_NE(input.at("lost")[0].get<std::string>().find("missing_inline.wrl:3:1: missing inline"),
              std::string::npos);
    EXPECT_EQ(input.at("findings").at("missing inline").get<int>(), 1);
    EXPECT_GE(report.at("warningCount").get<int>(), 1);
    EXPECT_TRUE(report.at("options").at("import").at("allowPartial").get<bool>());
    EXPECT_EQ(runCadlod({"simplify", in, "-o", dir + "/out.ply", "--allow-partial", "-q"}).exitCode, 0);
    const CliRun info = runCadlod({"info", in});  // shows what can be read, and says it is incomplete
    EXPECT_EQ(info.exitCode, 0) << info.stderrText;
    EXPECT_NE(info.stdoutText.find("incomplete   1 finding(s) lost geometry"), std::string::npos) << info.stdoutText;
}

// A face skipped for a bad index stays a warning: the model is converted, and the warning
// is in the report's list and count and in the summary.
TEST(CliInputLosses, SkippedFacesAreWarningsCountedInTheReportAndSummary)
{
    const std::string dir = freshDirectory("loss_faces");
    std::ofstream(dir + "/faces.wrl") << "#VRML V2.0 utf8\n" << kBox
                                      << "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, "
                                         "0 1 0 ] } coordIndex [ 0 1 2 -1 0 1 7 -1 ] } }\n";
    const CliRun run = runCadlod({"convert", dir + "/faces.wrl", "-o", dir + "/out.flt", "--report",
                                  dir + "/out.json", "--lod", "50"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_NE(run.stderrText.find("cadlod: 1 warning (1 bad index)"), std::string::npos) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/out.json"));
    EXPECT_TRUE(report.at("input").at("complete").get<bool>());
    EXPECT_EQ(report.at("input").at("findings").at("bad index").get<int>(), 1);
    ASSERT_FALSE(report.at("warnings").empty());
    EXPECT_NE(report.at("warnings")[0].get<std::string>().find("faces.wrl:3:"), std::string::npos);
    EXPECT_NE(report.at("warnings")[0].get<std::string>().find("bad index"), std::string::npos);
    EXPECT_GE(report.at("warningCount").get<int>(), 1);
}

}  // namespace
}  // namespace cadlod::test
