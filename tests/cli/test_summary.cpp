// What `cadlod convert` says when it is done: repeated lines folded with their count, one
// line of what the importer did, lengths in one format, no import speed.
#include "cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>
#include <sstream>

namespace cadlod::test {
namespace {

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::vector<std::string> linesOf(const std::string& text)
{
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        lines.push_back(line);
    return lines;
}

std::size_t linesContaining(const std::string& text, const std::string& part)
{
    std::size_t n = 0;
    for (const std::string& line : linesOf(text))
        n += line.find(part) != std::string::npos;
    return n;
}

// A shape with a face that indexes past its points, DEF'd once and USE'd three times more:
// expanded, the importer meets the bad face four times, at one place in the file.
std::string writeRepeatedBadFace(const std::string& dir)
{
    write(dir + "/repeat.wrl",
          "#VRML V2.0 utf8\n"
          "DEF P Transform { children Shape { geometry IndexedFaceSet {\n"
          "  coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0, 0 0 1] }\n"
          "  coordIndex [0 1 2 -1 0 2 3 -1 0 1 9 -1 0 1 4 -1] } } }\n"
          "Transform { translation 3 0 0 children USE P }\n"
          "Transform { translation 6 0 0 children USE P }\n"
          "Transform { translation 9 0 0 children USE P }\n");
    return dir + "/repeat.wrl";
}

TEST(CliSummary, RepeatedWarningsArePrintedOnceWithTheirCountAndReportedInFull)
{
    const std::string dir = freshDirectory("summary_fold");
    const CliRun run = runCadlod({"convert", writeRepeatedBadFace(dir), "-o", dir + "/r.flt", "--unit", "cm",
                                  "--instances", "expand", "--lod", "50", "--report", dir + "/r.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_EQ(linesContaining(run.stderrText, "coordIndex[10] = 9 out of range"), 1u) << run.stderrText;
    EXPECT_EQ(linesContaining(run.stderrText, "coordIndex[10] = 9 out of range (×4)"), 1u) << run.stderrText;
    EXPECT_EQ(linesContaining(run.stderrText, "cadlod: 4 warnings (4 bad index)"), 1u) << run.stderrText;
    // The report keeps every line.
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/r.json"));
    EXPECT_EQ(report.at("warnings").size(), 4u);
    EXPECT_EQ(report.at("warningCount"), 4);
}

}  // namespace
}  // namespace cadlod::test
