// buildLodSet for the cores' own mesh type, compiled once (lod_builder.h declares it).
#include "lod/lod_builder_impl.h"
#include "mesh/core_mesh.h"

namespace cadlod {

template LodSetResult buildLodSet<CoreMesh>(CoreMesh&, const LodSetOptions&, const std::function<CoreMesh&(int)>&,
                                            vcg::CallBackPos*);

}  // namespace cadlod
