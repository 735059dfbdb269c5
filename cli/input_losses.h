// What the command line makes of the VRML importer's findings: an input that lost geometry
// (vrml::losesGeometry) fails, unless --allow-partial; every finding is a warning, counted
// in the summary and in the JSON report.
#pragma once
#include "mesh_files.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace cadlod::cli {

// "file:line:col: kind: message".
std::string findingLine(const vrml::Diagnostic& d);

// The kept findings, as findingLine()s.
std::vector<std::string> findingLines(const vrml::Diagnostics& findings);

// The kept findings that lost geometry, as findingLine()s.
std::vector<std::string> geometryLosses(const vrml::Diagnostics& findings);

// Throws InputError naming the first loss and the count, unless `allowPartial`.
void refuseLosses(const vrml::Diagnostics& findings, bool allowPartial);

// The importer's kept findings and the command's notes, one line each; and their count
// (findings beyond those kept per kind included).
std::vector<std::string> warningLines(const LoadedMesh& loaded);
std::size_t warningCount(const LoadedMesh& loaded);

// The input's findings for the report: {"complete", "lost": [lines], "findings": {kind: count},
// "facesDropped": {"invalid", "degenerateAfterWelding"}}.
nlohmann::json findingsJson(const LoadedMesh& loaded);

// On stderr, one line of what the importer did: the parts (and `placements` of an
// assembly), the vertices welded and the faces dropped, the unit and why, KiCad's header.
void printImportSummary(const LoadedMesh& loaded);

// On stderr: the number of warnings by kind and, for a partial input, what was lost.
void printFindingsSummary(const LoadedMesh& loaded);

}  // namespace cadlod::cli
