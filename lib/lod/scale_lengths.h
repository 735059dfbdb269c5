// A chain's result in another unit: every length it holds multiplied by one factor, counts
// and ratios left alone. The command simplifies a model at the power of two nearest to its
// unit (vrml::UnitScaling) and reports its lengths in the unit asked for.
#pragma once

#include "lod/lod_builder.h"

namespace cadlod {

inline void scaleLengths(LodLevel& level, double scale)
{
    level.hausdorffMax *= scale;
    level.hausdorffMean *= scale;
    level.switchOut *= scale;
    if (level.switchIn < kNeverCulled)
        level.switchIn *= scale;
    for (double& c : level.center)
        c *= scale;
}

inline void scaleLengths(HausdorffStats& stats, double scale)
{
    stats.max *= scale;
    stats.mean *= scale;
    stats.rms *= scale;
}

inline void scaleLengths(SimplifyStats& stats, double scale)
{
    stats.largestError *= scale;
    stats.diagonal *= scale;
    stats.largestRemovedComponent *= scale;
    stats.widestTunnelCap *= scale;
    stats.errorBound *= scale;
}

inline void scaleLengths(LodSetResult& result, double scale)
{
    result.modelSize *= scale;
    for (LodLevel& level : result.levels)
        scaleLengths(level, scale);
    for (SimplifyStats& step : result.steps)
        scaleLengths(step, scale);
    for (SymmetricHausdorff& d : result.distance) {
        scaleLengths(d.forward, scale);
        scaleLengths(d.backward, scale);
        d.diagonal *= scale;
    }
}

}  // namespace cadlod
