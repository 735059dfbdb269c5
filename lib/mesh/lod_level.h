// The record of one level of an LOD set: what the LOD-set filter stores on each level's
// mesh (layer_metadata.h) and the OpenFlight exporter turns into LOD ranges. Plain data:
// no vcglib, no MeshLab.
#pragma once

#include <array>

namespace cadlod {

// Switch-in distance of the last level when the model is never culled.
inline constexpr double kNeverCulled = 1e30;

struct LodLevel {
    int setId = 0;             // layers with the same setId form one LOD set
    int level = 0;             // 0 = original, finest
    int faces = 0;
    double reduction = 0.0;    // fraction of level-0 faces removed (0.9 = 90 %)
    double hausdorffMax = 0.0; // symmetric Hausdorff distance to level 0, model units
    double hausdorffMean = 0.0;
    double switchIn = 0.0;     // FAR distance: visible while switchOut <= d < switchIn
    double switchOut = 0.0;    // NEAR distance
    std::array<double, 3> center{0, 0, 0};  // LOD center (level 0 bounding-box center)
};

}  // namespace cadlod
