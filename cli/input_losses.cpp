#include "input_losses.h"

#include "cli_errors.h"

#include <cstdio>

namespace cadlod::cli {
namespace {

int lossCount(const vrml::Diagnostics& findings)
{
    int n = 0;
    for (const auto& [kind, count] : findings.counts())
        if (vrml::losesGeometry(kind))
            n += count;
    return n;
}

std::string countsText(const vrml::Diagnostics& findings, bool losses)
{
    std::string text;
    for (const auto& [kind, count] : findings.counts())
        if (vrml::losesGeometry(kind) == losses)
            text += (text.empty() ? "" : ", ") + std::to_string(count) + " " + kind;
    return text;
}

std::string counted(std::size_t n, const char* one, const char* many)
{
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string partsText(const LoadedMesh& loaded)
{
    if (loaded.placements > 0)
        return counted(loaded.parts, "distinct part", "distinct parts") + " in " +
               counted(loaded.placements, "placement", "placements");
    return counted(loaded.parts, "part", "parts");
}

std::string droppedFacesText(const LoadedMesh& loaded)
{
    const std::size_t degenerate = std::size_t(loaded.degenerateFaces);
    if (loaded.invalidFaces + degenerate == 0)
        return "no faces dropped";
    std::string why;
    if (loaded.invalidFaces > 0)
        why = std::to_string(loaded.invalidFaces) + " invalid";
    if (degenerate > 0)
        why += (why.empty() ? "" : ", ") + std::to_string(degenerate) + " degenerate after welding";
    return counted(loaded.invalidFaces + degenerate, "face", "faces") + " dropped (" + why + ")";
}

// Readers that weld coincident vertices (the simplifier needs the surface connected).
bool welds(InputFormat format) { return format == InputFormat::Vrml || format == InputFormat::OpenFlight; }

}  // namespace

std::string findingLine(const vrml::Diagnostic& d) { return d.where + ": " + d.kind + ": " + d.message; }

std::vector<std::string> findingLines(const vrml::Diagnostics& findings)
{
    std::vector<std::string> lines;
    for (const vrml::Diagnostic& d : findings.kept())
        lines.push_back(findingLine(d));
    return lines;
}

std::vector<std::string> geometryLosses(const vrml::Diagnostics& findings)
{
    std::vector<std::string> lines;
    for (const vrml::Diagnostic& d : findings.kept())
        if (vrml::losesGeometry(d.kind))
            lines.push_back(findingLine(d));
    return lines;
}

void refuseLosses(const vrml::Diagnostics& findings, bool allowPartial)
{
    const int losses = lossCount(findings);
    if (losses == 0 || allowPartial)
        return;
    std::string message = geometryLosses(findings).front() + "\n  geometry lost: the output would be incomplete";
    if (losses > 1)
        message += " (" + std::to_string(losses) + " losses: " + countsText(findings, true) + ")";
    throw InputError(message + "; nothing written (--allow-partial converts what was read)");
}

std::vector<std::string> warningLines(const LoadedMesh& loaded)
{
    std::vector<std::string> lines = findingLines(loaded.findings);
    lines.insert(lines.end(), loaded.notes.begin(), loaded.notes.end());
    return lines;
}

std::size_t warningCount(const LoadedMesh& loaded)
{
    return std::size_t(loaded.findings.total()) + loaded.notes.size();
}

nlohmann::json findingsJson(const LoadedMesh& loaded)
{
    nlohmann::json counts = nlohmann::json::object();
    for (const auto& [kind, count] : loaded.findings.counts())
        counts[kind] = count;
    return {{"complete", lossCount(loaded.findings) == 0},
            {"lost", geometryLosses(loaded.findings)},
            {"findings", counts},
            {"facesDropped", {{"invalid", loaded.invalidFaces}, {"degenerateAfterWelding", loaded.degenerateFaces}}}};
}

void printImportSummary(const LoadedMesh& loaded)
{
    std::string line = partsText(loaded);
    if (welds(loaded.format))
        line += ", " + counted(std::size_t(loaded.mergedVertices), "vertex welded", "vertices welded");
    if (loaded.format == InputFormat::Vrml) {
        line += ", " + droppedFacesText(loaded) + "; input unit " + loaded.unit.describe();
        if (loaded.kicadHeader && !loaded.kicadUnitApplied)
            line += "; KiCad StepUp header found, its 0.1 inch not applied";
    }
    std::fprintf(stderr, "cadlod: import: %s\n", line.c_str());
}

void printFindingsSummary(const LoadedMesh& loaded)
{
    const std::size_t count = warningCount(loaded);
    if (count == 0)
        return;
    std::string kinds = countsText(loaded.findings, false);
    const std::string lost = countsText(loaded.findings, true);
    if (!lost.empty())
        kinds += (kinds.empty() ? "" : ", ") + lost;
    if (!loaded.notes.empty())
        kinds += (kinds.empty() ? "" : ", ") + std::to_string(loaded.notes.size()) + " about the model";
    std::fprintf(stderr, "cadlod: %zu warning%s (%s)\n", count, count == 1 ? "" : "s", kinds.c_str());
    if (!lost.empty())
        std::fprintf(stderr, "cadlod: partial input (--allow-partial): %s; the output lacks that geometry\n",
                     lost.c_str());
}

}  // namespace cadlod::cli
