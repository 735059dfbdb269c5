// cadlod report A B: what simplification did to A (faces, symmetric Hausdorff distance in
// % of A's diagonal, compactness before and after); both Hausdorff sides run in parallel.
#include "cli_errors.h"
#include "cli_options.h"
#include "commands.h"
#include "mesh_files.h"
#include "report_json.h"

#include <cstdio>
#include <iostream>
#include <memory>

namespace cadlod::cli {
namespace {

struct ReportArgs {
    std::string original, simplified;
    bool json = false;
    std::size_t samples = 0;
    ImportArgs import;
    int threads = 0;
};

void printText(const SimplificationReport& r)
{
    const double diag = r.distance.diagonal;
    std::printf("faces        %d -> %d\nvertices     %d -> %d\n", r.facesBefore, r.facesAfter, r.verticesBefore,
                r.verticesAfter);
    std::printf("hausdorff    max %.6g (%.4f%% diag), mean %.6g (%.4f%% diag)\n", r.distance.max(),
                diag > 0 ? 100 * r.distance.max() / diag : 0.0, r.distance.mean(),
                diag > 0 ? 100 * r.distance.mean() / diag : 0.0);
    std::printf("compactness  mean %.3f -> %.3f, min %.3f -> %.3f, below 0.1 %.1f%% -> %.1f%%\n", r.before.mean,
                r.after.mean, r.before.min, r.after.min, 100 * r.before.shareBelow01, 100 * r.after.shareBelow01);
    for (const std::string& line : histogramLines(r))
        std::printf("%s\n", line.c_str());
}

// The pair is measured only when the second may be a simplification of the first (the
// rule the GUI's Simplification Report applies, measure/simplification_report.h).
void refuseUnrelated(const ReportArgs& a, const CoreMesh& original, const CoreMesh& simplified,
                     const LoadedMesh& first, const LoadedMesh& second)
{
    const std::string why = whyNotASimplification(liveVertexBox(original), liveVertexBox(simplified));
    if (why.empty())
        return;
    const std::string units = " " + a.original + " was read in " + first.unit.describe() + ", " + a.simplified +
                              " in " + second.unit.describe();
    throw InputError(a.simplified + " cannot be a simplification of " + a.original + ": " + why + units);
}

void runReport(const ReportArgs& a)
{
    limitThreads(a.threads);
    const ImportSettings importing = importSettings(a.import);
    CoreMesh original, simplified;
    const LoadedMesh first = loadMesh(a.original, original, importing);
    const LoadedMesh second = loadMesh(a.simplified, simplified, importing);
    refuseUnrelated(a, original, simplified, first, second);
    const SimplificationReport r = compareWithOriginal(original, simplified, a.samples, nullptr,
                                                         runOnWorkers);
    if (a.json)
        std::cout << comparisonJson(r).dump(2) << "\n";
    else
        printText(r);
}

}  // namespace

void addReportCommand(CLI::App& app)
{
    auto args = std::make_shared<ReportArgs>();
    CLI::App* cmd = app.add_subcommand("report", "Before/after measures of a simplified mesh against its original");
    cmd->add_option("original", args->original, "Original")->required();
    cmd->add_option("simplified", args->simplified, "Simplified")->required();
    cmd->add_flag("--json", args->json, "JSON on stdout");
    cmd->add_option("--samples", args->samples, "Hausdorff samples per side (0: the larger face count)");
    cmd->add_option("--threads", args->threads, "Worker threads (0: all cores)")->check(CLI::NonNegativeNumber);
    addImportOptions(*cmd, args->import);
    cmd->callback([args] { runReport(*args); });
}

}  // namespace cadlod::cli
