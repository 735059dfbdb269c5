// Building a LOD set (design.md §5) on any vcglib mesh type: each level is a copy of the
// previous level (or of the original) simplified with the CAD Quadric Edge Collapse to its
// planned face count, measured against the original (symmetric Hausdorff, compactness),
// and given switch distances from its error. The caller owns the level meshes: the
// MeshLab filter makes them layers, the tests keep them in a container.
//
// This header declares it; lod_builder_impl.h defines it. It is compiled once for CoreMesh
// (lod_builder.cpp) and, in the MeshLab plugin, for CMeshO (cores_for_cmesho.cpp).
#pragma once

#include "lod/lod_plan.h"
#include "measure/compactness.h"  // CompactnessStats
#include "measure/hausdorff.h"    // SymmetricHausdorff
#include "mesh/layer_metadata.h"  // the LodLevel each level mesh carries
#include "simplify/simplify_params.h"
#include "support/run_together.h"

#include <wrap/callback.h>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace cadlod {

struct LodSetOptions {
    std::string levels = "50 60 70 80 90";
    LevelSpec spec = LevelSpec::ReductionPercent;
    bool fromOriginal = false;          // false: level k is made from level k-1 (faster)
    ViewParams view;
    std::size_t hausdorffSamples = 0;   // face samples per side; 0: as many as level-0 faces
    SimplifyParams simplify;            // stop criteria are set per level
    int setId = 1;
    // Measuring a level beside simplifying the next, and that level's weight trials two at a
    // time (weight_trials.h); empty: in sequence. Either way the levels come out the same.
    RunTogether runTogether;
};

struct LodSetResult {
    std::string error;                       // non-empty: nothing usable was built
    // The kept levels, renumbered 0..n (level 0 = the original). Levels that would never be
    // shown are dropped (see selectUsefulLevels); the caller discards their meshes.
    std::vector<LodLevel> levels;
    std::vector<CompactnessStats> compactness;
    std::vector<SimplifyStats> steps;        // one per simplified level (level 1..n)
    std::vector<SymmetricHausdorff> distance;
    double modelSize = 0.0;                  // bbox diagonal of the original
    std::vector<int> droppedLevels;          // as numbered by newLevel(k)
    std::vector<std::string> warnings;       // why each dropped level was dropped
    // Time spent measuring levels (and candidate proxies) against level 0
    // (DistanceToLevelZero): on one thread the measure's share of the build; on two, most of
    // it runs beside the collapses.
    double measureSeconds = 0.0;
    bool ok() const { return error.empty(); }
};

// `newLevel(k)` returns an empty mesh for level k (k >= 1) that stays valid until the
// call returns; the mesh must carry what cadlod::simplify needs (VF adjacency, marks).
// On success every level mesh, and `original`, carries its LodLevel attribute.
template <class MeshType>
LodSetResult buildLodSet(MeshType& original, const LodSetOptions& options,
                         const std::function<MeshType&(int)>& newLevel, vcg::CallBackPos* progress = nullptr);

// Compiled once (lod_builder.cpp).
struct CoreMesh;
extern template LodSetResult buildLodSet<CoreMesh>(CoreMesh&, const LodSetOptions&,
                                                   const std::function<CoreMesh&(int)>&, vcg::CallBackPos*);

}  // namespace cadlod
