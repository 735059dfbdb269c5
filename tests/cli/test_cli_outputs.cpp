// Outputs: never over an existing file without --force; a run killed while writing leaves
// no truncated output; simplify/report/info on PLY/OBJ/STL.
#include "cad_meshes.h"
#include "cli_runner.h"
#include "openflight/flt_reader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace cadlod::test {
namespace {

const std::string kDemo = std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz";

bool readsBack(const std::string& path)
{
    flt::LodModel model;
    std::string error;
    return flt::readOpenFlightFile(path, model, error) && !model.levels.empty();
}

TEST(CliOutputs, RefusesToOverwriteWithoutForce)
{
    const std::string dir = freshDirectory("overwrite");
    const std::string out = dir + "/d.flt";
    std::ofstream(out) << "keep me";
    const CliRun refused = runCadlod({"convert", kDemo, "-o", out, "--unit", "mm", "--lod", "90"});
    EXPECT_EQ(refused.exitCode, 2);
    EXPECT_NE(refused.stderrText.find("use --force"), std::string::npos) << refused.stderrText;
    EXPECT_EQ(readFile(out), "keep me");
    const CliRun forced = runCadlod({"convert", kDemo, "-o", out, "--unit", "mm", "--lod", "90", "--force"});
    EXPECT_EQ(forced.exitCode, 0) << forced.stderrText;
    EXPECT_TRUE(readsBack(out));
    EXPECT_EQ(filesIn(dir).size(), 1u);  // no temporary file left behind
}

// The report on the model's own path is a usage error, found before any work; the model
// is not replaced by the JSON.
TEST(CliOutputs, ReportOnTheOutputsPathIsAUsageError)
{
    const std::string dir = freshDirectory("report_same");
    const CliRun run = runCadlod({"convert", kDemo, "-o", dir + "/d.flt", "--report", dir + "/./d.flt", "--unit",
                                  "mm", "--lod", "90"});
    EXPECT_EQ(run.exitCode, 2) << run.stderrText;
    EXPECT_NE(run.stderrText.find("is the same file as -o"), std::string::npos) << run.stderrText;
    EXPECT_TRUE(filesIn(dir).empty());
}

// Both outputs or neither: a report that cannot be written leaves no model behind, and
// every output path is checked before the input is read (here it does not even exist).
TEST(CliOutputs, OutputPathsAreCheckedBeforeReadingAndWrittenTogether)
{
    const std::string dir = freshDirectory("outputs_together");
    const CliRun report = runCadlod({"convert", kDemo, "-o", dir + "/d.flt", "--report", dir + "/no/such/r.json",
                                     "--unit", "mm", "--lod", "90"});
    EXPECT_EQ(report.exitCode, 1) << report.stderrText;
    EXPECT_NE(report.stderrText.find("r.json: the folder"), std::string::npos) << report.stderrText;
    EXPECT_TRUE(filesIn(dir).empty());
    const CliRun rerun = runCadlod({"convert", kDemo, "-o", dir + "/d.flt", "--report", dir + "/r.json", "--unit",
                                    "mm", "--lod", "90", "-q"});
    EXPECT_EQ(rerun.exitCode, 0) << rerun.stderrText;
    EXPECT_EQ(filesIn(dir).size(), 2u);

    for (const std::vector<std::string>& args :
         {std::vector<std::string>{"convert", dir + "/none.wrl", "-o", dir + "/no/x.flt"},
          std::vector<std::string>{"convert", dir + "/none.wrl", "-o", dir + "/x.flt", "--report", dir + "/no/r.json"},
          std::vector<std::string>{"simplify", dir + "/none.wrl", "-o", dir + "/no/x.ply"}}) {
        const CliRun early = runCadlod(args);
        EXPECT_EQ(early.exitCode, 1) << early.stderrText;
        EXPECT_NE(early.stderrText.find("the folder " + dir + "/no does not exist"), std::string::npos)
            << early.stderrText;
        EXPECT_EQ(early.stderrText.find("none.wrl"), std::string::npos) << early.stderrText;  // not read
    }
    std::filesystem::create_directory(dir + "/sub.flt");
    const CliRun folder = runCadlod({"convert", dir + "/none.wrl", "-o", dir + "/sub.flt", "--force"});
    EXPECT_EQ(folder.exitCode, 2) << folder.stderrText;
    EXPECT_NE(folder.stderrText.find("is a folder"), std::string::npos) << folder.stderrText;
}

// Starts cadlod with stderr on a pipe (plain progress lines) and SIGKILLs it as soon as it
// reports writing the OpenFlight file.
void killWhileWriting(const std::vector<std::string>& args)
{
    int fds[2];
    ASSERT_EQ(::pipe(fds), 0);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        ::dup2(fds[1], STDERR_FILENO);
        ::close(fds[0]);
        std::vector<char*> argv{const_cast<char*>(CADLOD_CLI)};
        for (const std::string& a : args)
            argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::unsetenv("DISPLAY");
        ::execv(CADLOD_CLI, argv.data());
        ::_exit(127);
    }
    ::close(fds[1]);
    FILE* err = ::fdopen(fds[0], "r");
    char line[512];
    bool writing = false;
    while (!writing && std::fgets(line, sizeof line, err))
        writing = std::string(line).find("% writing") != std::string::npos;
    ::kill(pid, SIGKILL);
    std::fclose(err);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(writing) << "cadlod never reported writing";
}

TEST(CliOutputs, KilledRunLeavesNoTruncatedOutput)
{
    const std::string dir = freshDirectory("killed");
    const std::string out = dir + "/d.flt";
    killWhileWriting({"convert", kDemo, "-o", out, "--unit", "mm", "--lod", "50 90"});
    // Killed before the rename: no output at all; after it: a whole file. Never a part.
    if (fileExists(out)) {
        EXPECT_TRUE(readsBack(out));
    }
    for (const std::string& name : filesIn(dir))
        EXPECT_TRUE(name == "d.flt" || name.rfind(".d.flt.tmp-", 0) == 0) << name;

    // Over an existing output (--force): the old file stays whole until the new one is.
    std::ofstream(out, std::ios::trunc) << "old";
    killWhileWriting({"convert", kDemo, "-o", out, "--unit", "mm", "--lod", "50 90", "--force"});
    const std::string after = readFile(out);
    EXPECT_TRUE(after == "old" || readsBack(out));
}

TEST(CliOutputs, SimplifyWritesPlyObjStlAndReportMeasuresIt)
{
    const std::string dir = freshDirectory("simplify");
    for (const char* ext : {"ply", "obj", "stl", "flt"}) {
        const std::string out = dir + "/s." + ext;
        const CliRun run = runCadlod({"simplify", kDemo, "-o", out, "--unit", "mm", "--reduction", "80", "-q"});
        ASSERT_EQ(run.exitCode, 0) << ext << ": " << run.stderrText;
        const CliRun info = runCadlod({"info", out});
        ASSERT_EQ(info.exitCode, 0) << ext << ": " << info.stderrText;
        EXPECT_NE(info.stdoutText.find("triangles"), std::string::npos);
    }
    // The OBJ's header names the output, not the temporary file it was written as.
    const std::string obj = readFile(dir + "/s.obj");
    EXPECT_NE(obj.find("# Object s.obj "), std::string::npos) << obj.substr(0, 200);
    EXPECT_EQ(obj.find(".tmp-"), std::string::npos) << obj.substr(0, 200);
    const CliRun report = runCadlod({"report", kDemo, dir + "/s.ply", "--unit", "mm", "--json", "--samples", "20000"});
    ASSERT_EQ(report.exitCode, 0) << report.stderrText;
    const nlohmann::json r = nlohmann::json::parse(report.stdoutText);
    EXPECT_GT(r.at("facesBefore").get<int>(), 4 * r.at("facesAfter").get<int>());
    EXPECT_GT(r.at("hausdorffMaxPercentDiag").get<double>(), 0.0);
    EXPECT_LT(r.at("hausdorffMaxPercentDiag").get<double>(), 5.0);
    EXPECT_TRUE(r.contains("compactnessAfter"));
}

// What a CadBuilder made, as an ASCII PLY.
void writePly(const CadBuilder& b, const std::string& path)
{
    std::ofstream out(path);
    out << "ply\nformat ascii 1.0\nelement vertex " << b.points.size() << "\nproperty float x\nproperty float y\n"
        << "property float z\nelement face " << b.triangles.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto& p : b.points)
        out << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    for (const auto& t : b.triangles)
        out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

// The simplifier tests' drilled plate (40 x 40 x 2, a hole of radius 4, 32 points per ring:
// a closed surface of genus 1) as an ASCII PLY.
void writeDrilledPlatePly(const std::string& path)
{
    CadBuilder b;
    drilledPlate(b, 40, 2, 4, 32);
    writePly(b, path);
}

int trianglesOf(const std::string& path)
{
    const CliRun info = runCadlod({"info", path});
    const std::size_t at = info.stdoutText.find("triangles");
    return at == std::string::npos ? -1 : std::stoi(info.stdoutText.substr(at + 9));
}

// --shading-weight reaches the simplifier: on the generated assembly, whose shaft's facets the
// price keeps at 75 %, 0 (geometry alone) writes another mesh than the default; a negative
// weight is a usage error.
TEST(CliOutputs, ShadingWeightReachesTheSimplifier)
{
    const std::string dir = freshDirectory("shading");
    CadBuilder b;
    assembly(b, 48);
    writePly(b, dir + "/assembly.ply");
    const CliRun priced = runCadlod({"simplify", dir + "/assembly.ply", "-o", dir + "/priced.ply", "--reduction", "75"});
    ASSERT_EQ(priced.exitCode, 0) << priced.stderrText;
    const CliRun plain = runCadlod(
        {"simplify", dir + "/assembly.ply", "-o", dir + "/plain.ply", "--reduction", "75", "--shading-weight", "0"});
    ASSERT_EQ(plain.exitCode, 0) << plain.stderrText;
    EXPECT_EQ(trianglesOf(dir + "/priced.ply"), trianglesOf(dir + "/plain.ply"));
    EXPECT_NE(readFile(dir + "/priced.ply"), readFile(dir + "/plain.ply"));
    const CliRun negative = runCadlod(
        {"simplify", dir + "/assembly.ply", "-o", dir + "/negative.ply", "--reduction", "75", "--shading-weight", "-1"});
    EXPECT_EQ(negative.exitCode, 2) << negative.stderrText;
}

// 0 % asks to remove nothing: the mesh is written as loaded (it was once read as "no
// reduction given" and simplified by the default 90 %). A face target at or above the
// mesh's says why nothing was done.
TEST(CliOutputs, SimplifyAtZeroPercentWritesTheMeshUnsimplified)
{
    const std::string dir = freshDirectory("zero");
    writeDrilledPlatePly(dir + "/plate.ply");
    const CliRun zero = runCadlod({"simplify", dir + "/plate.ply", "-o", dir + "/zero.ply", "--reduction", "0"});
    ASSERT_EQ(zero.exitCode, 0) << zero.stderrText;
    EXPECT_EQ(trianglesOf(dir + "/zero.ply"), 256);
    EXPECT_NE(zero.stderrText.find("written unsimplified"), std::string::npos) << zero.stderrText;
    const CliRun above = runCadlod({"simplify", dir + "/plate.ply", "-o", dir + "/above.ply", "--faces", "1000"});
    ASSERT_EQ(above.exitCode, 0) << above.stderrText;
    EXPECT_EQ(trianglesOf(dir + "/above.ply"), 256);
    EXPECT_NE(above.stderrText.find("nothing to do"), std::string::npos) << above.stderrText;
    EXPECT_EQ(above.stderrText.find("stopped by )"), std::string::npos) << above.stderrText;
}

// Far below what its hole allows, a drilled plate gets there by closing the hole, and the
// command says so; --keep-tunnels keeps the hole and stops above the target.
TEST(CliOutputs, SimplifyClosesATunnelUnlessToldToKeepIt)
{
    const std::string dir = freshDirectory("drilled");
    writeDrilledPlatePly(dir + "/plate.ply");
    ASSERT_EQ(trianglesOf(dir + "/plate.ply"), 256);
    const CliRun closed = runCadlod({"simplify", dir + "/plate.ply", "-o", dir + "/closed.ply", "--faces", "12"});
    ASSERT_EQ(closed.exitCode, 0) << closed.stderrText;
    EXPECT_LE(trianglesOf(dir + "/closed.ply"), 12);
    EXPECT_NE(closed.stderrText.find("closed 1 tunnel"), std::string::npos) << closed.stderrText;
    const CliRun kept =
        runCadlod({"simplify", dir + "/plate.ply", "-o", dir + "/kept.ply", "--faces", "12", "--keep-tunnels"});
    ASSERT_EQ(kept.exitCode, 0) << kept.stderrText;
    EXPECT_GT(trianglesOf(dir + "/kept.ply"), 12);
    EXPECT_EQ(kept.stderrText.find("tunnel"), std::string::npos) << kept.stderrText;
}

// A part of a quarter of a million triangles collapses as two halves side by side first
// (core/collapse_halves.h): on two threads it writes what one thread writes, and says so.
TEST(CliOutputs, SimplifyOfALargePartOnTwoThreadsWritesWhatOneWrites)
{
    const std::string dir = freshDirectory("halves");
    CadBuilder b;
    const RevolveSpec spec = shaftSpecForTriangles(250000);
    revolve(b, shaftProfile(2.0), spec);
    writePly(b, dir + "/shaft.ply");
    std::string bytes[2];
    for (const int threads : {1, 2}) {
        const std::string out = dir + "/out" + std::to_string(threads) + ".ply";
        const CliRun run = runCadlod(
            {"simplify", dir + "/shaft.ply", "-o", out, "--reduction", "90", "--threads", std::to_string(threads)});
        ASSERT_EQ(run.exitCode, 0) << run.stderrText;
        EXPECT_NE(run.stderrText.find("collapses made on two halves side by side"), std::string::npos)
            << run.stderrText;
        bytes[threads - 1] = readFile(out);
    }
    ASSERT_GT(bytes[0].size(), 100000u);
    EXPECT_TRUE(bytes[0] == bytes[1]);
}

TEST(CliOutputs, InfoListsTheLevelsOfAnOpenFlightFile)
{
    const std::string dir = freshDirectory("info");
    ASSERT_EQ(runCadlod({"convert", kDemo, "-o", dir + "/d.flt", "--unit", "mm", "--lod", "50 90", "-q"}).exitCode, 0);
    const CliRun info = runCadlod({"info", dir + "/d.flt"});
    ASSERT_EQ(info.exitCode, 0) << info.stderrText;
    // The housing's 50 % level is held at its nearest point out to where its 90 % level takes
    // over: with no range of its own it is not written, and the file holds level 0 and 90 %.
    EXPECT_NE(info.stdoutText.find("LOD levels   2"), std::string::npos) << info.stdoutText;
    EXPECT_NE(info.stdoutText.find("level 0: 47512 triangles, 8 parts"), std::string::npos) << info.stdoutText;
    EXPECT_NE(info.stdoutText.find("parts        8"), std::string::npos) << info.stdoutText;
}

}  // namespace
}  // namespace cadlod::test
