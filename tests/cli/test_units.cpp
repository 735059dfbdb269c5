// Units that cannot go silently wrong: --unit wins over KiCad's header, the unit used and
// why are in the summary and the report, an implausible model size is a warning naming
// the --unit that fixes it, --up-axis; and `cadlod report` refuses a pair that cannot be
// an original and its simplification (different units, unrelated models).
#include "cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace cadlod::test {
namespace {

const std::string kShaft = std::string(CADLOD_SOURCE_DIR) + "/docs/sample/shaft.wrl";

// A box `size` file units on each side, under `header` comments.
std::string boxFile(const std::string& dir, const std::string& name, double size, const std::string& header = "")
{
    const std::string path = dir + "/" + name;
    std::ofstream(path) << "#VRML V2.0 utf8\n" << header << "Shape { geometry Box { size " << size << " " << size
                        << " " << size << " } }\n";
    return path;
}

struct Converted {
    CliRun run;
    nlohmann::json report;
};

Converted convert(const std::string& in, const std::string& dir, std::vector<std::string> options)
{
    std::vector<std::string> args{"convert", in, "-o", dir + "/out.flt", "--report", dir + "/out.json", "--force",
                                  "--lod", "50"};
    args.insert(args.end(), options.begin(), options.end());
    Converted c;
    c.run = runCadlod(args);
    if (c.run.exitCode == 0)
        c.report = nlohmann::json::parse(readFile(dir + "/out.json"));
    return c;
}

const std::string kKicadHeader = "#kicad StepUp wrl exported\n";
const double kKicadSide = 2.0 / 2.54;  // 2 mm in KiCad's 0.1 inch

TEST(CliUnits, KicadHeaderGivesTenthsOfAnInchUnlessUnitIsGiven)
{
    const std::string dir = freshDirectory("units_kicad");
    const std::string part = boxFile(dir, "part.wrl", kKicadSide, kKicadHeader);
    const double twoMillimetreBox = 0.002 * std::sqrt(3.0);

    const Converted detected = convert(part, dir, {});
    ASSERT_EQ(detected.run.exitCode, 0) << detected.run.stderrText;
    const nlohmann::json& i = detected.report.at("options").at("import");
    EXPECT_EQ(i.at("unit"), "0.1in");
    EXPECT_TRUE(i.at("kicadHeader").get<bool>());
    EXPECT_TRUE(i.at("kicadUnitApplied").get<bool>());
    EXPECT_EQ(i.at("unitSource"), "the KiCad StepUp header");
    EXPECT_NEAR(detected.report.at("modelSize").get<double>(), twoMillimetreBox, 1e-6);
    EXPECT_NE(detected.run.stderrText.find("input unit 0.1in (the KiCad StepUp header"), std::string::npos)
        << detected.run.stderrText;

    // --unit 0.1in, the natural choice for a KiCad file, is not applied on top of the header.
    const Converted given = convert(part, dir, {"--unit", "0.1in"});
    ASSERT_EQ(given.run.exitCode, 0) << given.run.stderrText;
    EXPECT_NEAR(given.report.at("modelSize").get<double>(), twoMillimetreBox, 1e-6);
    EXPECT_FALSE(given.report.at("options").at("import").at("kicadUnitApplied").get<bool>());
    EXPECT_TRUE(given.report.at("options").at("import").at("kicadHeader").get<bool>());
    EXPECT_NE(given.run.stderrText.find("its 0.1 inch not applied"), std::string::npos) << given.run.stderrText;

    // The user's unit is the file's unit, whatever the header says.
    const Converted mm = convert(part, dir, {"--unit", "mm"});
    ASSERT_EQ(mm.run.exitCode, 0) << mm.run.stderrText;
    EXPECT_NEAR(mm.report.at("modelSize").get<double>(), twoMillimetreBox / 2.54, 1e-6);

    // --default-unit serves the files that do not say: a KiCad file still does.
    const Converted fallback = convert(part, dir, {"--default-unit", "mm"});
    ASSERT_EQ(fallback.run.exitCode, 0) << fallback.run.stderrText;
    EXPECT_NEAR(fallback.report.at("modelSize").get<double>(), twoMillimetreBox, 1e-6);
    EXPECT_NE(runCadlod({"convert", "--help"}).stdoutText.find("KiCad"), std::string::npos);
    const CliRun info = runCadlod({"info", part});
    EXPECT_NE(info.stdoutText.find("units        0.1in (the KiCad StepUp header"), std::string::npos)
        << info.stdoutText;
}

TEST(CliUnits, AnImplausibleSizeIsAWarningNamingTheUnitThatFixesIt)
{
    const std::string dir = freshDirectory("units_size");
    const Converted big = convert(boxFile(dir, "big.wrl", 180), dir, {});
    ASSERT_EQ(big.run.exitCode, 0) << big.run.stderrText;
    const std::string bigWarning = "the model is 312 m across";
    EXPECT_NE(big.run.stderrText.find(bigWarning), std::string::npos) << big.run.stderrText;
    EXPECT_NE(big.run.stderrText.find("m (the default: no --unit given)"), std::string::npos) << big.run.stderrText;
    EXPECT_NE(big.run.stderrText.find("--unit mm makes it 312 mm across"), std::string::npos) << big.run.stderrText;
    ASSERT_FALSE(big.report.at("warnings").empty());
    EXPECT_NE(big.report.at("warnings").back().get<std::string>().find(bigWarning), std::string::npos);
    EXPECT_GE(big.report.at("warningCount").get<int>(), 1);

    const Converted small = convert(boxFile(dir, "small.wrl", 0.18), dir, {"--unit", "mm"});
    ASSERT_EQ(small.run.exitCode, 0) << small.run.stderrText;
    EXPECT_NE(small.run.stderrText.find("the model is 0.312 mm across"), std::string::npos) << small.run.stderrText;
    EXPECT_NE(small.run.stderrText.find("mm (--unit mm)"), std::string::npos) << small.run.stderrText;
    EXPECT_NE(small.run.stderrText.find("--unit m makes it 312 mm across"), std::string::npos) << small.run.stderrText;

    const Converted fine = convert(boxFile(dir, "fine.wrl", 180), dir, {"--unit", "mm"});
    ASSERT_EQ(fine.run.exitCode, 0) << fine.run.stderrText;
    EXPECT_EQ(fine.run.stderrText.find("across"), std::string::npos) << fine.run.stderrText;
}

// "the model is ... across" of a run's warning, empty when there is none.
std::string sizeWarning(const std::string& text)
{
    const std::size_t at = text.find("the model is ");
    return at == std::string::npos ? std::string() : text.substr(at, text.find(" across", at) - at);
}

TEST(CliUnits, AnInstancedAssemblyOfImplausibleSizeIsAWarningToo)
{
    const std::string dir = freshDirectory("units_assembly_size");
    const std::string input = dir + "/asm.wrl";
    std::ofstream(input) << "#VRML V2.0 utf8\n"
                            "DEF BOARD Group { children [\n"
                            "  Shape { geometry Box { size 30 20 1 } }\n"
                            "  DEF P1 Transform { translation 8 0 1 children DEF PIN Shape { geometry Box { size 1 1 4 } } }\n"
                            "  DEF P2 Transform { translation -8 0 1 children USE PIN }\n"
                            "] }\n"
                            "DEF Board_2 Transform { translation 0 0 40 scale 2 2 2 children USE BOARD }\n"
                            "DEF Board_3 Transform { translation 200 0 0 children USE BOARD }\n";
    const Converted kept = convert(input, dir, {});
    ASSERT_EQ(kept.run.exitCode, 0) << kept.run.stderrText;
    ASSERT_GT(kept.report.at("output").value("placements", 0), 1) << "not converted as an assembly";
    const std::string warning = sizeWarning(kept.run.stderrText);
    ASSERT_FALSE(warning.empty()) << kept.run.stderrText;
    EXPECT_NE(kept.run.stderrText.find("--unit mm makes it"), std::string::npos) << kept.run.stderrText;
    EXPECT_NE(kept.run.stderrText.find("1 warning (1 about the model)"), std::string::npos) << kept.run.stderrText;
    ASSERT_FALSE(kept.report.at("warnings").empty());
    EXPECT_NE(kept.report.at("warnings").back().get<std::string>().find(warning), std::string::npos);
    EXPECT_EQ(kept.report.at("warningCount"), 1);

    // The size of the placed parts is the size of the expanded model.
    const Converted expanded = convert(input, dir, {"--instances", "expand"});
    ASSERT_EQ(expanded.run.exitCode, 0) << expanded.run.stderrText;
    EXPECT_EQ(sizeWarning(expanded.run.stderrText), warning) << expanded.run.stderrText;

    const Converted fine = convert(input, dir, {"--unit", "mm"});
    ASSERT_EQ(fine.run.exitCode, 0) << fine.run.stderrText;
    EXPECT_EQ(fine.run.stderrText.find("across"), std::string::npos) << fine.run.stderrText;
}

// The extent along each axis, from `cadlod info`'s bbox line.
std::array<double, 3> extentOf(const std::string& path)
{
    const CliRun info = runCadlod({"info", path});
    const std::size_t at = info.stdoutText.find("bbox");
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    if (at == std::string::npos ||
        std::sscanf(info.stdoutText.c_str() + at, "bbox (%lf %lf %lf) .. (%lf %lf %lf)", &lo[0], &lo[1], &lo[2],
                    &hi[0], &hi[1], &hi[2]) != 6)
        ADD_FAILURE() << info.stdoutText << info.stderrText;
    return {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
}

TEST(CliUnits, UpAxisYTurnsTheModelToZUpAndIsInTheReport)
{
    const std::string dir = freshDirectory("units_up");
    std::ofstream(dir + "/tall.wrl") << "#VRML V2.0 utf8\nShape { geometry Box { size 1 3 2 } }\n";
    const Converted kept = convert(dir + "/tall.wrl", dir, {});
    ASSERT_EQ(kept.run.exitCode, 0) << kept.run.stderrText;
    EXPECT_EQ(kept.report.at("options").at("import").at("upAxis"), "keep");
    const Converted turned = convert(dir + "/tall.wrl", dir, {"--up-axis", "y"});
    ASSERT_EQ(turned.run.exitCode, 0) << turned.run.stderrText;
    EXPECT_EQ(turned.report.at("options").at("import").at("upAxis"), "y");
    const std::array<double, 3> e = extentOf(dir + "/out.flt");
    EXPECT_NEAR(e[0], 1, 1e-5);
    EXPECT_NEAR(e[1], 2, 1e-5);
    EXPECT_NEAR(e[2], 3, 1e-5);  // +Y of the file is up (+Z)
    ASSERT_EQ(runCadlod({"simplify", dir + "/tall.wrl", "-o", dir + "/tall.ply", "--reduction", "0", "--up-axis",
                         "y", "-q"}).exitCode, 0);
    EXPECT_NEAR(extentOf(dir + "/tall.ply")[2], 3, 1e-5);
    EXPECT_EQ(runCadlod({"convert", dir + "/tall.wrl", "-o", dir + "/x.flt", "--up-axis", "x"}).exitCode, 2);
}

// One input converted in `unit` with the default chain: the report and the model's size.
struct InUnit {
    std::string unit;
    double metres = 1.0;  // of one file unit
    Converted converted;
    std::uintmax_t bytes = 0;
};

InUnit convertIn(const std::string& in, const std::string& dir, const std::string& unit, double metres)
{
    InUnit r{unit, metres, {}, 0};
    const std::string out = dir + "/" + unit + ".flt", report = dir + "/" + unit + ".json";
    r.converted.run = runCadlod({"convert", in, "-o", out, "--report", report, "--unit", unit, "-q"});
    if (r.converted.run.exitCode == 0) {
        r.converted.report = nlohmann::json::parse(readFile(report));
        r.bytes = readFile(out).size();
    }
    return r;
}

// A length of the report in file units.
double inFileUnits(const nlohmann::json& length, const InUnit& r) { return length.get<double>() / r.metres; }

void expectSameLevels(const nlohmann::json& levels, const nlohmann::json& reference, const InUnit& r,
                      const InUnit& ref)
{
    ASSERT_EQ(levels.size(), reference.size()) << r.unit << " against " << ref.unit;
    for (std::size_t k = 0; k < levels.size(); ++k) {
        const nlohmann::json &l = levels[k], &e = reference[k];
        SCOPED_TRACE(r.unit + " level " + std::to_string(k));
        EXPECT_EQ(l.at("faces"), e.at("faces"));
        const double error = inFileUnits(e.at("hausdorffMax"), ref);
        EXPECT_NEAR(inFileUnits(l.at("hausdorffMax"), r), error, 1e-9 * error + 1e-12);
        const double out = inFileUnits(e.at("switchOut"), ref);
        EXPECT_NEAR(inFileUnits(l.at("switchOut"), r), out, 1e-9 * out);
        if (e.at("switchIn").is_string())
            EXPECT_EQ(l.at("switchIn"), e.at("switchIn"));
        else
            EXPECT_NEAR(inFileUnits(l.at("switchIn"), r), inFileUnits(e.at("switchIn"), ref),
                        1e-9 * inFileUnits(e.at("switchIn"), ref));
    }
}

// The file written in r's unit: as many bytes as in ref's, its extent in proportion.
void expectTheSameFileInProportion(const std::string& dir, const InUnit& r, const InUnit& ref)
{
    EXPECT_EQ(r.bytes, ref.bytes) << r.unit;
    const std::array<double, 3> e = extentOf(dir + "/" + r.unit + ".flt"), m = extentOf(dir + "/" + ref.unit + ".flt");
    for (int axis = 0; axis < 3; ++axis)
        EXPECT_NEAR(e[axis] / r.metres, m[axis] / ref.metres, 1e-4 * m[axis] / ref.metres) << r.unit;
}

const std::vector<std::pair<std::string, double>> kThreeUnits{{"mm", 0.001}, {"0.1in", 0.00254}, {"m", 1.0}};

// Scaling the input must not change the simplification: the shaft in millimetres, in tenths
// of an inch and in metres gives the same levels of the same triangles, its lengths in
// proportion, and files of the same size.
TEST(CliUnits, TheUnitScalesTheLevelsAndChangesNothingElse)
{
    const std::string dir = freshDirectory("units_three_scales");
    std::vector<InUnit> runs;
    for (const auto& [unit, metres] : kThreeUnits) {
        runs.push_back(convertIn(kShaft, dir, unit, metres));
        ASSERT_EQ(runs.back().converted.run.exitCode, 0) << runs.back().converted.run.stderrText;
    }
    const InUnit& mm = runs.front();
    ASSERT_GT(mm.converted.report.at("levels").size(), 3u);
    for (const InUnit& r : runs) {
        expectSameLevels(r.converted.report.at("levels"), mm.converted.report.at("levels"), r, mm);
        EXPECT_NEAR(inFileUnits(r.converted.report.at("modelSize"), r), inFileUnits(mm.converted.report.at("modelSize"), mm),
                    1e-6);
        expectTheSameFileInProportion(dir, r, mm);
    }
}

// The same for an assembly that places one part three times: the part's chain, the
// placements and the clusters' proxies.
TEST(CliUnits, TheUnitScalesAnAssemblyAndChangesNothingElse)
{
    const std::string dir = freshDirectory("units_three_scales_assembly");
    std::ofstream(dir + "/rack.wrl") << "#VRML V2.0 utf8\n"
                                     << "Transform { translation 0 0 0 children Inline { url \"" << kShaft << "\" } }\n"
                                     << "Transform { translation 40 0 0 children Inline { url \"" << kShaft << "\" } }\n"
                                     << "Transform { translation 0 70 5 rotation 0 0 1 1.2 children Inline { url \""
                                     << kShaft << "\" } }\n";
    std::vector<InUnit> runs;
    for (const auto& [unit, metres] : kThreeUnits) {
        runs.push_back(convertIn(dir + "/rack.wrl", dir, unit, metres));
        ASSERT_EQ(runs.back().converted.run.exitCode, 0) << runs.back().converted.run.stderrText;
    }
    const InUnit& mm = runs.front();
    ASSERT_EQ(mm.converted.report.at("parts").size(), 1u);
    ASSERT_EQ(mm.converted.report.at("output").at("placements"), 3);
    for (const InUnit& r : runs) {
        const nlohmann::json& part = r.converted.report.at("parts").at(0);
        expectSameLevels(part.at("levels"), mm.converted.report.at("parts").at(0).at("levels"), r, mm);
        EXPECT_EQ(r.converted.report.at("hlod"), mm.converted.report.at("hlod")) << r.unit;
        expectTheSameFileInProportion(dir, r, mm);
    }
}

TEST(CliUnits, ReportRefusesAPairInDifferentUnitsOrUnrelated)
{
    const std::string dir = freshDirectory("units_report");
    ASSERT_EQ(runCadlod({"convert", kShaft, "-o", dir + "/shaft.flt", "--unit", "mm", "--lod", "90", "-q"}).exitCode,
              0);
    const CliRun refused = runCadlod({"report", kShaft, dir + "/shaft.flt"});
    EXPECT_EQ(refused.exitCode, 1) << refused.stderrText;
    EXPECT_NE(refused.stderrText.find("cannot be a simplification of"), std::string::npos) << refused.stderrText;
    EXPECT_NE(refused.stderrText.find("1000x smaller"), std::string::npos) << refused.stderrText;
    EXPECT_NE(refused.stderrText.find("a different unit"), std::string::npos) << refused.stderrText;
    EXPECT_TRUE(refused.stdoutText.empty()) << refused.stdoutText;

    const CliRun measured = runCadlod({"report", kShaft, dir + "/shaft.flt", "--unit", "mm"});
    EXPECT_EQ(measured.exitCode, 0) << measured.stderrText;
    EXPECT_NE(measured.stdoutText.find("hausdorff"), std::string::npos) << measured.stdoutText;

    const CliRun unrelated = runCadlod({"report", kShaft, boxFile(dir, "connector.wrl", 0.02), "--unit", "mm"});
    EXPECT_EQ(unrelated.exitCode, 1) << unrelated.stderrText;
    EXPECT_NE(unrelated.stderrText.find("smaller"), std::string::npos) << unrelated.stderrText;
}

}  // namespace
}  // namespace cadlod::test
