// The simplifier compiled for the cores' mesh type.
#include "mesh/core_mesh.h"
#include "simplify/best_of_trials_impl.h"

namespace cadlod {

template SimplifyStats simplify<CoreMesh>(CoreMesh&, const SimplifyParams&, vcg::CallBackPos*, const RunTogether&);
template SimplifyStats bestOfTrials<CoreMesh>(CoreMesh&, const SimplifyParams&, vcg::CallBackPos*,
                                              const RunTogether&);

}  // namespace cadlod
