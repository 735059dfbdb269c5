#include "cli_options.h"

#include "cli_errors.h"

#include <cstdlib>
#include <map>

namespace cadlod::cli {

void addImportOptions(CLI::App& app, ImportArgs& a)
{
    app.add_option("--unit", a.unit,
                   "Unit of the input coordinates: mm, cm, m, in, 0.1in or a factor to metres (scaled to metres)")
        ->capture_default_str();
    app.add_flag("--no-merge", a.noMerge, "Do not weld coincident vertices");
    app.add_option("--merge-tolerance", a.mergeTolerance,
                   "Also merge vertices closer than this (model units, after scaling)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--normals", a.normals, "Vertex normals: keep the file's or recompute from creaseAngle")
        ->check(CLI::IsMember({"keep", "recompute"}))
        ->capture_default_str();
}

void addProtectionOptions(CLI::App& app, ProtectionArgs& a)
{
    app.add_option("--feature-angle", a.featureAngle, "Creases sharper than this (degrees) are features")
        ->check(CLI::Range(0.0, 180.0))
        ->capture_default_str();
    app.add_option("--feature-penalty", a.featurePenalty,
                   "A collapse that breaks a feature costs this many times its quadric cost (0: hard lock)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    app.add_option("--shading-weight", a.shadingWeight,
                   "Price of the faces a collapse turns further than the shading angle from their input faces, per squared "
                   "bbox diagonal of turned area (0: geometry alone)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    app.add_flag("--part-borders", a.partBorders,
                 "Edges between parts are features, also where the parts meet flat and in one colour");
    app.add_flag("--no-colour-borders,--no-color-borders", a.noColorBorders,
                 "Edges between colours (materials) are not features");
    app.add_flag("--no-boundary", a.noBoundary, "Open boundaries get no constraint quadrics");
    app.add_flag("--no-relax", a.noRelax, "Stop early rather than cut non-manifold edges apart, relax the shape guards or remove components");
    app.add_flag("--keep-tunnels", a.keepTunnels,
                 "Never cut and cap a tunnel (a through-hole) whose rim has shrunk to three edges");
    app.add_flag("--no-weight-trials", a.noWeightTrials,
                 "Simplify with the default plane weight only; by default a mesh under 200 000 faces is first "
                 "simplified with three plane weights and once with the crease and boundary constraint planes at a "
                 "quarter (seven runs at 90 % and beyond: the heaviest weight with features at their plain cost, with "
                 "and without their constraint planes, and one keeping smooth joins; where at least half of the faces "
                 "stay, one more without the shape guard), two at a time on two cores, and the one nearest the input "
                 "(distance, shading, slivers, faces turned over) is used, or its run with slivers removed first where "
                 "that costs no distance or shading a viewer sees");
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

double unitScaleOf(const std::string& unit)
{
    static const std::map<std::string, double> named{
        {"mm", 0.001}, {"cm", 0.01}, {"m", 1.0}, {"in", 0.0254}, {"0.1in", 0.00254}};
    if (auto it = named.find(unit); it != named.end())
        return it->second;
    char* end = nullptr;
    const double factor = std::strtod(unit.c_str(), &end);
    if (unit.empty() || *end != '\0' || !(factor > 0))
        throw UsageError("--unit: '" + unit + "' is neither mm, cm, m, in, 0.1in nor a positive factor");
    return factor;
}

ImportSettings importSettings(const ImportArgs& a)
{
    ImportSettings s;
    s.unitScale = unitScaleOf(a.unit);
    s.mergeVertices = !a.noMerge;
    s.mergeTolerance = a.mergeTolerance;
    s.recomputeNormals = a.normals == "recompute";
    return s;
}

void applyProtection(const ProtectionArgs& a, SimplifyParams& p)
{
    p.featureAngle = a.featureAngle;
    p.featurePenalty = a.featurePenalty;
    p.shadingWeight = a.shadingWeight;
    p.keepPartBorders = a.partBorders;
    p.keepColorBorders = !a.noColorBorders;
    p.preserveBoundary = !a.noBoundary;
    p.relaxToReachTarget = !a.noRelax;
    p.closeTunnels = !a.keepTunnels;
    if (a.noWeightTrials)
        p.weightTrialsMaxFaces = 0;
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

nlohmann::json toJson(const ImportArgs& a)
{
    return {{"unit", a.unit},
            {"unitScale", unitScaleOf(a.unit)},
            {"mergeVertices", !a.noMerge},
            {"mergeTolerance", a.mergeTolerance},
            {"normals", a.normals}};
}

nlohmann::json toJson(const ProtectionArgs& a)
{
    return {{"featureAngle", a.featureAngle},   {"featurePenalty", a.featurePenalty},
            {"shadingWeight", a.shadingWeight},
            {"keepPartBorders", a.partBorders}, {"keepColourBorders", !a.noColorBorders},
            {"preserveBoundary", !a.noBoundary}, {"relaxToReachTarget", !a.noRelax},
            {"closeTunnels", !a.keepTunnels}, {"weightTrials", !a.noWeightTrials}};
}

nlohmann::json toJson(const ExportArgs& a)
{
    return {{"units", a.units}, {"drawType", a.drawType}, {"objects", a.objects}, {"records", a.records}};
}

}  // namespace cadlod::cli
