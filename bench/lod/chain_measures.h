// How a LOD chain serves a scene (design.md §5), from its levels' face counts and switch
// ranges alone, so that any two chains are judged the same way:
//  - path: the mean triangles drawn by a camera backing away from 1x to 1000x the model's
//    diagonal at log-spaced distances, as a share of level 0;
//  - scene: the mean triangles per object for objects spread evenly over a ground disc of
//    radius 1000x the diagonal around the viewer (the share of objects at distance d grows
//    with d, so the far field dominates), as a share of level 0;
//  - worst projected error: the largest measured error of a level, in pixels, at the
//    nearest distance it is drawn.
#pragma once

#include "mesh/layer_metadata.h"
#include "lod/lod_plan.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace cadlod::bench {

struct ChainFigures {
    double pathShare = 0;   // mean drawn / level-0 faces over the camera path
    double sceneShare = 0;  // mean drawn / level-0 faces over the disc
    double worstPixels = 0; // largest projected error of a drawn level
};

// Faces drawn at distance d: the level whose range holds d, or none when culled.
inline int facesAt(const std::vector<LodLevel>& levels, double d)
{
    for (const LodLevel& l : levels)
        if (d >= l.switchOut && d < l.switchIn)
            return l.faces;
    return 0;
}

inline ChainFigures chainFigures(const std::vector<LodLevel>& levels, double diagonal, const ViewParams& view,
                                 int pathSteps = 300)
{
    ChainFigures f;
    if (levels.empty() || !(diagonal > 0))
        return f;
    const double faces0 = levels.front().faces;
    double sum = 0;
    for (int i = 0; i < pathSteps; ++i) {
        const double d = diagonal * std::pow(1000.0, double(i) / (pathSteps - 1));
        sum += facesAt(levels, d);
    }
    f.pathShare = sum / pathSteps / faces0;

    // Objects uniform on a disc of radius R: P(distance < d) = (d / R)^2.
    const double R = 1000.0 * diagonal;
    double scene = 0;
    for (const LodLevel& l : levels) {
        const double a = std::min(l.switchOut, R), b = std::min(l.switchIn, R);
        if (b > a)
            scene += l.faces * (b * b - a * a) / (R * R);
    }
    f.sceneShare = scene / faces0;

    const double tanHalf = std::tan(0.5 * view.fovYDegrees * M_PI / 180.0);
    for (const LodLevel& l : levels) {
        if (!(l.switchIn > l.switchOut) || l.hausdorffMax <= 0)
            continue;
        const double nearest = std::max(l.switchOut, 1e-300);
        f.worstPixels = std::max(f.worstPixels, l.hausdorffMax * view.viewportHeightPx / (2.0 * nearest * tanHalf));
    }
    return f;
}

}  // namespace cadlod::bench
