// A model far from the origin (site coordinates: a plant in UTM) written about a local
// origin. OpenFlight's Matrix records hold 32-bit floats, and OpenSceneGraph keeps vertices
// in them; far off they are coarser than a part is small, so parts and the vertices of
// geometry placed there would stand visibly off. Moved, every part's geometry lies about
// its own frame's origin, every placement and proxy about the model's centre, and the
// model's root Group carries the one move back, by a translation that a float holds
// exactly: the file places everything where it was.
#pragma once

#include "openflight/instanced_writer.h"

namespace cadlod::flt {

// Moves `model` about a local origin when its placements or its parts' geometry stand far
// enough from the origin for floats to place them visibly off (placementPrecision; for each
// part's geometry in its own frame, a thousandth of the part's size), setting model.origin.
// Returns the number of part definitions whose geometry was moved to lie about their own
// origin; a model near the origin is left as it was (model.origin stays zero).
std::size_t moveToLocalOrigin(InstancedModel& model);

// What the summary and the report say of a model moved about a local origin, `centred` parts'
// geometry moved too, lengths in `unitName`; empty for a model left where it was.
std::string localOriginNote(const InstancedModel& model, std::size_t centred, const std::string& unitName);

}  // namespace cadlod::flt
