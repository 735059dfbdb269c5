#include "report_json.h"

#include "output_file.h"

#include <cmath>
#include <fstream>

namespace cadlod::cli {
namespace {

double percentOf(double value, double whole) { return whole > 0 ? 100.0 * value / whole : 0.0; }

// Pixels an error of `error` covers at distance `d` (the inverse of projectedErrorDistance);
// at a level's switch-out (near) distance, the largest it is ever seen at.
double pixelsAt(double error, double d, const ViewParams& view)
{
    if (!(d > 0) || d >= kNeverCulled)
        return 0.0;
    const double halfFov = 0.5 * view.fovYDegrees * M_PI / 180.0;
    return error * view.viewportHeightPx / (2.0 * d * std::tan(halfFov));
}

nlohmann::json rangeJson(double d) { return d >= kNeverCulled ? nlohmann::json("never") : nlohmann::json(d); }

}  // namespace

nlohmann::json compactnessJson(const CompactnessStats& c)
{
    return {{"mean", c.mean}, {"min", c.min}, {"p5", c.p5}, {"shareBelow0.1", c.shareBelow01},
            {"shareBelow0.3", c.shareBelow03}};
}

nlohmann::json simplifyStatsJson(const SimplifyStats& s)
{
    return {{"facesBefore", s.facesBefore},
            {"facesAfter", s.facesAfter},
            {"collapses", s.collapses},
            {"halvesCollapses", s.halvesCollapses},
            {"largestCollapseError", s.largestError},
            {"errorBound", s.errorBound},
            {"stoppedBy", s.stoppedBy},
            {"featureBreaks", s.featureBreaks},
            {"removedComponents", s.removedComponents},
            {"largestRemovedComponent", s.largestRemovedComponent},
            {"closedTunnels", s.closedTunnels},
            {"widestTunnelCap", s.widestTunnelCap},
            {"relaxed", s.relaxed},
            {"weightTrials", s.weightTrials},
            {"message", s.message}};
}

nlohmann::json levelsJson(const LodSetResult& r, const ViewParams& view)
{
    nlohmann::json levels = nlohmann::json::array();
    for (std::size_t k = 0; k < r.levels.size(); ++k) {
        const LodLevel& l = r.levels[k];
        nlohmann::json j{{"level", l.level},
                         {"faces", l.faces},
                         {"reductionPercent", 100.0 * l.reduction},
                         {"hausdorffMax", l.hausdorffMax},
                         {"hausdorffMean", l.hausdorffMean},
                         {"hausdorffMaxPercentDiag", percentOf(l.hausdorffMax, r.modelSize)},
                         {"hausdorffMeanPercentDiag", percentOf(l.hausdorffMean, r.modelSize)},
                         {"errorPixelsAtSwitchOut", pixelsAt(l.hausdorffMax, l.switchOut, view)},
                         {"switchOut", l.switchOut},
                         {"switchIn", rangeJson(l.switchIn)},
                         {"compactness", compactnessJson(r.compactness[k])}};
        if (k > 0 && k - 1 < r.steps.size())
            j["simplification"] = simplifyStatsJson(r.steps[k - 1]);
        levels.push_back(j);
    }
    return levels;
}

nlohmann::json comparisonJson(const SimplificationReport& r)
{
    const double diag = r.distance.diagonal;
    return {{"facesBefore", r.facesBefore},
            {"facesAfter", r.facesAfter},
            {"verticesBefore", r.verticesBefore},
            {"verticesAfter", r.verticesAfter},
            {"diagonal", diag},
            {"hausdorffMax", r.distance.max()},
            {"hausdorffMean", r.distance.mean()},
            {"hausdorffMaxPercentDiag", percentOf(r.distance.max(), diag)},
            {"hausdorffMeanPercentDiag", percentOf(r.distance.mean(), diag)},
            {"compactnessBefore", compactnessJson(r.before)},
            {"compactnessAfter", compactnessJson(r.after)}};
}

bool writeJsonTo(const std::string& file, const nlohmann::json& report)
{
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << report.dump(2) << "\n";
    out.close();
    return bool(out);
}

void writeJsonFile(const std::string& path, const nlohmann::json& report)
{
    writeAtomically(path, [&](const std::string& temporary) { return writeJsonTo(temporary, report); });
}

}  // namespace cadlod::cli
