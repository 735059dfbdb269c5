// The CAD Quadric Edge Collapse's placement and protection parameters (simplify/parameter_table.h),
// shared by the simplification filter and the LOD-set filter (same names in both, for .mlx scripts).
#pragma once

#include "simplify/simplify_params.h"

#include <common/interfaces.h>

namespace cadlod {

// All of them (the simplification filter).
void addPlacementParameters(RichParameterList& par);
// Only those a LOD set's user decides on: what is a feature and how dearly it gives way
// (the LOD-set filter; the others keep their defaults, and its dialog fits a screen).
void addFeatureParameters(RichParameterList& par);
// Reads those `par` has; the others keep their values in `p`.
void readPlacementParameters(const RichParameterList& par, SimplifyParams& p);

}  // namespace cadlod
