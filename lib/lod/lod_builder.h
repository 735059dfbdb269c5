// Building a LOD set (design.md §5) on any vcglib mesh type: each level is a copy of the
// previous level (or of the original) simplified with the CAD Quadric Edge Collapse to its
// planned face count, measured against the original (symmetric Hausdorff, compactness),
// and given switch distances from its error. The caller owns the level meshes: the
// MeshLab filter makes them layers, the tests keep them in a container.
#pragma once

#include "measure/compactness.h"
#include "measure/hausdorff.h"
#include "mesh/layer_metadata.h"
#include "lod/lod_plan.h"
#include "support/run_together.h"
#include "simplify/best_of_trials.h"

#include <vcg/complex/append.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <functional>
#include <optional>
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

namespace detail {

// A face by the bits of its corners' coordinates (as floats), corners in sorted order: the
// same face whichever corner comes first. What a level kept of level 0 has the same key
// there; bits, not values, so that every key orders (a NaN too).
using FaceKey = std::array<std::uint32_t, 9>;

template <class FaceType>
FaceKey faceKey(const FaceType& f)
{
    std::array<std::array<std::uint32_t, 3>, 3> corners;
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) {
            const float x = float(f.cP(j)[k]);
            std::memcpy(&corners[j][k], &x, sizeof x);
        }
    std::sort(corners.begin(), corners.end());
    FaceKey key;
    for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
            key[3 * j + k] = corners[j][k];
    return key;
}

// The keys of `m`'s live faces, sorted.
template <class MeshType>
std::vector<FaceKey> sortedFaceKeys(MeshType& m)
{
    std::vector<FaceKey> keys;
    for (const auto* f : liveFaces(m))
        keys.push_back(faceKey(*f));
    std::sort(keys.begin(), keys.end());
    return keys;
}

inline bool hasKey(const std::vector<FaceKey>& sortedKeys, const FaceKey& key)
{
    return std::binary_search(sortedKeys.begin(), sortedKeys.end(), key);
}

template <class FaceType>
bool hasFace(const std::vector<FaceKey>& sortedKeys, const FaceType& f)
{
    return hasKey(sortedKeys, faceKey(f));
}

}  // namespace detail

// The symmetric Hausdorff distance of levels to level 0 (`original`). Level 0's index and
// the keys of its faces are made once for all levels: by prepare(), which a caller may run
// beside other work, or by the first measure; its sample points are drawn for each level
// on the faces that level no longer has (once for all the levels that kept none of them).
// `together` runs the two sides, and each
// side's chunks, at once where it can (hausdorff.h: the figures do not depend on it).
template <class MeshType>
class DistanceToLevelZero
{
public:
    // A level switches by its maximum distance, measured from every point; the mean it
    // reports comes from every kMeanEvery-th point (hausdorff.h: the others are looked up in
    // full only when they could raise the maximum).
    static constexpr std::size_t kMeanEvery = 32;
    // A level's changed faces are measured at points splitting each edge into this many
    // pieces too (hausdorffSamples).
    static constexpr int kLevelEdgePieces = 8;

    DistanceToLevelZero(MeshType& original, std::size_t samples, double diagonal, RunTogether together)
        : original_(original), samples_(samples), diagonal_(diagonal), together_(std::move(together))
    {
    }

    void prepare()
    {
        if (!index_)
            together_([&] { facesOfLevelZero_ = detail::sortedFaceKeys(original_); },
                      [&] { index_.emplace(original_); });
    }

    // Each side's points go only to the faces the other side does not have: a face a level
    // kept as it was lies on level 0 all over, so a fine level's few changed faces, and the
    // level-0 faces they replace, are sampled densely (spread evenly, the random points
    // missed a level's largest distance by up to a quarter: chain_bench --verify). Level 0:
    // `samples` random points besides its vertices, and each such face's centroid and edge
    // midpoints where that adds at most a quarter of the points (a fillet's or a thread's
    // small faces; a board's level that kept a few large faces got them on all the rest, a
    // million points a level at 300k faces); the level: `backwardSamples` random points
    // besides its vertices and each such face's centroid, edge midpoints and the points that
    // split its edges into kLevelEdgePieces. A level held to its budget by the distance each
    // collapse opens from level 0's points (collapse_buckets.h) has its largest distance
    // between those points as often as not: the edge midpoints find it where random points
    // missed it by 7 % (the demo's level 3), the edge pieces next to a long face's corner.
    SymmetricHausdorff operator()(MeshType& level, std::size_t backwardSamples)
    {
        const auto start = std::chrono::steady_clock::now();
        prepare();
        SymmetricHausdorff h;
        together_(
            [&] { h.forward = fromLevelZero(level); },
            [&] {
                const auto moved = [&](const auto& f) { return !detail::hasFace(facesOfLevelZero_, f); };
                h.backward =
                    distancesToSurface(hausdorffSamples(level, backwardSamples, 2, true, moved, kLevelEdgePieces),
                                       *index_, nullptr, together_, kMeanEvery);
            });
        h.diagonal = diagonal_;
        seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return h;
    }

    // The time the measures took so far (LodSetResult::measureSeconds).
    double seconds() const { return seconds_; }

private:
    // The distances from level 0's points on the faces `level` no longer has. A level that
    // kept none of them (every coarse one) is measured from the points drawn on all of level
    // 0, the same random points each time: they are drawn once (on a million faces, drawing
    // them again for every level was a large share of a chain's time: docs/benchmarks.md).
    HausdorffStats fromLevelZero(MeshType& level)
    {
        const detail::ClosestFace<MeshType> closest(level);
        const std::vector<detail::FaceKey> levelFaces = detail::sortedFaceKeys(level);
        const auto inLevelZero = [&](const detail::FaceKey& key) { return detail::hasKey(facesOfLevelZero_, key); };
        const std::size_t kept = std::size_t(std::count_if(levelFaces.begin(), levelFaces.end(), inLevelZero));
        const std::size_t goneFaces = std::size_t(original_.fn) - std::min(kept, std::size_t(original_.fn));
        const bool everyFace = 4 * goneFaces <= samples_;
        if (kept == 0) {
            if (!onAllOfLevelZero_)
                onAllOfLevelZero_ = hausdorffSamples(original_, samples_, 1, everyFace);
            return distancesToSurface(*onAllOfLevelZero_, closest, nullptr, together_, kMeanEvery);
        }
        const auto gone = [&](const auto& f) { return !detail::hasFace(levelFaces, f); };
        return distancesToSurface(hausdorffSamples(original_, samples_, 1, everyFace, gone), closest, nullptr,
                                  together_, kMeanEvery);
    }

    MeshType& original_;
    std::size_t samples_;
    double diagonal_;
    RunTogether together_;
    std::optional<detail::ClosestFace<MeshType>> index_;
    std::vector<detail::FaceKey> facesOfLevelZero_;  // sorted
    std::optional<HausdorffSamples> onAllOfLevelZero_;  // drawn on every face of level 0
    double seconds_ = 0.0;
};

namespace detail {

// Copies `from` into `to`, keeping cadlod's part attributes.
template <class MeshType>
void copyWithParts(MeshType& to, MeshType& from)
{
    to.Clear();
    if (hasParts(from)) {
        facePartHandle(to);
        partTableHandle(to)() = partTableHandle(from)();
    }
    vcg::tri::Append<MeshType, MeshType>::MeshCopy(to, from, false, false);
}


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
            kept.warnings.push_back("level " + std::to_string(k) + " (" + std::to_string(r.levels[k].faces) +
                                    " faces) dropped: " + selection.why[k]);
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

}  // namespace detail

// `newLevel(k)` returns an empty mesh for level k (k >= 1) that stays valid until the
// call returns; the mesh must carry what cadlod::simplify needs (VF adjacency, marks).
// On success every level mesh, and `original`, carries its LodLevel attribute.
template <class MeshType>
LodSetResult buildLodSet(MeshType& original, const LodSetOptions& options,
                         const std::function<MeshType&(int)>& newLevel, vcg::CallBackPos* progress = nullptr)
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
