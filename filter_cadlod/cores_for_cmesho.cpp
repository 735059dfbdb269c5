// The cores' templates the plugin calls on MeshLab's mesh type, compiled once here; the
// plugin's other files include only their declarations.
#include <common/ml_mesh_type.h>

#include "lod/lod_builder_impl.h"
#include "lod/lod_chain_builder.h"
#include "simplify/best_of_trials_impl.h"

namespace cadlod {

template SimplifyStats simplify<CMeshO>(CMeshO&, const SimplifyParams&, vcg::CallBackPos*, const RunTogether&);
template SimplifyStats bestOfTrials<CMeshO>(CMeshO&, const SimplifyParams&, vcg::CallBackPos*, const RunTogether&);
template LodSetResult buildLodSet<CMeshO>(CMeshO&, const LodSetOptions&, const std::function<CMeshO&(int)>&,
                                          vcg::CallBackPos*);
template LodSetResult buildLodChain<CMeshO>(CMeshO&, CMeshO&, const LodChainOptions&,
                                            const std::function<CMeshO&(int)>&, vcg::CallBackPos*,
                                            std::function<CMeshO&()>);

}  // namespace cadlod
