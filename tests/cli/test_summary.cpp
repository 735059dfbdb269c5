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

// One face indexes past the points; another uses two points at one place, which welding
// makes one vertex: the importer drops both.
std::string writeWeldedFaces(const std::string& dir)
{
    write(dir + "/weld.wrl", "#VRML V2.0 utf8\n"
                             "Shape { geometry IndexedFaceSet {\n"
                             "  coord Coordinate { point [0 0 0, 1 0 0, 1 1 0, 0 1 0, 0 0 0] }\n"
                             "  coordIndex [0 1 2 -1 0 2 3 -1 0 1 4 -1 0 1 7 -1] } }\n");
    return dir + "/weld.wrl";
}

TEST(CliSummary, OneLineSaysWhatTheImporterDid)
{
    const std::string dir = freshDirectory("summary_import");
    const CliRun run = runCadlod({"convert", writeWeldedFaces(dir), "-o", dir + "/w.flt", "--unit", "cm", "--lod", "50",
                                  "--report", dir + "/w.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/w.json"));
    const int welded = report.at("input").at("mergedVertices");
    EXPECT_GT(welded, 0);
    EXPECT_EQ(linesContaining(run.stderrText, "cadlod: import: 1 part, " + std::to_string(welded) +
                                                  " vertices welded, 2 faces dropped (1 invalid, 1 degenerate after "
                                                  "welding); input unit cm (--unit cm)"),
              1u)
        << run.stderrText;
    EXPECT_EQ(report.at("input").at("facesDropped").at("invalid"), 1);
    EXPECT_EQ(report.at("input").at("facesDropped").at("degenerateAfterWelding"), 1);
}

// A board DEF'd once and placed three times, with a cylinder placed twice on it.
std::string writeSmallAssembly(const std::string& dir, const std::string& name)
{
    write(dir + "/" + name, "#VRML V2.0 utf8\n"
                            "DEF BOARD Group { children [\n"
                            "  Shape { geometry Box { size 30 20 1 } }\n"
                            "  DEF C1 Transform { translation 0 5 1 children\n"
                            "    DEF CYL Shape { geometry Cylinder { radius 1 height 4 } } }\n"
                            "  DEF C2 Transform { translation 0 -5 1 children USE CYL }\n"
                            "] }\n"
                            "DEF Board_2 Transform { translation 0 0 40 children USE BOARD }\n"
                            "DEF Board_3 Transform { translation 50 0 0 children USE BOARD }\n");
    return dir + "/" + name;
}

TEST(CliSummary, AnAssemblysImportLineCountsItsPartsAndPlacements)
{
    const std::string dir = freshDirectory("summary_assembly_import");
    const CliRun run = runCadlod({"convert", writeSmallAssembly(dir, "board.wrl"), "-o", dir + "/b.flt", "--unit", "mm",
                                  "--report", dir + "/b.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/b.json"));
    const std::size_t parts = report.at("parts").size();
    const std::size_t placements = report.at("output").at("placements");
    EXPECT_EQ(linesContaining(run.stderrText, "cadlod: import: " + std::to_string(parts) + " distinct parts in " +
                                                  std::to_string(placements) + " placements, "),
              1u)
        << run.stderrText;
    EXPECT_EQ(linesContaining(run.stderrText, "no faces dropped; input unit mm (--unit mm)"), 1u) << run.stderrText;
}

// The summary's lines: all but the progress.
std::string summaryOf(const std::string& stderrText)
{
    static const std::regex progress(R"(^cadlod: +\d+%.*)");
    std::string out;
    for (const std::string& line : linesOf(stderrText))
        if (!std::regex_match(line, progress))
            out += line + "\n";
    return out;
}

TEST(CliSummary, LengthsAreWrittenWithoutExponentsAndTheModelSizeIsALength)
{
    const std::string dir = freshDirectory("summary_formats");
    write(dir + "/tower.wrl", "#VRML V2.0 utf8\nShape { geometry Sphere { radius 700 } }\n");
    const CliRun run = runCadlod({"convert", dir + "/tower.wrl", "-o", dir + "/t.flt"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const std::string summary = summaryOf(run.stderrText);
    EXPECT_FALSE(std::regex_search(summary, std::regex(R"(\d[eE][+-]?\d)"))) << summary;
    EXPECT_TRUE(std::regex_search(summary, std::regex(R"(\(model size \d+(\.\d+)? m\))"))) << summary;
    EXPECT_TRUE(std::regex_search(summary, std::regex(R"(the model is \d+ m across)"))) << summary;
    EXPECT_TRUE(std::regex_search(summary, std::regex(R"(\.\. \d{5,} m\n)"))) << summary;  // past 10 km
}

TEST(CliSummary, NoImportSpeedIsPrinted)
{
    const std::regex speed(R"(B/s|/s\b|per second)");
    const std::string dir = freshDirectory("summary_speed");
    for (const std::string& input : {writeWeldedFaces(dir), writeSmallAssembly(dir, "board.wrl")}) {
        const CliRun run = runCadlod({"convert", input, "-o", dir + "/out.flt", "--force", "--lod", "50"});
        ASSERT_EQ(run.exitCode, 0) << run.stderrText;
        EXPECT_FALSE(std::regex_search(run.stdoutText + run.stderrText, speed)) << run.stderrText;
        const CliRun info = runCadlod({"info", input});
        ASSERT_EQ(info.exitCode, 0) << info.stderrText;
        EXPECT_FALSE(std::regex_search(info.stdoutText + info.stderrText, speed)) << info.stdoutText;
    }
}

}  // namespace
}  // namespace cadlod::test
