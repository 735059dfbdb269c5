// Planning a LOD set (design.md §5): which face count each level gets, and the distances
// at which a viewer switches between levels. Level 0 is the original; level k is shown
// from switchOut(k) (near) to switchIn(k) (far), and switchIn(k) == switchOut(k+1).
#pragma once

#include "mesh/lod_level.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace cadlod {

enum class LevelSpec { ReductionPercent, FaceCount };

struct LevelPlan {
    std::vector<int> targetFaces;       // one per simplified level (level 1..n)
    std::vector<std::string> warnings;  // levels left out because the mesh is too small for them
    std::string error;                  // non-empty when the list cannot be used
    bool ok() const { return error.empty(); }
};

// Parses a level list such as "50 60 70 80 90" (reductions in %, as the paper) or
// "20000 8000 2000" (face counts). The values must get strictly coarser; a level that
// would not have fewer faces than the one before it on this mesh (a face count above the
// input, or a small mesh where two reductions round to the same count) is left out with a
// warning, so one list serves a whole batch of parts. An empty plan is valid: level 0 only.
inline LevelPlan planLevels(const std::string& list, LevelSpec spec, int inputFaces)
{
    LevelPlan plan;
    std::istringstream in(list);
    std::string token;
    int previousFaces = inputFaces;
    double previousValue = spec == LevelSpec::ReductionPercent ? 0.0 : std::numeric_limits<double>::infinity();
    bool any = false;
    while (in >> token) {
        while (!token.empty() && (token.back() == '%' || token.back() == ','))
            token.pop_back();
        char* end = nullptr;
        const double value = std::strtod(token.c_str(), &end);
        if (token.empty() || *end != '\0' || !std::isfinite(value)) {
            plan.error = "'" + token + "' is not a number";
            return plan;
        }
        any = true;
        int faces = 0;
        if (spec == LevelSpec::ReductionPercent) {
            if (value <= 0.0 || value >= 100.0) {
                plan.error = "reduction " + token + "% is outside (0, 100)";
                return plan;
            }
            faces = int(std::lround(inputFaces * (1.0 - value / 100.0)));
        } else {
            if (value < 1.0 || value != std::floor(value)) {
                plan.error = "face count " + token + " is not a positive whole number";
                return plan;
            }
            faces = int(value);
        }
        const bool coarser = spec == LevelSpec::ReductionPercent ? value > previousValue : value < previousValue;
        if (!coarser) {
            plan.error = "level '" + token + "' is not coarser than the level before it";
            return plan;
        }
        previousValue = value;
        faces = std::max(faces, 1);
        if (faces >= previousFaces) {
            plan.warnings.push_back("level '" + token + "' left out: it would keep " + std::to_string(faces) +
                                    " faces, not fewer than the " + std::to_string(previousFaces) +
                                    " of the level before it");
            continue;
        }
        plan.targetFaces.push_back(faces);
        previousFaces = faces;
    }
    if (!any)
        plan.error = "the level list is empty";
    return plan;
}

struct ViewParams {
    double fovYDegrees = 45.0;     // vertical field of view of the simulator's camera
    double viewportHeightPx = 1080.0;
    double pixelThreshold = 1.0;   // a level is used once its error projects below this
};

// Distance at which a geometric error of `error` (model units) projects onto fewer than
// `pixelThreshold` pixels: error * H / (2 d tan(fov/2)) = N  =>  d = error * H / (2 N tan(fov/2)).
inline double projectedErrorDistance(double error, const ViewParams& view)
{
    const double halfFov = 0.5 * view.fovYDegrees * M_PI / 180.0;
    return error * view.viewportHeightPx / (2.0 * view.pixelThreshold * std::tan(halfFov));
}

// Errors below this fraction of the model size count as this much, so that a lossless
// level still gets a (tiny) distance of its own.
inline constexpr double kRelativeErrorFloor = 1e-7;

// Which simplified levels are worth a place in the set (levels[0] is the original and is
// always kept). A level is dropped when it has no fewer faces than the level kept before it
// (the simplifier could not get further), or when the next kept level is at least as
// accurate: that level is lighter and would be switched in no later, so this one would
// never be shown. `why[k]` says why level k was dropped.
struct LevelSelection {
    std::vector<bool> keep;
    std::vector<std::string> why;
};

inline LevelSelection selectUsefulLevels(const std::vector<LodLevel>& levels, double errorFloor)
{
    LevelSelection s;
    s.keep.assign(levels.size(), true);
    s.why.assign(levels.size(), "");
    std::size_t lastKept = 0;
    for (std::size_t k = 1; k < levels.size(); ++k) {
        if (levels[k].faces >= levels[lastKept].faces) {
            s.keep[k] = false;
            s.why[k] = "the simplifier stopped at " + std::to_string(levels[k].faces) +
                       " faces, no fewer than level " + std::to_string(lastKept);
        } else {
            lastKept = k;
        }
    }
    double nextError = std::numeric_limits<double>::infinity();
    std::size_t nextLevel = levels.size();
    for (std::size_t k = levels.size(); k-- > 1;) {
        if (!s.keep[k])
            continue;
        const double error = std::max(levels[k].hausdorffMax, errorFloor);
        if (error < nextError) {
            nextError = error;
            nextLevel = k;
        } else {
            s.keep[k] = false;
            s.why[k] = "level " + std::to_string(nextLevel) + " has fewer faces and no larger error, "
                       "so this level would never be shown";
        }
    }
    return s;
}

// Fills switchIn/switchOut of levels[0..n) (level order, level 0 first) from their
// hausdorffMax (at least `errorFloor`). The last level stays visible until the whole model
// (bounding-box diagonal `modelSize`) projects below one pixel. Levels must have
// increasing errors (selectUsefulLevels); any that do not get an empty range.
inline void assignSwitchDistances(std::vector<LodLevel>& levels, double modelSize, const ViewParams& view,
                                  double errorFloor = 0.0)
{
    if (levels.empty())
        return;
    double near = 0.0;
    for (std::size_t k = 0; k < levels.size(); ++k) {
        levels[k].switchOut = near;
        double far;
        if (k + 1 < levels.size())
            far = projectedErrorDistance(std::max(levels[k + 1].hausdorffMax, errorFloor), view);
        else {
            ViewParams onePixel = view;
            onePixel.pixelThreshold = 1.0;
            far = projectedErrorDistance(modelSize, onePixel);
        }
        levels[k].switchIn = std::max(near, far);
        near = levels[k].switchIn;
    }
}

}  // namespace cadlod
