// A placement that stretches its geometry unevenly (a scale of 1 1 3, or a shear) would show
// its levels' errors stretched with it: a level's error is measured in the geometry's own
// frame, and an LOD node picks its level by the eye's distance in that frame, which the
// stretch shrinks along one axis and not along another. Such a placement gets a geometry of
// its own with the stretch built in, simplified in the shape it is seen in; its matrix keeps
// only the turn (or mirror) and the move. Placements stretched alike share that geometry.
#pragma once

#include "vrml/assembly.h"

#include <cstddef>
#include <vector>

namespace cadlod {

// A placement whose scales along its principal axes differ by more than this share is
// stretched.
inline constexpr double kStretchTolerance = 1e-6;

// Appends a stretched geometry to `assembly` for each distinct (geometry, stretch) among
// `placements`, holding the geometry's parts (its children are placements of their own), and
// moves each stretched placement onto it. Returns how many placements were stretched.
std::size_t buildStretchesIn(vrml::Assembly& assembly, std::vector<vrml::Placement>& placements);

}  // namespace cadlod
