// JSON for the reports (--report, report --json): LOD levels with their errors in model
// units, % of the diagonal and pixels at switch-in, compactness and what was relaxed.
#pragma once
#include "lod/lod_builder.h"
#include "lod/lod_chain.h"
#include "measure/simplification_report.h"

#include <nlohmann/json.hpp>
#include <string>

namespace cadlod::cli {

nlohmann::json levelsJson(const LodSetResult& r, const ViewParams& view);
nlohmann::json compactnessJson(const CompactnessStats& c);
nlohmann::json simplifyStatsJson(const SimplifyStats& s);
nlohmann::json comparisonJson(const SimplificationReport& r);

// Writes `report` (indented) to `path` atomically; throws InputError.
void writeJsonFile(const std::string& path, const nlohmann::json& report);
// Writes `report` (indented) to `file` as it is (e.g. an OutputSet's temporary).
bool writeJsonTo(const std::string& file, const nlohmann::json& report);

}  // namespace cadlod::cli
