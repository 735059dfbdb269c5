// Which built levels a LOD set keeps (selectUsefulLevels, lod_plan.h), applied to a
// result and its level meshes.
#pragma once

#include "lod/lod_builder.h"
#include "lod/lod_plan.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace cadlod::detail {

// Drops the levels selectUsefulLevels rejects from `result` and `meshes` (parallel to
// result.levels), records them, and renumbers the rest.
template <class MeshType>
void keepUsefulLevels(LodSetResult& r, std::vector<MeshType*>& meshes)
{
    const double errorFloor = std::max(kRelativeErrorFloor * r.modelSize, 1e-12);
    const LevelSelection selection = selectUsefulLevels(r.levels, errorFloor);
    LodSetResult kept = r;
    kept.levels.clear();
    kept.compactness.clear();
    kept.steps.clear();
    kept.distance.clear();
    std::vector<MeshType*> keptMeshes;
    // What gave way for a dropped level is told by the next kept one (its lines say what
    // gave way since the level before it).
    std::vector<std::string> untold;
    for (std::size_t k = 0; k < r.levels.size(); ++k) {
        if (!selection.keep[k]) {
            kept.droppedLevels.push_back(int(k));
            // Named by where it stood among the kept levels: their numbers are the ones the user sees.
            kept.warnings.push_back("a candidate level after level " + std::to_string(kept.levels.empty() ? 0 : kept.levels.size() - 1) + " (" +
                                    std::to_string(r.levels[k].faces) + " faces) dropped: " + selection.why[k]);
            if (k > 0 && k - 1 < r.steps.size())
                for (const std::string& line : r.steps[k - 1].relaxed)
                    untold.push_back("(dropped level " + std::to_string(k) + ") " + line);
            continue;
        }
        LodLevel level = r.levels[k];
        level.level = int(kept.levels.size());
        kept.levels.push_back(level);
        kept.compactness.push_back(r.compactness[k]);
        if (k > 0) {
            kept.steps.push_back(r.steps[k - 1]);
            auto& lines = kept.steps.back().relaxed;
            lines.insert(lines.begin(), untold.begin(), untold.end());
            untold.clear();
            kept.distance.push_back(r.distance[k - 1]);
        }
        keptMeshes.push_back(meshes[k]);
    }
    r = std::move(kept);
    meshes = std::move(keptMeshes);
}

}  // namespace cadlod::detail
