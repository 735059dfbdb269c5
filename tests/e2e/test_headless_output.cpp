// What a user reads from the staged meshlabserver (issue 16, item 9):
//   QT_LOGGING_RULES='*.debug=false' xvfb-run -a build/stage/bin/meshlabserver -i shaft.wrl -s script.mlx -o shaft.flt
// Each progress message is a line of its own (meshlabserver prints them with no newline, so
// they ran together), and each log line appears once (MeshLab echoes every log line with
// qDebug, which the documented setting turns off).
#include "meshlabserver_runner.h"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

using namespace cadlod::test;

namespace {

// The setting the README and the user guide put before every meshlabserver command.
const char* const kDocumentedEnvironment = "QT_LOGGING_RULES='*.debug=false'";

// The messages filter_cadlod reports progress with (lib/support/progress_lines.h).
const std::regex kProgressMessage("CAD edge collapse|Simplifying (level|for)|Measuring (level|the box)|LOD chain done");

std::vector<std::string> linesOf(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

std::size_t progressMessagesIn(const std::string& line)
{
    return std::distance(std::sregex_iterator(line.begin(), line.end(), kProgressMessage), std::sregex_iterator());
}

std::size_t linesContaining(const std::vector<std::string>& lines, const std::string& text)
{
    std::size_t n = 0;
    for (const std::string& line : lines)
        n += line.find(text) != std::string::npos;
    return n;
}

// The CAD simplifier, then an LOD set by screen-space error, on the sample shaft: both
// filters report progress, the second logs one line per level.
class HeadlessOutputE2E : public ::testing::Test {
protected:
    static void SetUpTestSuite()
    {
        const std::string dir = scratchDir("headless_output");
        writeText(dir + "/script.mlx",
                  mlxScript({mlxFilter("Simplification: CAD Quadric Edge Collapse (compactness)",
                                       {mlxParam("RichFloat", "reductionPerc", "50")}),
                             mlxFilter("Generate CAD LOD Set")}));
        run_ = runMeshlabServerAsDocumented({"-i", std::string(CADLOD_SOURCE_DIR) + "/docs/sample/shaft.wrl", "-s",
                                             dir + "/script.mlx", "-o", dir + "/shaft.flt"},
                                            kDocumentedEnvironment, 300);
    }
    static inline ServerRun run_;
};

}  // namespace

TEST_F(HeadlessOutputE2E, EachProgressMessageIsALineOfItsOwn)
{
    ASSERT_TRUE(run_.ok()) << run_.output;
    std::size_t progressLines = 0, collapseLines = 0;
    for (const std::string& line : linesOf(run_.standardOutput)) {
        const std::size_t messages = progressMessagesIn(line);
        EXPECT_LE(messages, 1u) << "progress messages run together: " << line;
        if (messages == 0)
            continue;
        EXPECT_TRUE(std::regex_search(line, kProgressMessage, std::regex_constants::match_continuous))
            << "a progress message does not start its line: " << line;
        ++progressLines;
        collapseLines += line.rfind("CAD edge collapse", 0) == 0;
    }
    EXPECT_GE(progressLines, 3u) << "no progress reached stdout:\n" << run_.standardOutput;
    EXPECT_GE(collapseLines, 1u);
    EXPECT_LE(collapseLines, 21u) << "one line per 5 % at most, not one per step";
}

TEST_F(HeadlessOutputE2E, EachLogLineAppearsOnceWithTheDocumentedEnvironment)
{
    ASSERT_TRUE(run_.ok()) << run_.output;
    const std::vector<std::string> lines = linesOf(run_.standardOutput + run_.standardError);
    // The script's last filter: meshlabserver prints the whole log again after each filter,
    // so an earlier filter's lines repeat whatever the setting (docs/user-guide.md).
    EXPECT_EQ(linesContaining(lines, "LOD0:"), 1u) << run_.output;
    EXPECT_EQ(linesContaining(lines, "; model size "), 1u) << run_.output;
    EXPECT_EQ(linesContaining(lines, " s of it measuring the levels against level 0)"), 1u) << run_.output;
    // The IO plugin's own stderr lines (fprintf, not qDebug) stay, once each.
    EXPECT_EQ(linesContaining(lines, "io_vrml_flt: VRML 2 import of"), 1u) << run_.output;
    EXPECT_EQ(linesContaining(lines, "io_vrml_flt: OpenFlight"), 1u) << run_.output;
}

TEST(HeadlessOutputDocs, MeshlabserverCommandsCarryTheSetting)
{
    for (const char* doc : {"README.md", "docs/user-guide.md"}) {
        const std::string text = readText(std::string(CADLOD_SOURCE_DIR) + "/" + doc);
        const std::string command = std::string(kDocumentedEnvironment) + " xvfb-run -a build/stage/bin/meshlabserver";
        EXPECT_NE(text.find(command), std::string::npos) << doc << " does not show: " << command;
    }
}
