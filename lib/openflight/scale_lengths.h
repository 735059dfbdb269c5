// A model in another unit: positions, LOD centres, switch distances and placement
// translations multiplied by one factor (a range that never ends stays so). The command
// simplifies at the power of two nearest to the input's unit (vrml::UnitScaling) and writes
// in the unit asked for.
#pragma once

#include "openflight/instanced_writer.h"
#include "openflight/lod_model.h"

namespace cadlod::flt {

void scaleLengths(Level& level, double scale);
void scaleLengths(LodModel& model, double scale);
void scaleLengths(InstancedModel& model, double scale);

}  // namespace cadlod::flt
