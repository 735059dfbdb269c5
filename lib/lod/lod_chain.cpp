// buildLodChain for the cores' own mesh type, compiled once (lod_chain.h declares it).
#include "lod/lod_chain_builder.h"
#include "mesh/core_mesh.h"

namespace cadlod {

template LodSetResult buildLodChain<CoreMesh>(CoreMesh&, CoreMesh&, const LodChainOptions&,
                                              const std::function<CoreMesh&(int)>&, vcg::CallBackPos*,
                                              std::function<CoreMesh&()>);

}  // namespace cadlod
