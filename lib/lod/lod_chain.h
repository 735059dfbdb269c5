// A LOD chain planned by screen-space error (design.md §5): what a VR engine needs, from
// the distance where the model fills the viewport out to where it is a few pixels high.
//
// Level k is meant for the distance d_k = d_first * ratio^(k-1), from d_first = d_fill / 32
// (d_fill: where the model's diagonal spans the viewport height; a viewer may come closer,
// and an over-tessellated CAD part loses most of its triangles there already). A distance
// whose mesh is less than 10 % lighter than the last level's adds no level. Its budget is
// the error that projects to the pixel error there. Halfway between two planned distances
// (a factor of √ratio) the model is copied too; the copy becomes a level only where the
// next level's measured error overshoots, landing more than the ratio beyond the last
// level's, so that the chain has no gap wider than the ratio where it can fill one.
// Collapse sessions run with that budget as their maximum error, one per piece of the
// model (collapse_buckets.h: whole connected components, side by side), each for the whole
// chain (the quadrics carry the whole history, so errors do not restart at each level);
// there features (part borders too, when they are kept) and whole small components give
// way as soon as breaking them costs less than the budget (simplify.h). Collapses are
// ranked by their quadric error, but held to the budget by the distance they open too
// (far_field.h: from level 0's points to the faces they make, and back from those faces to
// level 0): how far the quadric error is from that distance varies from one collapse to
// the next, and a bound on the quadric error alone had to allow for the worst of them. From
// where the model is kFarFieldPixels high, the pieces are in the far field: operations are
// ranked by that distance too, since the quadrics' error no longer tells how far a few
// hundred faces stand from thousands. The pieces together are then taken as level k and
// measured against level 0 (symmetric Hausdorff) while the sessions go on to the next level
// (the caller's RunTogether may run both at once); the ratio between the measured error
// and the largest distance opened steers the distance bound from the level after next, so
// an estimate that falls short of what a viewer sees is corrected level by level.
// Where the model is `proxyPixels` high, a proxy is made: one axis-aligned box per remaining connected component (a box per part): the box of its
// vertices or of its surface without what sticks out (a pin, a leg), whichever measures
// closer. Collapse levels go on beyond it only while the box's measured error is still
// above the budget and they are heavier than the box (a jack's deep socket keeps its box
// far off). Where the model is a couple of pixels high, a tetrahedron in each box follows
// (inscribed, or in the box grown about its centre, whichever measures closest), and last
// one tetrahedron for the whole model.
//
// Every level's range comes from its measured error (lod_plan.h): it is drawn from where
// that error projects to the pixel error, until the next level's does. The last level is
// drawn for ever unless `cullPixels` is set.
//
// This header declares buildLodChain; lod_chain_builder.h defines it, step by step. It is
// compiled once for CoreMesh (lod_chain.cpp) and, in the MeshLab plugin, for CMeshO
// (cores_for_cmesho.cpp).
#pragma once

#include "lod/lod_builder.h"  // LodSetResult
#include "lod/lod_plan.h"
#include "simplify/simplify_params.h"
#include "support/run_together.h"

#include <wrap/callback.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <string>

namespace cadlod {

struct LodChainOptions {
    ViewParams view;                  // camera and pixel error
    double distanceRatio = 2.0;       // between the distances of consecutive levels
    double proxyPixels = 8.0;         // the box proxy serves from where the model is this many px high
    double cullPixels = 0.0;          // > 0: not drawn once the model is smaller than this many px
    std::size_t hausdorffSamples = 0; // face samples per side; 0: as many as level-0 faces, 100 000 to 500 000
    SimplifyParams simplify;          // placement and protection; the budget is set per level
    int setId = 1;
    RunTogether runTogether;          // measuring a level beside the next collapses; empty: in sequence
    std::string distanceUnit = "model units";  // how the progress names distances
    double distanceScale = 1.0;                // ... after multiplying them by this
    // > 0: the first level is planned for this distance when it is farther than the usual
    // first distance; a cluster proxy, never drawn nearer, needs no level before it.
    double nearestDistance = 0.0;
    // > 0: no level is planned past this distance, the last one serving from there on; a
    // cluster proxy is drawn no farther than where its parent cluster's proxy takes over.
    double farthestDistance = 0.0;
};

// Where the model is this many pixels high (its diagonal), the pieces go into the far field
// (far_field.h): from there on they rank operations by the distance they open and are held
// to the budget by it. Chosen on the chain bench (docs/benchmarks.md).
inline constexpr double kFarFieldPixels = 64.0;
// The least compactness a collapse of a chain level may leave a face with (the simplifier's
// shape guard, simplify_params.h), before the far field, where a session held to its
// distance is judged by the distance alone (cad_edge_collapse.h).
inline constexpr double kChainMinCompactness = 0.05;
// Where the model is this many pixels high, a tetrahedron per component replaces its box.
inline constexpr double kTetrahedronPixels = 2.0;
// The first level is planned this many times closer than where the model fills the view.
inline constexpr double kCloseUpFactor = 32.0;

namespace detail {

inline double tanHalfFov(const ViewParams& view) { return std::tan(0.5 * view.fovYDegrees * M_PI / 180.0); }

// The geometric error that projects to the pixel error at distance d.
inline double errorBudgetAt(double d, const ViewParams& view)
{
    return view.pixelThreshold * 2.0 * d * tanHalfFov(view) / view.viewportHeightPx;
}

// Where a length `size` spans `pixels` pixels of the viewport height.
inline double distanceForPixels(double size, double pixels, const ViewParams& view)
{
    return size * view.viewportHeightPx / (2.0 * tanHalfFov(view) * pixels);
}

}  // namespace detail

// `newLevel(k)` returns an empty mesh for level k (k >= 1), as for buildLodSet; `working`
// is an empty mesh with what cadlod::simplify needs, left in an unspecified state.
// `newScratch` returns more such meshes, for the pieces of the model simplified side by
// side (collapse_buckets.h); they may go once the call returns. Empty: default-constructed
// meshes of the chain's own (enough where MeshType has no optional components to enable).
// The result has the same form as buildLodSet's; result.steps holds, per kept level, the
// collapse statistics up to it, whose `relaxed` lines say what gave way since the level
// before (and, for a large piece, that it started as two halves).
template <class MeshType>
LodSetResult buildLodChain(MeshType& original, MeshType& working, const LodChainOptions& options,
                           const std::function<MeshType&(int)>& newLevel, vcg::CallBackPos* progress = nullptr,
                           std::function<MeshType&()> newScratch = {});

// Compiled once (lod_chain.cpp).
struct CoreMesh;
extern template LodSetResult buildLodChain<CoreMesh>(CoreMesh&, CoreMesh&, const LodChainOptions&,
                                                     const std::function<CoreMesh&(int)>&, vcg::CallBackPos*,
                                                     std::function<CoreMesh&()>);

}  // namespace cadlod
