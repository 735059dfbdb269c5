// Exit codes and messages: 1 for inputs that cannot be read (with where), 2 for usage.
#include "cli_runner.h"

#include <gtest/gtest.h>

#include <fstream>

namespace cadlod::test {
namespace {

const std::string kDemo = std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz";

TEST(CliErrors, MissingInputIsAnInputError)
{
    const std::string dir = freshDirectory("missing");
    const CliRun run = runCadlod({"convert", dir + "/nothing.wrl", "-o", dir + "/x.flt"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.stderrText.find("nothing.wrl: cannot open file"), std::string::npos) << run.stderrText;
    EXPECT_FALSE(fileExists(dir + "/x.flt"));
}

TEST(CliErrors, BrokenVrmlSaysWhereAndExitsWithOne)
{
    const std::string dir = freshDirectory("broken");
    std::ofstream(dir + "/bad.wrl") << "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate {\n"
                                       "  point [ 0 0 0, 1 0 0 ] } coordIndex [ 0 1 2 -1 ] ";
    const CliRun run = runCadlod({"convert", dir + "/bad.wrl", "-o", dir + "/bad.flt"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.stderrText.find("bad.wrl:3:"), std::string::npos) << run.stderrText;  // file:line:col
    EXPECT_NE(run.stderrText.find("error:"), std::string::npos) << run.stderrText;
    EXPECT_FALSE(fileExists(dir + "/bad.flt"));
}

TEST(CliErrors, TruncatedOpenFlightGivesTheRecordOffset)
{
    const std::string dir = freshDirectory("badflt");
    ASSERT_EQ(runCadlod({"convert", kDemo, "-o", dir + "/d.flt", "--unit", "mm", "--lod", "90", "-q"}).exitCode, 0);
    const std::string bytes = readFile(dir + "/d.flt");
    std::ofstream(dir + "/cut.flt", std::ios::binary) << bytes.substr(0, bytes.size() / 2 + 3);
    const CliRun run = runCadlod({"info", dir + "/cut.flt"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.stderrText.find("cut.flt"), std::string::npos) << run.stderrText;
    EXPECT_NE(run.stderrText.find("offset"), std::string::npos) << run.stderrText;
}

TEST(CliErrors, UsageErrorsExitWithTwo)
{
    EXPECT_EQ(runCadlod({}).exitCode, 2);
    EXPECT_EQ(runCadlod({"convert", kDemo}).exitCode, 2);  // no -o
    const CliRun unknown = runCadlod({"convert", kDemo, "-o", "x.flt", "--no-such-option"});
    EXPECT_EQ(unknown.exitCode, 2);
    EXPECT_NE(unknown.stderrText.find("--no-such-option"), std::string::npos) << unknown.stderrText;
    const CliRun unit = runCadlod({"convert", kDemo, "-o", "x.flt", "--unit", "furlong"});
    EXPECT_EQ(unit.exitCode, 2);
    EXPECT_NE(unit.stderrText.find("--unit: 'furlong'"), std::string::npos) << unit.stderrText;
    EXPECT_EQ(runCadlod({"convert", kDemo, "-o", "x.ply"}).exitCode, 2);
    EXPECT_EQ(runCadlod({"--help"}).exitCode, 0);
}

// A bad option value is a usage error found before the input is read (here it does not
// exist, and is never blamed).
TEST(CliErrors, BadOptionValuesAreUsageErrorsFoundBeforeReading)
{
    const std::string dir = freshDirectory("bad_values");
    const std::string none = dir + "/none.wrl";
    for (const std::vector<std::string>& bad :
         {std::vector<std::string>{"--lod", "50 abc"}, {"--lod", "90 50"}, {"--lod", "120"}, {"--pixel-error", "0"},
          {"--fov", "180"}, {"--viewport", "-5"}, {"--distance-ratio", "1"}, {"--unit", "-2"},
          {"--default-unit", "furlong"}}) {
        std::vector<std::string> args{"convert", none, "-o", dir + "/x.flt"};
        args.insert(args.end(), bad.begin(), bad.end());
        const CliRun run = runCadlod(args);
        EXPECT_EQ(run.exitCode, 2) << bad[0] << " " << bad[1] << ": " << run.stderrText;
        EXPECT_NE(run.stderrText.find(bad[0]), std::string::npos) << run.stderrText;
        EXPECT_EQ(run.stderrText.find("none.wrl"), std::string::npos) << run.stderrText;
    }
    const CliRun lod = runCadlod({"convert", none, "-o", dir + "/x.flt", "--lod", "50 abc"});
    EXPECT_NE(lod.stderrText.find("'abc' is not a number"), std::string::npos) << lod.stderrText;
    EXPECT_FALSE(fileExists(dir + "/x.flt"));
}

// --version needs no subcommand: it prints the project's version and exits 0.
TEST(CliErrors, VersionPrintsTheVersion)
{
    const CliRun v = runCadlod({"--version"});
    EXPECT_EQ(v.exitCode, 0) << v.stderrText;
    EXPECT_EQ(v.stdoutText, "cadlod " CADLOD_TEST_VERSION "\n");
}

}  // namespace
}  // namespace cadlod::test
