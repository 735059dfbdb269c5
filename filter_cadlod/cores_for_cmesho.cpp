// The cores compiled for MeshLab's mesh type, once for the whole plugin.
#include <common/interfaces.h>

#include "simplify/best_of_trials_impl.h"

namespace cadlod {

template SimplifyStats simplify<CMeshO>(CMeshO&, const SimplifyParams&, vcg::CallBackPos*, const RunTogether&);
template SimplifyStats bestOfTrials<CMeshO>(CMeshO&, const SimplifyParams&, vcg::CallBackPos*, const RunTogether&);

}  // namespace cadlod
