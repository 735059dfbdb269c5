// The CAD Quadric Edge Collapse's placement and protection parameters, shared by the
// simplification filter and the LOD-set filter (same names in both, for .mlx scripts).
#pragma once

#include "core/simplify_params.h"

#include <common/interfaces.h>

namespace cadlod {

void addPlacementParameters(RichParameterList& par);
void readPlacementParameters(const RichParameterList& par, SimplifyParams& p);

}  // namespace cadlod
