// cadlod::bestOfTrials: what the command and the plugins run. Where the weight trials apply
// (weight_trials.h: a face target on a mesh small enough), copies of the mesh are simplified
// once per trial's weights, each result is measured against the input, and the mesh itself is
// then simplified once with the weights of the closest. Elsewhere it is simplify() itself.
//
// Compiled once per mesh type, as simplify() is; the implementation is best_of_trials_impl.h.
#pragma once

#include "simplify/simplify.h"

namespace cadlod {

// Simplifies `m` in place with the weights of the best trial, where trials apply, else as
// simplify() does. `progress` may be null; `together` runs the trials two at a time, and the
// halves of a large mesh, or everything one after the other (the result is the same).
template <class MeshType>
SimplifyStats bestOfTrials(MeshType& m, const SimplifyParams& params, vcg::CallBackPos* progress = nullptr,
                           const RunTogether& together = runInSequence);

extern template SimplifyStats bestOfTrials<CoreMesh>(CoreMesh&, const SimplifyParams&, vcg::CallBackPos*,
                                                     const RunTogether&);

}  // namespace cadlod
