// cadlod convert IN -o OUT.flt: import, LOD chain (screen-space, default) or the paper's
// percentage list, one OpenFlight LOD model, optional JSON report.
#include "cli_errors.h"
#include "cli_options.h"
#include "input_losses.h"
#include "commands.h"
#include "mesh_files.h"
#include "note_lines.h"
#include "output_file.h"
#include "progress_bar.h"
#include "report_json.h"

#include "assembly/assembly_convert.h"
#include "assembly/hierarchical_lod.h"
#include "assembly/level_store.h"
#include "assembly/part_chunks.h"
#include "lod/lod_builder.h"
#include "lod/lod_chain.h"
#include "lod/scale_lengths.h"
#include "openflight/flt_writer.h"
#include "openflight/local_origin.h"
#include "openflight/scale_lengths.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <deque>
#include <memory>
#include <utility>

namespace cadlod::cli {
namespace {

struct ConvertArgs {
    std::string input, output, report;
    std::string lod = "auto";
    std::string instances = "keep";
    std::string hlod = "auto";
    std::size_t clusterParts = 0;   // 0: the default of the --hlod mode
    std::size_t clusterFanout = 0;
    double pixelError = 1.0, fov = 45.0, viewport = 1080.0, distanceRatio = 2.0, cullPixels = 0.0,
           proxyPixels = 8.0;
    bool fromOriginal = false;
    std::size_t samples = 0;
    ImportArgs import;
    ProtectionArgs protection;
    ExportArgs exporting;
    CommonArgs common;
};

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string baseName(const std::string& path)
{
    std::string name = path.substr(path.find_last_of('/') + 1);
    return name.substr(0, name.find('.'));
}

ViewParams viewOf(const ConvertArgs& a)
{
    ViewParams v;
    v.fovYDegrees = a.fov;
    v.viewportHeightPx = a.viewport;
    v.pixelThreshold = a.pixelError;
    return v;
}

// --hlod auto, instances or calls: the placements in clusters with merged proxies, when the
// chain plans the levels (a level list has no error to switch a proxy by) and there are parts
// to cluster.
bool hierarchical(const ConvertArgs& a) { return a.hlod != "off" && a.lod == "auto"; }

// What --hlod comes to for a model of `placements`: instances or the fewest draw calls
// (assembly/hierarchical_lod.h, ClusterMode).
ClusterMode clusterMode(const ConvertArgs& a, std::size_t placements)
{
    const ClusterMode asked = a.hlod == "calls"       ? ClusterMode::FewestCalls
                              : a.hlod == "instances" ? ClusterMode::Instances
                                                      : ClusterMode::Auto;
    return resolvedMode(asked, placements);
}

const char* clusterModeName(ClusterMode mode) { return mode == ClusterMode::FewestCalls ? "calls" : "instances"; }

ClusterTreeOptions clusterTree(const ConvertArgs& a, std::size_t placements)
{
    ClusterTreeOptions tree = hierarchyOptionsOf(clusterMode(a, placements)).tree;
    if (a.clusterParts > 0)
        tree.leafItems = a.clusterParts;
    if (a.clusterFanout > 0)
        tree.fanout = a.clusterFanout;
    return tree;
}

// The shares of the one progress bar: reading is quick beside the LOD chain, writing quicker.
constexpr int kReadingEnd = 10, kWritingStart = 95;
// An assembly's parts fill this much of the LOD chain's share when proxies follow them.
constexpr int kPartsShareBeforeProxies = 70;

// The parts and proxies of an assembly on the one progress bar.
ProgressSpans barSpans()
{
    ProgressSpans spans;
    spans.begin = [](int from, int to, const std::string& label) { progress::beginSpan(from, to, label); };
    spans.end = [] { progress::endSpan(); };
    spans.step = progress::callback;
    return spans;
}

// `lengthScale` turns the mesh's lengths into metres, for the progress to name distances in.
// `progress`: null where the chain runs beside others (an assembly's parts and proxies).
LodSetResult buildLevels(const ConvertArgs& a, double lengthScale, CoreMesh& original, LevelStore& store,
                         vcg::CallBackPos* progress, const ProxyRange& range = {})
{
    const auto newLevel = [&](int) -> CoreMesh& { return store.add(); };
    if (a.lod == "auto") {
        LodChainOptions o;
        o.view = viewOf(a);
        o.distanceRatio = a.distanceRatio;
        o.proxyPixels = a.proxyPixels;
        o.cullPixels = a.cullPixels;
        o.hausdorffSamples = a.samples;
        applyProtection(a.protection, o.simplify);
        o.runTogether = runOnWorkers;
        o.distanceUnit = "m";
        o.distanceScale = lengthScale;
        o = proxyChainOptions(o, original.fn, range);
        CoreMesh scratch;
        return buildLodChain<CoreMesh>(original, scratch, o, newLevel, progress);
    }
    LodSetOptions o;
    o.levels = a.lod;
    o.view = viewOf(a);
    o.fromOriginal = a.fromOriginal;
    o.runTogether = runOnWorkers;
    o.hausdorffSamples = a.samples;
    applyProtection(a.protection, o.simplify);
    return buildLodSet<CoreMesh>(original, o, newLevel, progress);
}

nlohmann::json optionsJson(const ConvertArgs& a, const LoadedMesh& loaded)
{
    const ClusterTreeOptions tree = clusterTree(a, loaded.placements);
    return {{"lod", a.lod},
            {"instances", a.instances},
            {"hlod", a.hlod},
            {"clusterParts", tree.leafItems},
            {"clusterFanout", tree.fanout},
            {"clusterLargeShare", tree.largeShare},
            {"pixelError", a.pixelError},
            {"fovY", a.fov},
            {"viewport", a.viewport},
            {"distanceRatio", a.distanceRatio},
            {"cullPixels", a.cullPixels},
            {"proxyPixels", a.proxyPixels},
            {"fromOriginal", a.fromOriginal},
            {"samples", a.samples},
            {"import", toJson(a.import, loaded)},
            {"simplify", toJson(a.protection)},
            {"export", toJson(a.exporting)}};
}

nlohmann::json reportJson(const ConvertArgs& a, const LoadedMesh& loaded, const LodSetResult& result,
                          const flt::WriteStats& written, std::size_t skipped, const nlohmann::json& timings)
{
    nlohmann::json input{{"path", a.input}, {"format", formatName(loaded.format)}, {"parts", loaded.parts},
                         {"faces", result.levels.front().faces}, {"mergedVertices", loaded.mergedVertices}};
    input.update(findingsJson(loaded));
    std::vector<std::string> warnings = warningLines(loaded);
    warnings.insert(warnings.end(), result.warnings.begin(), result.warnings.end());
    return {{"command", "convert"},
            {"input", input},
            {"output", {{"path", a.output}, {"bytes", written.bytes}, {"triangles", written.triangles},
                        {"objects", written.objects}, {"lodNodes", written.lodNodes},
                        {"skippedDegenerateFaces", skipped}}},
            {"options", optionsJson(a, loaded)},
            {"modelSize", result.modelSize},
            {"levels", levelsJson(result, viewOf(a))},
            {"droppedLevels", result.droppedLevels},
            {"warnings", warnings},
            {"warningCount", warningCount(loaded) + result.warnings.size()},
            {"timings", timings}};
}

// The model's bytes go to the OutputSet's temporary, renamed into place with the report.
void writeFlt(OutputSet& outputs, const std::string& path, const flt::LodModel& model,
              const flt::WriteOptions& options, flt::WriteStats& written)
{
    std::vector<std::uint8_t> bytes;
    std::string error;
    if (!flt::writeOpenFlight(model, options, bytes, error, &written))
        throw InputError(path + ": " + error);
    outputs.write(path, [&](const std::string& temporary) { return writeBytesTo(temporary, bytes); });
}

// One format for every length of the summary: four significant digits, never an exponent
// beside a fixed-point number.
std::string lengthText(double metres) { return metresText(metres, 4); }

// The chain's levels as a table, and its notes.
void printLevels(const LodSetResult& r, const flt::WriteStats& written, const std::string& output)
{
    std::fprintf(stderr, "cadlod: %s: %zu levels, %zu triangles, %zu bytes (model size %s)\n", output.c_str(),
                 r.levels.size(), written.triangles, written.bytes, lengthText(r.modelSize).c_str());
    std::fprintf(stderr, "level  triangles  hausdorff max     (%% diag)  switch out .. in\n");
    for (const LodLevel& l : r.levels)
        std::fprintf(stderr, "%5d  %9d  %-16s  %8.4f%%  %s .. %s\n", l.level, l.faces, lengthText(l.hausdorffMax).c_str(),
                     r.modelSize > 0 ? 100.0 * l.hausdorffMax / r.modelSize : 0.0, lengthText(l.switchOut).c_str(),
                     l.switchIn >= kNeverCulled ? "never" : lengthText(l.switchIn).c_str());
    printFolded("note", r.warnings);
}

void printSummary(const LodSetResult& r, const flt::WriteStats& written, const std::string& output,
                  const LoadedMesh& loaded)
{
    printLevels(r, written, output);
    printImportSummary(loaded);
    printFindingsSummary(loaded);
}

void printAssemblySummary(const AssemblyConversion& c, const flt::InstancedWriteStats& written,
                          const std::string& output)
{
    std::fprintf(stderr, "cadlod: %s: %zu placements of %zu distinct parts (%zu shared), %zu bytes\n", output.c_str(),
                 written.placements, c.parts.size(), written.instanceDefinitions, written.bytes);
    std::fprintf(stderr, "cadlod: level 0 draws %zu triangles; %zu distinct triangles written in all levels\n",
                 c.model.placedTriangles(), written.triangles);
    if (c.stretchedPlacements > 0)
        std::fprintf(stderr, "cadlod: %zu placements scale their part unevenly: each such part is simplified "
                             "as stretched as it is seen (its name ends in \"stretched\")\n",
                     c.stretchedPlacements);
    std::fprintf(stderr, "part                              placements  triangles  levels\n");
    for (const PartChain& p : c.parts)
        std::fprintf(stderr, "%-32.32s  %10zu  %9d  %6zu\n", p.name.c_str(), p.placements, p.triangles,
                     p.result.levels.size());
    std::vector<std::string> notes;
    for (const PartChain& p : c.parts)
        for (const std::string& w : p.result.warnings)
            notes.push_back(p.name + ": " + w);
    printFolded("note", notes);
}

// A model of one placed part (a file of one part, kept as placed once for --hlod): it reads
// as a part, its levels shown rather than a table of parts.
bool onePlacedPart(const AssemblyConversion& c) { return c.model.placements.size() == 1; }

// What the importer did to an assembly: the file's findings, and each distinct part welded
// as a whole model is.
LoadedMesh assemblyImport(const LoadedMesh& loaded, const AssemblyConversion& c)
{
    LoadedMesh whole = loaded;
    whole.parts = c.parts.size();
    whole.placements = c.model.placements.size();
    for (const PartChain& p : c.parts) {
        whole.mergedVertices += p.weldedVertices;
        whole.degenerateFaces += p.degenerateFaces;
    }
    return whole;
}

nlohmann::json partsJson(const AssemblyConversion& c, const ViewParams& view)
{
    nlohmann::json parts = nlohmann::json::array();
    for (const PartChain& p : c.parts)
        parts.push_back({{"name", p.name}, {"placements", p.placements}, {"faces", p.triangles},
                         {"modelSize", p.result.modelSize}, {"levels", levelsJson(p.result, view)},
                         {"warnings", p.result.warnings}});
    return parts;
}

nlohmann::json assemblyReportJson(const ConvertArgs& a, const AssemblyConversion& c,
                                  const flt::InstancedWriteStats& written, const LoadedMesh& loaded,
                                  double importSeconds, double lodSeconds, double writeSeconds, double totalSeconds)
{
    nlohmann::json input{{"path", a.input}, {"format", "VRML"}, {"parts", c.parts.size()},
                         {"placements", written.placements}, {"faces", c.model.placedTriangles()},
                         {"mergedVertices", loaded.mergedVertices}, {"stretchedPlacements", c.stretchedPlacements}};
    input.update(findingsJson(loaded));
    nlohmann::json report{
        {"command", "convert"},
        {"input", input},
        {"output", {{"path", a.output}, {"bytes", written.bytes}, {"triangles", written.triangles},
                    {"objects", written.objects}, {"lodNodes", written.lodNodes}, {"placements", written.placements},
                    {"instanceDefinitions", written.instanceDefinitions},
                    {"instanceReferences", written.instanceReferences},
                    {"skippedDegenerateFaces", c.skippedFaces}}},
        {"options", optionsJson(a, loaded)},
        {"parts", partsJson(c, viewOf(a))},
        {"warnings", warningLines(loaded)},
        {"warningCount", warningCount(loaded)},
        {"timings", {{"importSeconds", importSeconds}, {"lodSeconds", lodSeconds}, {"writeSeconds", writeSeconds},
                     {"totalSeconds", totalSeconds}}}};
    if (onePlacedPart(c)) {
        report["modelSize"] = c.parts.front().result.modelSize;
        report["levels"] = levelsJson(c.parts.front().result, viewOf(a));
    }
    return report;
}

// The placements in clusters with proxies (a model of one placement: none, its levels made
// one drawable each as an assembly's are).
HierarchyStats clusterPlacements(const ConvertArgs& a, AssemblyConversion& c, const ImportSettings& importing,
                                 double lengthScale)
{
    if (!hierarchical(a))
        return {};
    const std::size_t placements = c.model.placements.size();
    HierarchyOptions options = hierarchyOptionsOf(clusterMode(a, placements));
    options.tree = clusterTree(a, placements);
    options.view = viewOf(a);
    const auto chain = [&](CoreMesh& merged, LevelStore& store, const ProxyRange& range, vcg::CallBackPos* progress) {
        return buildLevels(a, lengthScale, merged, store, progress, range);
    };
    return buildHierarchy(c, options, weldingOf(importing), chain, barSpans());
}

// The distinct parts drawn in chunks near the viewer, and their chunks at every depth.
std::pair<std::size_t, std::size_t> chunksOf(const flt::InstancedModel& model)
{
    std::pair<std::size_t, std::size_t> n{0, 0};
    for (const flt::PartDefinition& definition : model.definitions)
        if (!definition.chunks.empty()) {
            ++n.first;
            n.second += chunkCount(definition.chunks);
        }
    return n;
}

nlohmann::json hierarchyJson(const ConvertArgs& a, const flt::InstancedModel& model, const HierarchyStats& h)
{
    const std::size_t placements = model.placements.size();
    const ClusterTreeOptions tree = clusterTree(a, placements);
    const auto chunks = chunksOf(model);
    return {{"mode", a.hlod},
            {"tree", clusterModeName(clusterMode(a, placements))},
            {"clusters", h.clusters},
            {"withProxies", h.proxied},
            {"proxyLevels", h.proxyLevels},
            {"proxyShapes", h.proxyShapes},
            {"proxyTriangles", h.proxyTriangles},
            {"mergedTriangles", h.inputTriangles},
            {"copiedClusters", h.copied},
            {"turnedCopies", h.turned},
            {"mirroredCopies", h.mirrored},
            {"clusterParts", tree.leafItems},
            {"fanout", tree.fanout},
            {"largeShare", tree.largeShare},
            {"chunkedParts", chunks.first},
            {"chunks", chunks.second}};
}

// What the hierarchy is for a model of one placed part: its held levels, and its chunks.
void printOnePlacementSummary(const ConvertArgs& a, const AssemblyConversion& c)
{
    const flt::PartDefinition& part = c.model.definitions.at(c.model.placements.front().definition);
    std::fprintf(stderr, "cadlod: hlod %s: one placed part, no clusters; its levels switch where they hold at its "
                         "nearest point", a.hlod.c_str());
    if (!part.chunks.empty())
        std::fprintf(stderr, ", and nearer than its first simplified level it is drawn in %zu chunks, each "
                             "switched by its own centre and cut again nearer still (%zu chunks in all)",
                     part.chunks.size(), chunkCount(part.chunks));
    std::fputc('\n', stderr);
}

// What --hlod auto chose, and why ("" for a mode asked by name).
std::string autoChoice(const ConvertArgs& a, std::size_t placements)
{
    if (a.hlod != "auto")
        return {};
    const std::string count = std::to_string(placements) + " placements";
    if (clusterMode(a, placements) == ClusterMode::FewestCalls)
        return " (fewest draw calls: " + count + ", more than the " + std::to_string(kDrawCallBudget) +
               " draw calls a frame may spend)";
    return " (instances near the viewer: " + count + ")";
}

void printHierarchySummary(const ConvertArgs& a, const AssemblyConversion& c, const HierarchyStats& h)
{
    if (h.clusters == 0 && hierarchical(a) && c.model.placements.size() == 1) {
        printOnePlacementSummary(a, c);
        return;
    }
    if (h.clusters == 0) {
        std::fprintf(stderr, "cadlod: hlod off: one LOD node per placed part%s\n",
                     a.hlod != "off" ? " (a level list has no errors)" : "");
        return;
    }
    const std::size_t placements = c.model.placements.size();
    const ClusterTreeOptions tree = clusterTree(a, placements);
    std::fprintf(stderr,
                 "cadlod: hlod %s%s: %zu clusters of up to %zu placements (%zu per node%s), %zu with proxies: %zu "
                 "proxy levels drawing %zu meshes of %zu triangles, merged from %zu; %zu clusters copies of others "
                 "(%zu turned, %zu mirrored), drawing their meshes moved\n",
                 a.hlod.c_str(), autoChoice(a, placements).c_str(), h.clusters, tree.leafItems, tree.fanout,
                 tree.largeShare > 0 ? ", the largest above" : "", h.proxied,
                 h.proxyLevels, h.proxyShapes, h.proxyTriangles, h.inputTriangles, h.copied, h.turned, h.mirrored);
}

// An assembly that shares geometry: each distinct part simplified once, placed by instances.
void convertInstanced(const ConvertArgs& a, vrml::Scene& scene, const ImportSettings& importing,
                      const SaveSettings& saving, Clock::time_point t0, OutputSet& outputs, const LoadedMesh& loaded)
{
    if (saving.flt.geometry != flt::GeometryRecords::Meshes)
        throw UsageError(a.input + ": shared parts are written with Mesh records; use --records mesh, or "
                                   "--instances expand for Face records");
    const double importSeconds = secondsSince(t0);
    const auto t1 = Clock::now();
    const double lengthScale = loaded.lengthScale;
    const ImportSettings inParts = inMeshUnits(importing, loaded);
    progress::phase(kReadingEnd, kWritingStart, "LOD chain");
    const int partsShare = hierarchical(a) && loaded.placements > 1 ? kPartsShareBeforeProxies : 100;
    progress::beginSpan(0, partsShare, "");
    const auto chain = [&](CoreMesh& original, LevelStore& store, vcg::CallBackPos* progress) {
        return buildLevels(a, lengthScale, original, store, progress);
    };
    AssemblyConversion c =
        convertAssembly(scene, baseName(a.output), weldingOf(inParts), chain, hierarchical(a), barSpans());
    progress::endSpan();
    progress::beginSpan(partsShare, 100, "");
    const HierarchyStats hierarchy = clusterPlacements(a, c, inParts, lengthScale);
    progress::endSpan();
    scaleLengths(c, lengthScale);  // to the unit chosen
    const std::size_t centred = flt::moveToLocalOrigin(c.model);
    c.model.units = saving.units;
    const double lodSeconds = secondsSince(t1);
    const auto t2 = Clock::now();
    progress::phase(kWritingStart, 100, "writing");
    flt::WriteOptions writeOptions = saving.flt;
    writeOptions.progress = [](int p) { progress::report(p, ""); };
    flt::InstancedWriteStats written;
    std::vector<std::uint8_t> bytes;
    std::string error;
    if (!flt::writeInstancedOpenFlight(c.model, writeOptions, bytes, error, &written))
        throw InputError(a.output + ": " + error);
    outputs.write(a.output, [&](const std::string& temporary) { return writeBytesTo(temporary, bytes); });
    const double writeSeconds = secondsSince(t2);
    progress::done();
    const LoadedMesh imported = assemblyImport(loaded, c);
    const std::string originNote = flt::localOriginNote(c.model, centred, a.exporting.units);
    if (!a.report.empty())
        outputs.write(a.report, [&](const std::string& temporary) {
            nlohmann::json report = assemblyReportJson(a, c, written, imported, importSeconds, lodSeconds,
                                                       writeSeconds, secondsSince(t0));
            report["hlod"] = hierarchyJson(a, c.model, hierarchy);
            report["output"]["origin"] = c.model.origin;
            if (!originNote.empty())
                report["notes"] = {originNote};
            return writeJsonTo(temporary, report);
        });
    outputs.commit();
    if (!a.common.quiet) {
        if (!originNote.empty())
            printFolded("note", {originNote});
        if (onePlacedPart(c))
            printLevels(c.parts.front().result, written, a.output);
        else
            printAssemblySummary(c, written, a.output);
        printHierarchySummary(a, c, hierarchy);
        printImportSummary(imported);
        printFindingsSummary(imported);
    }
}


void runConvert(const ConvertArgs& a)
{
    if (extensionOf(a.output) != "flt")
        throw UsageError(a.output + ": convert writes OpenFlight (.flt); use 'cadlod simplify' for PLY/OBJ/STL");
    OutputSet outputs(a.common.force);
    outputs.add(a.output, "-o");
    if (!a.report.empty())
        outputs.add(a.report, "--report");
    ImportSettings importing = importSettings(a.import);
    importing.keepInstances = a.instances == "keep";
    importing.placeParts = importing.keepInstances && hierarchical(a);
    importing.placeWholeModel = importing.placeParts && a.exporting.records == "mesh";
    importing.unitScaling = vrml::UnitScaling::PowerOfTwo;
    const SaveSettings saving = saveSettings(a.exporting);
    progress::enable(!a.common.quiet);
    limitThreads(a.common.threads);

    const auto t0 = Clock::now();
    progress::phase(0, kReadingEnd, "reading");
    CoreMesh original;
    vrml::Scene assembly;
    const LoadedMesh loaded = loadMesh(a.input, original, importing, &assembly);
    if (loaded.placements > 0) {
        convertInstanced(a, assembly, importing, saving, t0, outputs, loaded);
        return;
    }
    const double importSeconds = secondsSince(t0);

    const auto t1 = Clock::now();
    progress::phase(kReadingEnd, kWritingStart, "LOD chain");
    LevelStore store;
    LodSetResult result = buildLevels(a, loaded.lengthScale, original, store, progress::callback);
    if (!result.ok())
        throw InputError(a.input + ": " + result.error);
    const double lodSeconds = secondsSince(t1);

    const auto t2 = Clock::now();
    std::vector<CoreMesh*> meshes{&original};
    for (auto& m : store.meshes)
        meshes.push_back(m.get());
    std::size_t skipped = 0;
    flt::LodModel model = lodMeshesToModel(meshes, result.levels.front().setId, baseName(a.output), skipped);
    flt::scaleLengths(model, loaded.lengthScale);
    scaleLengths(result, loaded.lengthScale);
    model.units = saving.units;
    progress::phase(kWritingStart, 100, "writing");
    flt::WriteOptions writeOptions = saving.flt;
    writeOptions.progress = [](int p) { progress::report(p, ""); };
    flt::WriteStats written;
    writeFlt(outputs, a.output, model, writeOptions, written);
    const double writeSeconds = secondsSince(t2);
    progress::done();
    if (!a.report.empty()) {
        const nlohmann::json timings{{"importSeconds", importSeconds}, {"lodSeconds", lodSeconds},
                                     {"lodMeasureSeconds", result.measureSeconds}, {"writeSeconds", writeSeconds},
                                     {"totalSeconds", secondsSince(t0)}};
        const nlohmann::json report = reportJson(a, loaded, result, written, skipped, timings);
        outputs.write(a.report, [&](const std::string& temporary) { return writeJsonTo(temporary, report); });
    }
    outputs.commit();
    if (!a.common.quiet)
        printSummary(result, written, a.output, loaded);
}

// "auto" or a level list the LOD planner accepts (lod_plan.h), checked before any work.
CLI::Validator levelListCheck()
{
    return CLI::Validator(
        [](const std::string& list) -> std::string {
            if (list == "auto")
                return {};
            const LevelPlan plan = planLevels(list, LevelSpec::ReductionPercent, std::numeric_limits<int>::max());
            return plan.ok() ? std::string() : "--lod \"" + list + "\": " + plan.error;
        },
        "auto|LIST");
}

CLI::Validator openRange(double low, double high)
{
    return CLI::Validator(
        [low, high](const std::string& text) -> std::string {
            char* end = nullptr;
            const double v = std::strtod(text.c_str(), &end);
            if (text.empty() || *end != '\0' || !(v > low && v < high))
                return "'" + text + "' is not a number above " + std::to_string(int(low)) +
                       (std::isfinite(high) ? " and below " + std::to_string(int(high)) : std::string());
            return {};
        },
        "");
}

}  // namespace

void addConvertCommand(CLI::App& app)
{
    auto args = std::make_shared<ConvertArgs>();
    CLI::App* cmd = app.add_subcommand("convert", "VRML (or PLY/OBJ/STL/FLT) to an OpenFlight LOD model");
    cmd->add_option("input", args->input, "Input file")->required();
    cmd->add_option("-o,--output", args->output, "Output .flt")->required();
    cmd->add_option("--lod", args->lod,
                    "auto: screen-space LOD chain; or a quoted list of reductions in % (\"50 60 70 80 90\")")
        ->check(levelListCheck())
        ->capture_default_str();
    cmd->add_option("--pixel-error", args->pixelError, "Largest error on screen when a level is shown (px)")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    cmd->add_option("--fov", args->fov, "Vertical field of view of the simulator (degrees)")
        ->check(openRange(0.0, 180.0))
        ->capture_default_str();
    cmd->add_option("--viewport", args->viewport, "Viewport height (px)")->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_option("--distance-ratio", args->distanceRatio, "auto: ratio between consecutive level distances")
        ->check(openRange(1.0, std::numeric_limits<double>::infinity()))
        ->capture_default_str();
    cmd->add_option("--proxy-pixels", args->proxyPixels, "auto: the box proxy serves below this height (px)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd->add_option("--cull-pixels", args->cullPixels, "auto: not drawn below this height (px); 0: never culled")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd->add_option("--instances", args->instances,
                    "keep: a part the file places many times (USE, Inline) is simplified once and written as an "
                    "OpenFlight instance; expand: a copy per placement")
        ->check(CLI::IsMember({"keep", "expand"}))
        ->capture_default_str();
    cmd->add_option("--hlod", args->hlod,
                    "auto: the placements of an assembly in clusters of nearby parts, each drawn far off as one "
                    "merged, simplified proxy (switch distances held at every node's nearest point), as calls "
                    "above 400 placements, as instances up to that; instances: every part its own instance near "
                    "the viewer, clusters of 48; calls: the fewest draw calls near the viewer, small clusters "
                    "drawn as their parts merged (files about 4x larger); off: one LOD node per part")
        ->check(CLI::IsMember({"auto", "instances", "calls", "off"}))
        ->capture_default_str();
    cmd->add_option("--cluster-parts", args->clusterParts,
                    "hlod: at most this many placements in a leaf cluster [instances: 48, calls: 2]")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--cluster-fanout", args->clusterFanout,
                    "hlod: at most this many nodes below a cluster [instances: 8, calls: 2]")
        ->check(CLI::Range(2, 64));
    cmd->add_flag("--from-original", args->fromOriginal, "List: simplify every level from the original");
    cmd->add_option("--samples", args->samples, "Hausdorff samples per side (0: automatic)");
    cmd->add_option("--report", args->report, "Write a JSON report here");
    addImportOptions(*cmd, args->import);
    addProtectionOptions(*cmd, args->protection);
    addExportOptions(*cmd, args->exporting);
    addCommonOptions(*cmd, args->common);
    cmd->callback([args] { runConvert(*args); });
}

}  // namespace cadlod::cli
