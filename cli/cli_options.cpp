#include "cli_options.h"

#include "cli_errors.h"
#include "unit_choice.h"

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <map>
#include <vector>

namespace cadlod::cli {
namespace {

// A CLI11 check: empty when `unit` is one, else why not.
std::string checkUnit(const std::string& unit, const std::string& option)
{
    try {
        unitScaleOf(unit, option);
        return {};
    } catch (const UsageError& e) {
        return e.what();
    }
}

}  // namespace

void addImportOptions(CLI::App& app, ImportArgs& a)
{
    app.add_option("--unit", a.unit,
                   "Unit of the input coordinates: mm, cm, m, in, 0.1in or a factor to metres (scaled to metres); "
                   "wins over a KiCad StepUp header (0.1 inch)")
        ->check([](const std::string& u) { return checkUnit(u, "--unit"); });
    app.add_option("--default-unit", a.defaultUnit,
                   "Unit when neither --unit nor the file says (KiCad StepUp files say 0.1 inch)")
        ->check([](const std::string& u) { return checkUnit(u, "--default-unit"); })
        ->each([&a](const std::string&) { a.defaultUnitGiven = true; })
        ->capture_default_str();
    app.add_option("--up-axis", a.upAxis, "keep: as in the file (CAD exports are Z-up); y: +Y up (VRML's convention), "
                                          "turned to OpenFlight's +Z")
        ->check(CLI::IsMember({"keep", "y"}))
        ->capture_default_str();
    app.add_flag("--allow-partial", a.allowPartial,
                 "Convert what was read of an input that lost geometry (syntax error, missing Inline, ...); "
                 "the report names what was lost");
    app.add_flag("--no-merge", a.noMerge, "Do not weld coincident vertices");
    app.add_option("--merge-tolerance", a.mergeTolerance,
                   "Also merge vertices closer than this (model units, after scaling)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--normals", a.normals, "Vertex normals: keep the file's or recompute from creaseAngle")
        ->check(CLI::IsMember({"keep", "recompute"}))
        ->capture_default_str();
}

namespace {

// The simplifier's rows `cadlod` offers, in the order `--help` lists them.
std::vector<std::size_t> cliRows()
{
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < kSimplifyParameterCount; ++i)
        if (kSimplifyParameters[i].cli.form != CliForm::None)
            rows.push_back(i);
    std::sort(rows.begin(), rows.end(), [](std::size_t a, std::size_t b) {
        return kSimplifyParameters[a].cli.position < kSimplifyParameters[b].cli.position;
    });
    return rows;
}

CLI::Validator validatorOf(const ParameterRange& r)
{
    if (r.min == 0 && !r.minExcluded && r.max == std::numeric_limits<double>::infinity())
        return CLI::NonNegativeNumber;
    return CLI::Range(r.min, r.max);
}

}  // namespace

ProtectionArgs::ProtectionArgs()
{
    for (std::size_t i = 0; i < kSimplifyParameterCount; ++i)
        values[i] = defaultOf(kSimplifyParameters[i]);
}

void addProtectionOptions(CLI::App& app, ProtectionArgs& a)
{
    for (const std::size_t i : cliRows()) {
        const CliSpec& cli = kSimplifyParameters[i].cli;
        if (cli.form == CliForm::Option)
            app.add_option(cli.names, a.values[i], cli.help)
                ->check(validatorOf(kSimplifyParameters[i].range))
                ->capture_default_str();
        else
            app.add_flag(cli.names, a.flags[i], cli.help);
    }
}

void addExportOptions(CLI::App& app, ExportArgs& a)
{
    app.add_option("--units", a.units, "Units written in the OpenFlight header (coordinates are not scaled)")
        ->check(CLI::IsMember({"meters", "kilometers", "feet", "inches", "nautical-miles"}))
        ->capture_default_str();
    app.add_option("--draw-type", a.drawType, "OpenFlight draw type: single-sided (back faces culled) or two-sided")
        ->check(CLI::IsMember({"single", "two"}))
        ->capture_default_str();
    app.add_option("--objects", a.objects, "One OpenFlight Object per part or per level")
        ->check(CLI::IsMember({"part", "level"}))
        ->capture_default_str();
    app.add_option("--records", a.records, "Geometry as Mesh records (compact) or Face records (old tools)")
        ->check(CLI::IsMember({"mesh", "face"}))
        ->capture_default_str();
}

void addCommonOptions(CLI::App& app, CommonArgs& a)
{
    app.add_option("--threads", a.threads, "Worker threads (0: all cores)")->check(CLI::NonNegativeNumber);
    app.add_flag("--force", a.force, "Overwrite an existing output");
    app.add_flag("-q,--quiet", a.quiet, "No progress on stderr");
}

ImportSettings importSettings(const ImportArgs& a)
{
    ImportSettings s;
    s.unit = a.unit;
    s.defaultUnit = a.defaultUnit;
    s.defaultUnitGiven = a.defaultUnitGiven;
    s.unitScale = unitScaleOf(a.unit.empty() ? a.defaultUnit : a.unit, a.unit.empty() ? "--default-unit" : "--unit");
    s.yUpToZUp = a.upAxis == "y";
    s.allowPartial = a.allowPartial;
    s.mergeVertices = !a.noMerge;
    s.mergeTolerance = a.mergeTolerance;
    s.recomputeNormals = a.normals == "recompute";
    return s;
}

void applyProtection(const ProtectionArgs& a, SimplifyParams& p)
{
    for (const std::size_t i : cliRows()) {
        const SimplifyParameter& row = kSimplifyParameters[i];
        if (row.cli.form == CliForm::Option)
            row.field.set(p, a.values[i]);
        else if (a.flags[i])
            row.field.set(p, row.cli.form == CliForm::FlagOn ? 1.0 : 0.0);
        else
            row.field.set(p, defaultOf(row));
    }
}

SaveSettings saveSettings(const ExportArgs& a)
{
    static const std::map<std::string, flt::Units> units{{"meters", flt::Units::Meters},
                                                         {"kilometers", flt::Units::Kilometers},
                                                         {"feet", flt::Units::Feet},
                                                         {"inches", flt::Units::Inches},
                                                         {"nautical-miles", flt::Units::NauticalMiles}};
    SaveSettings s;
    s.units = units.at(a.units);
    s.flt.drawType = a.drawType == "two" ? flt::DrawType::TwoSided : flt::DrawType::SingleSided;
    s.flt.objects = a.objects == "level" ? flt::ObjectGrouping::PerLevel : flt::ObjectGrouping::PerPart;
    s.flt.geometry = a.records == "face" ? flt::GeometryRecords::Faces : flt::GeometryRecords::Meshes;
    return s;
}

nlohmann::json toJson(const ImportArgs& a, const LoadedMesh& loaded)
{
    return {{"unit", loaded.unit.unit},
            {"unitScale", loaded.unit.scale},
            {"unitSource", loaded.unit.source},
            {"defaultUnit", a.defaultUnit},
            {"kicadHeader", loaded.kicadHeader},
            {"kicadUnitApplied", loaded.kicadUnitApplied},
            {"upAxis", a.upAxis},
            {"allowPartial", a.allowPartial},
            {"mergeVertices", !a.noMerge},
            {"mergeTolerance", a.mergeTolerance},
            {"normals", a.normals}};
}

nlohmann::json toJson(const ProtectionArgs& a)
{
    SimplifyParams p;
    applyProtection(a, p);
    nlohmann::json j = nlohmann::json::object();
    for (const SimplifyParameter& row : kSimplifyParameters) {
        if (!row.jsonKey)
            continue;
        const double value = row.field.get(p);
        switch (row.field.kind) {
        case ParameterKind::Bool:
            j[row.jsonKey] = value != 0;
            break;
        case ParameterKind::Int:
            j[row.jsonKey] = int(value);
            break;
        case ParameterKind::Float:
            j[row.jsonKey] = value;
            break;
        }
    }
    return j;
}

nlohmann::json toJson(const ExportArgs& a)
{
    return {{"units", a.units}, {"drawType", a.drawType}, {"objects", a.objects}, {"records", a.records}};
}

}  // namespace cadlod::cli
