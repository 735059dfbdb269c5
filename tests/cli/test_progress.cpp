// The progress of `cadlod convert`: one bar for the whole job, whose percentages never go
// back, each phase named, no step named twice; and the bar's line fitted to the terminal.
#include "cli_runner.h"
#include "progress_bar.h"

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <unistd.h>

namespace cadlod::test {
namespace {

struct ProgressLine {
    int percent = 0;
    std::string text;
};

// The "cadlod:  NN% text" lines of a run whose stderr is not a terminal.
std::vector<ProgressLine> progressLines(const std::string& stderrText)
{
    static const std::regex line(R"(^cadlod: +(\d+)%(?: (.*))?$)");
    std::vector<ProgressLine> out;
    std::istringstream in(stderrText);
    std::smatch m;
    for (std::string s; std::getline(in, s);)
        if (std::regex_match(s, m, line))
            out.push_back({std::stoi(m[1]), m[2]});
    return out;
}

// Percentages from 0 to 100 that never go back; each phase named; each step (a text beyond
// a phase's bare name) on one line only.
void expectOneMonotoneBar(const std::string& stderrText, const std::vector<std::string>& steps)
{
    const std::vector<ProgressLine> lines = progressLines(stderrText);
    ASSERT_GE(lines.size(), 3u) << stderrText;
    EXPECT_EQ(lines.front().percent, 0) << stderrText;
    EXPECT_EQ(lines.back().percent, 100) << stderrText;
    std::map<std::string, int> named;
    for (std::size_t k = 0; k < lines.size(); ++k) {
        if (k > 0) {
            EXPECT_GE(lines[k].percent, lines[k - 1].percent) << "line " << k << "\n" << stderrText;
        }
        ++named[lines[k].text];
    }
    for (const char* phase : {"reading", "LOD chain", "writing"})
        EXPECT_TRUE(named.count(phase)) << phase << "\n" << stderrText;
    for (const auto& [text, count] : named) {
        if (text != "reading" && text != "LOD chain" && text != "writing") {
            EXPECT_EQ(count, 1) << text << "\n" << stderrText;
        }
    }
    for (const std::string& step : steps) {
        int linesNaming = 0;
        for (const auto& [text, count] : named)
            linesNaming += text.find(step) != std::string::npos ? count : 0;
        EXPECT_GE(linesNaming, 1) << step << "\n" << stderrText;
    }
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Two parts, each placed twice, the whole board placed twice more: parts and a proxy.
std::string writeInstancedAssembly(const std::string& dir)
{
    write(dir + "/knob.wrl", "#VRML V2.0 utf8\nShape { geometry Sphere { radius 2 } }\n");
    write(dir + "/asm.wrl", "#VRML V2.0 utf8\n"
                            "DEF BOARD Group { children [\n"
                            "  Shape { geometry Box { size 30 20 1 } }\n"
                            "  DEF K1 Transform { translation -8 0 1 children Inline { url \"knob.wrl\" } }\n"
                            "  DEF K2 Transform { translation 8 0 1 children Inline { url \"knob.wrl\" } }\n"
                            "  DEF C1 Transform { translation 0 5 1 children\n"
                            "    DEF CYL Shape { geometry Cylinder { radius 1 height 4 } } }\n"
                            "  DEF C2 Transform { translation 0 -5 1 children USE CYL }\n"
                            "] }\n"
                            "DEF Board_2 Transform { translation 0 0 40 children USE BOARD }\n");
    return dir + "/asm.wrl";
}

TEST(CliProgress, TheSampleShowsOneBarFromReadingToWriting)
{
    const std::string dir = freshDirectory("progress_sample");
    const CliRun run = runCadlod({"convert", std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz", "-o",
                                  dir + "/sample.flt", "--unit", "mm", "--instances", "expand"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    expectOneMonotoneBar(run.stderrText, {"simplifying for", "measuring the box proxy"});
}

TEST(CliProgress, AnInstancedAssemblyShowsItsPartsAndProxiesInTheOneBar)
{
    const std::string dir = freshDirectory("progress_assembly");
    const CliRun run = runCadlod({"convert", writeInstancedAssembly(dir), "-o", dir + "/asm.flt", "--unit", "mm"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    expectOneMonotoneBar(run.stderrText, {"part 1/", "proxy 1/"});
}

TEST(CliProgress, QuietPrintsNoProgress)
{
    const std::string dir = freshDirectory("progress_quiet");
    const CliRun run = runCadlod({"convert", std::string(CADLOD_SOURCE_DIR) + "/docs/sample/shaft.wrl", "-o",
                                  dir + "/shaft.flt", "-q"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_TRUE(progressLines(run.stderrText).empty()) << run.stderrText;
}

TEST(ProgressLine, FillsTheWidthButTheLastColumn)
{
    for (int columns : {20, 40, 80, 200}) {
        const std::string line = cli::progress::fitLine(42, "LOD chain: simplifying for 1.43 m and beyond", columns);
        EXPECT_EQ(int(line.size()), columns - 1) << "[" << line << "]";
        EXPECT_NE(line.find(" 42%"), std::string::npos) << line;
    }
}

TEST(ProgressLine, CutsATextTooLongAtAWordBoundary)
{
    const std::string text = "LOD chain: part 12/40 a_part_with_a_long_name and more words";
    const std::string line = cli::progress::fitLine(7, text, 60);
    ASSERT_EQ(line.size(), 59u) << line;
    const std::size_t dots = line.find("...");
    ASSERT_NE(dots, std::string::npos) << line;
    const std::size_t start = line.find("LOD chain");
    ASSERT_NE(start, std::string::npos) << line;
    const std::string kept = line.substr(start, dots - start);
    EXPECT_EQ(text.compare(0, kept.size(), kept), 0) << line;  // a prefix of the text ...
    EXPECT_EQ(text[kept.size()], ' ') << line;                  // ... ending where a word does
}

TEST(ProgressLine, ShowsTheWholeTextWhenItFits)
{
    const std::string line = cli::progress::fitLine(100, "writing", 200);
    EXPECT_NE(line.find("[##############################] 100% writing"), std::string::npos) << line;
}

TEST(ProgressLine, CountsAMultibyteCharacterAsOneColumn)
{
    const std::string line = cli::progress::fitLine(5, "LOD chain: part 1/2 Gehäuse_für_Lüfter", 30);
    std::size_t columns = 0;
    for (char c : line)
        columns += (static_cast<unsigned char>(c) & 0xC0) != 0x80;
    EXPECT_EQ(columns, 29u) << line;
    const std::string wide = cli::progress::fitLine(5, "Gehäuse", 80);
    EXPECT_NE(wide.find("Gehäuse"), std::string::npos) << wide;
}

TEST(ProgressLine, TheTerminalWidthComesFromColumnsWhenStderrIsNoTerminal)
{
    if (::isatty(STDERR_FILENO))
        GTEST_SKIP() << "stderr is a terminal: its own width wins";
    ::setenv("COLUMNS", "123", 1);
    EXPECT_EQ(cli::progress::terminalColumns(), 123);
    ::unsetenv("COLUMNS");
    EXPECT_EQ(cli::progress::terminalColumns(), 80);
}

}  // namespace
}  // namespace cadlod::test
