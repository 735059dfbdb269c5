// cadlod simplify IN -o OUT: one CAD quadric edge collapse run (reduction %, face count
// or maximum error), written as PLY/OBJ/STL or a one-level .flt.
#include "cli_errors.h"
#include "cli_options.h"
#include "input_losses.h"
#include "commands.h"
#include "mesh_files.h"
#include "output_file.h"
#include "note_lines.h"
#include "progress_bar.h"

#include "lod/scale_lengths.h"
#include "simplify/best_of_trials.h"

#include <vcg/complex/algorithms/update/position.h>

#include <memory>

namespace cadlod::cli {
namespace {

struct SimplifyArgs {
    std::string input, output;
    double reduction = 0.0;
    bool reductionGiven = false;  // --reduction on the command line (0 included)
    int faces = 0;
    double maxError = 0.0;
    ImportArgs import;
    ProtectionArgs protection;
    ExportArgs exporting;
    CommonArgs common;
};

SimplifyParams paramsOf(const SimplifyArgs& a)
{
    SimplifyParams p;
    p.reductionPerc = a.reduction;
    p.targetFaces = a.faces;
    p.maxError = a.maxError;
    if (!a.reductionGiven && p.targetFaces == 0 && p.maxError == 0)
        p.reductionPerc = 90.0;
    applyProtection(a.protection, p);
    return p;
}

// The mesh in the unit chosen: it was simplified at the power of two nearest to it
// (vrml::UnitScaling).
void toUnitChosen(CoreMesh& m, const LoadedMesh& loaded)
{
    if (loaded.lengthScale != 1.0)
        vcg::tri::UpdatePosition<CoreMesh>::Scale(m, CoreMesh::ScalarType(loaded.lengthScale));
}

void runSimplify(const SimplifyArgs& a)
{
    checkWritable(a.output, a.common.force);
    ImportSettings importing = importSettings(a.import);
    importing.unitScaling = vrml::UnitScaling::PowerOfTwo;
    const SaveSettings saving = saveSettings(a.exporting);
    progress::enable(!a.common.quiet);
    limitThreads(a.common.threads);
    CoreMesh m;
    progress::phase(0, 10, "reading");
    const LoadedMesh loaded = loadMesh(a.input, m, importing);
    // 0 % asks to remove nothing: the mesh is written as loaded (a conversion), unless a
    // maximum error is what bounds the run.
    if (a.reductionGiven && a.reduction == 0 && a.maxError == 0) {
        toUnitChosen(m, loaded);
        progress::phase(10, 100, "writing");
        saveMesh(a.output, m, saving);
        progress::done();
        if (!a.common.quiet)
            std::fprintf(stderr, "cadlod: %s: %d faces, written unsimplified (--reduction 0)\n", a.output.c_str(), m.fn);
        if (!a.common.quiet)
            printFindingsSummary(loaded);
        return;
    }
    progress::phase(10, 95, "simplifying");
    SimplifyStats stats = bestOfTrials(m, paramsOf(a), progress::callback, runOnWorkers);
    if (!stats.ok)
        throw InputError(a.input + ": " + stats.message);
    toUnitChosen(m, loaded);
    scaleLengths(stats, loaded.lengthScale);
    progress::phase(95, 100, "writing");
    saveMesh(a.output, m, saving);
    progress::done();
    if (!a.common.quiet && stats.stoppedBy.empty())  // nothing to do: the message says why
        std::fprintf(stderr, "cadlod: %s: %d faces, written unsimplified: %s\n", a.output.c_str(), stats.facesAfter,
                     stats.message.c_str());
    else if (!a.common.quiet)
        std::fprintf(stderr, "cadlod: %s: %d -> %d faces (stopped by %s), largest collapse error %.6g (%.4f%% diag)\n",
                     a.output.c_str(), stats.facesBefore, stats.facesAfter, stats.stoppedBy.c_str(),
                     stats.largestError, 100.0 * stats.largestErrorFraction());
    if (!a.common.quiet && stats.halvesCollapses > 0)
        std::fprintf(stderr, "cadlod: %d of %d collapses made on two halves side by side (a band of %d vertices "
                             "between them left to the end)\n",
                     stats.halvesCollapses, stats.collapses, stats.halvesBandVertices);
    if (!a.common.quiet && !stats.weightTrials.empty())
        std::fprintf(stderr, "cadlod: %s\n", stats.weightTrials.c_str());
    if (!a.common.quiet)
        printFolded("", stats.relaxed);  // what gave way to reach the target
    if (!a.common.quiet)
        printFindingsSummary(loaded);
}

}  // namespace

void addSimplifyCommand(CLI::App& app)
{
    auto args = std::make_shared<SimplifyArgs>();
    CLI::App* cmd = app.add_subcommand("simplify", "Simplify a mesh once (CAD quadric edge collapse)");
    cmd->add_option("input", args->input, "Input file")->required();
    cmd->add_option("-o,--output", args->output, "Output (.ply, .obj, .stl or .flt)")->required();
    auto* reduction = cmd->add_option("--reduction", args->reduction, "Remove this % of the faces (default 90; 0 writes the mesh unsimplified)")
                          ->check(CLI::Range(0.0, 100.0));
    auto* faces = cmd->add_option("--faces", args->faces, "Stop at this many faces")->check(CLI::PositiveNumber);
    cmd->add_option("--max-error", args->maxError, "Never collapse beyond this error (fraction of the diagonal)")
        ->check(CLI::PositiveNumber);
    reduction->excludes(faces);
    addImportOptions(*cmd, args->import);
    addProtectionOptions(*cmd, args->protection);
    addExportOptions(*cmd, args->exporting);
    addCommonOptions(*cmd, args->common);
    cmd->callback([args, reduction] {
        args->reductionGiven = reduction->count() > 0;
        runSimplify(*args);
    });
}

}  // namespace cadlod::cli
