// "Simplification: CAD Quadric Edge Collapse (compactness)": the MeshLab side of
// core/simplify.h. Parameter names are stable (.mlx scripts use them).
#pragma once

#include <common/interfaces.h>

namespace cadlod {

void cadSimplifyParameters(MeshModel& m, RichParameterList& par);
bool cadSimplify(MeshFilterInterface& plugin, MeshModel& m, const RichParameterList& par, vcg::CallBackPos* cb,
                 QString& error);

}  // namespace cadlod
