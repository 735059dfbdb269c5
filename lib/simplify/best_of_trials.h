// cadlod::bestOfTrials: what the command and the plugins run. Where the weight trials apply
// (weight_trials.h: a face target on a mesh small enough), copies of the mesh are simplified
// once per trial's weights, each result is measured against the input, and the mesh itself is
// then simplified once with the weights of the closest. Elsewhere it is simplify() itself.
#pragma once

#include "simplify/simplify.h"
#include "simplify/weight_trials.h"

#include <chrono>
#include <vector>

namespace cadlod {

namespace detail {

// vcglib's bit flags of one mesh type, taken for a scope and given back at its end.
template <class MeshType>
struct TakenFeatureBits {
    FeatureBits bits = takeFeatureBits<MeshType>();
    TakenFeatureBits() = default;
    TakenFeatureBits(const TakenFeatureBits&) = delete;
    TakenFeatureBits& operator=(const TakenFeatureBits&) = delete;
    ~TakenFeatureBits() { giveBackFeatureBits<MeshType>(bits); }
};

// The parameters of the trial kept, and the log line of all the trials in stats.weightTrials.
template <class MeshType>
SimplifyParams chooseWeights(MeshType& m, const SimplifyParams& params, vcg::CallBackPos* progress,
                             const RunTogether& together, SimplifyStats& stats)
{
    // The trials run two at a time on copies (`together`); vcglib's pool of bit flags is one
    // per mesh type and process, so the copies share one set taken here.
    const TakenFeatureBits<CoreMesh> trialBits;
    // Distances within the flat tolerance move no plane a viewer could see: the trials' pick
    // does not tell them apart (an exact result then wins on slivers alone).
    const double diagonal = liveDiagonal(m);
    const double distanceFloor = params.flatTolerance * diagonal;
    const std::vector<WeightTrial> trials = runWeightTrials(
        m, params,
        [&](CoreMesh& copy, const SimplifyParams& p) {
            return simplifySharing(copy, p, nullptr, runInSequence, &trialBits.bits);
        },
        progress, together, distanceFloor);
    const std::size_t best = keptTrial(trials, distanceFloor);
    stats.weightTrials = describeTrials(trials, best, diagonal, params);
    return best < trials.size() ? trialParams(params, trials[best].weights) : params;
}

}  // namespace detail

// Simplifies `m` in place with the weights of the best trial, where trials apply, else as
// simplify() does. `progress` may be null; `together` runs the trials two at a time, and the
// halves of a large mesh, or everything one after the other (the result is the same).
template <class MeshType>
SimplifyStats bestOfTrials(MeshType& m, const SimplifyParams& params, vcg::CallBackPos* progress = nullptr,
                           const RunTogether& together = runInSequence)
{
    const auto start = std::chrono::steady_clock::now();
    SimplifyStats stats;
    if (!detail::readyToSimplify(m, params, stats))
        return stats;
    const SimplifyParams chosen =
        weightTrialsApply(m, params) ? detail::chooseWeights(m, params, progress, together, stats) : params;
    return simplifyWith(m, chosen, stats, start, progress, together, nullptr);
}

}  // namespace cadlod
