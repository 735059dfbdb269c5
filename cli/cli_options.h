// The options several commands share, declared once on a CLI11 (sub)command: import
// (units, welding, normals), simplification (stop criteria, protection) and OpenFlight
// export (units, draw type, objects, records).
#pragma once
#include "mesh_files.h"
#include "simplify/parameter_table.h"

#include <CLI/CLI.hpp>
#include <array>
#include <nlohmann/json.hpp>
#include <string>

namespace cadlod::cli {

struct ImportArgs {
    std::string unit;                 // mm|cm|m|in|0.1in|<factor>; empty: not given
    std::string defaultUnit = "m";    // the unit when neither --unit nor the file says
    bool defaultUnitGiven = false;
    std::string upAxis = "keep";      // keep|y
    bool allowPartial = false;        // convert what was read of an input that lost geometry
    bool noMerge = false;
    float mergeTolerance = 0.0f;
    std::string normals = "keep";  // keep|recompute
};

// The simplifier's parameters offered as options and flags (simplify/parameter_table.h's
// CLI column), by table row.
struct ProtectionArgs {
    ProtectionArgs();
    std::array<double, kSimplifyParameterCount> values{};  // the options' values: the simplifier's defaults unless given
    std::array<bool, kSimplifyParameterCount> flags{};     // the flags given
};

struct ExportArgs {
    std::string units = "meters";       // meters|kilometers|feet|inches|nautical-miles
    std::string drawType = "single";    // single|two
    std::string objects = "part";       // part|level
    std::string records = "mesh";       // mesh|face
};

struct CommonArgs {
    int threads = 0;  // 0: all cores
    bool force = false;
    bool quiet = false;
};

void addImportOptions(CLI::App& app, ImportArgs& a);
void addProtectionOptions(CLI::App& app, ProtectionArgs& a);
void addExportOptions(CLI::App& app, ExportArgs& a);
void addCommonOptions(CLI::App& app, CommonArgs& a);

// Throws UsageError for a unit that is neither a name nor a positive factor.
ImportSettings importSettings(const ImportArgs& a);
void applyProtection(const ProtectionArgs& a, SimplifyParams& p);
SaveSettings saveSettings(const ExportArgs& a);

// The import options, with what loading found: the unit used and why, KiCad's header.
nlohmann::json toJson(const ImportArgs& a, const LoadedMesh& loaded);
nlohmann::json toJson(const ProtectionArgs& a);
nlohmann::json toJson(const ExportArgs& a);

}  // namespace cadlod::cli
