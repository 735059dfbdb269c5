// "Generate CAD LOD Set": the MeshLab side of core/lod_builder.h. One new layer per level,
// each carrying its cadlod::LodLevel (what the OpenFlight exporter writes), a log table
// like the paper's Table 1.
#pragma once

#include <common/interfaces.h>

namespace cadlod {

void lodSetParameters(MeshModel& m, RichParameterList& par);
bool generateLodSet(MeshFilterInterface& plugin, MeshDocument& md, const RichParameterList& par,
                    vcg::CallBackPos* cb, QString& error);

}  // namespace cadlod
