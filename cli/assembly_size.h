// The size of an assembly where its placements put its parts, for the plausibility check
// of its unit (unit_choice.h), read before any part is converted.
#pragma once
#include "vrml/assembly.h"

namespace cadlod::cli {

// The diagonal of a box that holds every placed part in world coordinates (the boxes of
// the parts, moved by each placement; a bound, not the tightest box when parts are turned).
double placedDiagonal(const vrml::Assembly& assembly);

}  // namespace cadlod::cli
