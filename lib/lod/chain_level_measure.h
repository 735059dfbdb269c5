// How a LOD chain (lod_chain.h) measures a level against level 0: the symmetric Hausdorff
// distance (DistanceToLevelZero) beside the level's compactness, with as many sample points
// on the level's side as its faces call for.
#pragma once

#include "lod/distance_to_level_zero.h"
#include "measure/compactness.h"
#include "measure/hausdorff.h"
#include "support/run_together.h"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace cadlod {

// A coarse level is sampled with at most this many points per face (besides its vertices)
// when measured against level 0: its points stand far from level 0, where each lookup is
// slow, and a few dozen per face find the largest distance of a flat triangle to the
// surface it replaces (MeshLab's Hausdorff filter samples one point per vertex).
inline constexpr std::size_t kBackwardSamplesPerFace = 256;
// ...but never fewer than this many in all: a level of a few dozen faces, each large, would
// otherwise be sampled too sparsely to find its largest distance within the 5 % that an
// independent re-measurement may find beyond it.
inline constexpr std::size_t kMinBackwardSamples = 32768;
// ...and at most this many (or as many as level 0 has, where that is more, or what the
// caller asked for). A coarse level's largest distance may stand over a narrow strip of one
// large face, which random points find only by luck; `chain_bench --verify` measures the
// levels again with many more points to check the cap finds it.
inline constexpr std::size_t kBackwardSamplesCap = 400000;

struct ChainLevelMeasures {
    SymmetricHausdorff distance;
    CompactnessStats compactness;
};

template <class MeshType>
class ChainLevelMeasure
{
public:
    // `hausdorffSamples`: LodChainOptions::hausdorffSamples (0: automatic).
    ChainLevelMeasure(MeshType& original, std::size_t hausdorffSamples, double diagonal, RunTogether together)
        : ChainLevelMeasure(original, levelZeroSamples(original, hausdorffSamples), hausdorffSamples != 0,
                            diagonal, std::move(together))
    {
    }

    // Level 0's points and index, made once before the first level is measured; a caller
    // may run this beside other work.
    void prepare() { distance_.prepare(); }

    ChainLevelMeasures operator()(MeshType& level)
    {
        ChainLevelMeasures m;
        const std::size_t backwardSamples =
            std::min(backwardCap_, std::max(kMinBackwardSamples, kBackwardSamplesPerFace * std::size_t(level.fn)));
        together_([&] { m.distance = distance_(level, backwardSamples); },
                  [&] { m.compactness = meshCompactness(level); });
        return m;
    }

    // The time the measures took so far (LodSetResult::measureSeconds).
    double seconds() const { return distance_.seconds(); }

private:
    static std::size_t levelZeroSamples(const MeshType& original, std::size_t hausdorffSamples)
    {
        return hausdorffSamples ? hausdorffSamples
                                : std::clamp<std::size_t>(std::size_t(original.fn), 100000, 500000);
    }

    ChainLevelMeasure(MeshType& original, std::size_t samples, bool samplesGiven, double diagonal,
                      RunTogether together)
        : distance_(original, samples, diagonal, together),
          backwardCap_(samplesGiven ? samples : std::max(samples, kBackwardSamplesCap)),
          together_(std::move(together))
    {
    }

    DistanceToLevelZero<MeshType> distance_;
    std::size_t backwardCap_;  // the most points a level is sampled with
    RunTogether together_;
};

}  // namespace cadlod
