// Switch distances that hold at a node's nearest point (design.md §5, "The contract must
// hold wherever the viewer stands"). A simulator picks an LOD node's level by the eye's
// distance d to the node's centre; the viewer sees the level's geometry from as near as
// d - r, r being how far its vertices reach from the centre. A level whose error projects
// to the pixel error at distance e (at the centre) is therefore switched in at e + r: from
// there no vertex is nearer than e. And never before kNearestPointReach * r, so that a
// level switched in at s is never seen from nearer than s / kApparentErrorBound: the error
// a viewer can read off the switch distance and the nearest geometry stays bounded too,
// for a level whose own error is far below the pixel.
#pragma once

#include "lod/lod_chain.h"  // kNeverCulled

#include <algorithm>
#include <cstddef>
#include <vector>

namespace cadlod {

// The switch distance over the distance of the nearest vertex, at most.
inline constexpr double kApparentErrorBound = 1.2;
inline constexpr double kNearestPointReach = kApparentErrorBound / (kApparentErrorBound - 1.0);
// A level held to a range narrower than this share of where it is switched in is one a
// viewer would barely see: the finer level serves through it, and the file does not hold it.
inline constexpr double kNarrowestRange = 0.05;

// `atCentre`: where the level's error projects to the pixel error; `reach`: the largest
// distance from the node's centre to a vertex of the level.
inline double switchAtNearestPoint(double atCentre, double reach)
{
    return std::max(atCentre + reach, kNearestPointReach * reach);
}

// Levels finest first, each drawn for switchOut <= d < switchIn, consecutive ones
// contiguous; `reach[k]` for level k. Every switch moves to where it holds at the nearest
// point; a level left with no range of its own, or one narrower than kNarrowestRange, is
// dropped. Returns the indices kept.
template <class Level>
std::vector<std::size_t> holdAtNearestPoint(std::vector<Level>& levels, const std::vector<double>& reach)
{
    std::vector<std::size_t> kept;
    for (std::size_t k = 0; k < levels.size(); ++k) {
        if (k > 0 && levels[k].switchOut > 0 && levels[k].switchOut < kNeverCulled)
            levels[k].switchOut = switchAtNearestPoint(levels[k].switchOut, reach[k]);
        // A level left with no range, or too narrow a one, gives way: the finer level before
        // it serves up to where the coarser one is held.
        while (kept.size() > 1 && levels[k].switchOut <= levels[kept.back()].switchOut * (1 + kNarrowestRange))
            kept.pop_back();
        kept.push_back(k);
    }
    std::vector<Level> out;
    for (std::size_t i = 0; i < kept.size(); ++i) {
        Level l = levels[kept[i]];
        if (i + 1 < kept.size())
            l.switchIn = levels[kept[i + 1]].switchOut;
        else if (l.switchIn > 0 && l.switchIn < kNeverCulled)  // culled: as far out as it moved
            l.switchIn = std::max(l.switchIn + reach[kept[i]], l.switchOut);
        out.push_back(std::move(l));
    }
    levels = std::move(out);
    return kept;
}

}  // namespace cadlod
