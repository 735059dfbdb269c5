// How far a LOD level stands from level 0: the symmetric Hausdorff distance, measured only
// where the level changed level 0's faces (a face kept as it was lies on level 0 all over).
#pragma once

#include "measure/hausdorff.h"
#include "support/run_together.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

namespace cadlod {

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
    // miss it, the edge pieces next to a long face's corner.
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
    // them again for every level would take a large share of a chain's time).
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

}  // namespace cadlod
