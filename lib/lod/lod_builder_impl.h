// buildLodSet (lod_builder.h): each level simplified from the one before it (or from the
// original), measured against level 0 beside the next level's simplification.
#pragma once

#include "lod/copy_with_parts.h"
#include "lod/distance_to_level_zero.h"
#include "lod/lod_builder.h"
#include "lod/lod_plan.h"
#include "lod/useful_levels.h"
#include "measure/compactness.h"
#include "measure/hausdorff.h"
#include "mesh/layer_metadata.h"
#include "simplify/best_of_trials.h"
#include "support/run_together.h"

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

namespace cadlod {

template <class MeshType>
LodSetResult buildLodSet(MeshType& original, const LodSetOptions& options,
                         const std::function<MeshType&(int)>& newLevel, vcg::CallBackPos* progress)
{
    LodSetResult result;
    const LevelPlan plan = planLevels(options.levels, options.spec, original.fn);
    if (!plan.ok()) {
        result.error = "level list: " + plan.error;
        return result;
    }
    result.warnings = plan.warnings;
    const std::size_t samples = options.hausdorffSamples ? options.hausdorffSamples : std::size_t(original.fn);
    std::vector<MeshType*> meshes{&original};

    LodLevel level0;
    level0.setId = options.setId;
    level0.faces = original.fn;
    const vcg::Box3d box = liveVertexBox(original);
    if (!box.IsNull())
        level0.center = {box.Center()[0], box.Center()[1], box.Center()[2]};
    result.modelSize = box.IsNull() ? 0.0 : box.Diag();
    result.levels.push_back(level0);
    result.compactness.push_back(meshCompactness(original));

    // Level k is measured while level k+1 is simplified (from a copy of it, or of the
    // original): the two share nothing mutable. The simplification runs its weight trials
    // two at a time too: they take most of a level's time, the measure far less.
    const RunTogether together = options.runTogether ? options.runTogether : RunTogether(runInSequence);
    const int count = int(plan.targetFaces.size());
    DistanceToLevelZero<MeshType> distanceToOriginal(original, samples, result.modelSize, together);
    SymmetricHausdorff distance;
    CompactnessStats compactness;
    auto measure = [&](MeshType& mesh) {
        distance = distanceToOriginal(mesh, samples);
        compactness = meshCompactness(mesh);
    };
    auto addLevel = [&](MeshType& mesh, int k) {
        LodLevel level = level0;
        level.level = k;
        level.faces = mesh.fn;
        level.reduction = original.fn ? 1.0 - double(mesh.fn) / original.fn : 0.0;
        level.hausdorffMax = distance.max();
        level.hausdorffMean = distance.mean();
        result.levels.push_back(level);
        result.distance.push_back(distance);
        result.compactness.push_back(compactness);
    };
    for (int k = 1; k <= count + 1; ++k) {
        MeshType* previous = k > 1 ? meshes.back() : nullptr;  // made, not yet measured
        MeshType* mesh = nullptr;
        SimplifyStats stats;
        if (k <= count) {
            mesh = &newLevel(k);
            detail::copyWithParts(*mesh, options.fromOriginal ? original : *meshes.back());
            vcg::tri::Allocator<MeshType>::CompactEveryVector(*mesh);
        }
        SimplifyParams params = options.simplify;
        params.targetFaces = k <= count ? plan.targetFaces[std::size_t(k - 1)] : 0;
        params.reductionPerc = 0.0;
        params.maxError = 0.0;
        if (progress)
            progress(100 * (k - 1) / count, (k <= count ? "Simplifying level " + std::to_string(k)
                                                          : "Measuring level " + std::to_string(count)).c_str());
        together([&] { if (previous) measure(*previous); },
                 [&] { if (mesh) stats = bestOfTrials(*mesh, params, nullptr, together); });
        if (previous)
            addLevel(*previous, k - 1);
        if (!mesh)
            break;
        vcg::tri::Allocator<MeshType>::CompactEveryVector(*mesh);
        if (!stats.ok) {
            result.error = "level " + std::to_string(k) + ": " + stats.message;
            return result;
        }
        result.steps.push_back(stats);
        meshes.push_back(mesh);
    }

    result.measureSeconds = distanceToOriginal.seconds();
    detail::keepUsefulLevels(result, meshes);
    const double errorFloor = std::max(kRelativeErrorFloor * result.modelSize, 1e-12);
    assignSwitchDistances(result.levels, result.modelSize, options.view, errorFloor);
    for (std::size_t k = 0; k < meshes.size(); ++k)
        lodLevelHandle(*meshes[k])() = result.levels[k];
    return result;
}

}  // namespace cadlod
