// cadlod::simplify: runs the CAD Quadric Edge Collapse once on a vcglib triangle mesh with VF
// adjacency and per-vertex marks (CoreMesh, or MeshLab's CMeshO with MM_VERTFACETOPO |
// MM_VERTMARK). Deleted elements are left in place (m.fn/m.vn are right); compact the
// containers afterwards if needed. best_of_trials.h first tries several weights on copies.
//
// Compiled once per mesh type: for CoreMesh in cadlod::simplify, for CMeshO in the plugin.
// The implementation, for another mesh type and for tests of the session's internals, is
// simplify_impl.h.
#pragma once

#include "simplify/simplify_params.h"
#include "support/run_together.h"

#include <cstring>  // before callback.h, which uses it without including it

#include <wrap/callback.h>

namespace cadlod {

struct CoreMesh;

// Simplifies `m` in place, once, with `params` as they are. `progress` may be null.
// `together` runs two tasks at once, or one after the other (the result is the same): the
// two halves of a large mesh (collapse_halves.h).
template <class MeshType>
SimplifyStats simplify(MeshType& m, const SimplifyParams& params, vcg::CallBackPos* progress = nullptr,
                       const RunTogether& together = runInSequence);

extern template SimplifyStats simplify<CoreMesh>(CoreMesh&, const SimplifyParams&, vcg::CallBackPos*,
                                                 const RunTogether&);

}  // namespace cadlod
