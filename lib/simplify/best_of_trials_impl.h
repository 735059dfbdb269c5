// The weight-trials driver behind bestOfTrials() (best_of_trials.h). Included where it is
// compiled for a mesh type.
#pragma once

#include "simplify/best_of_trials.h"
#include "simplify/simplify_impl.h"
#include "simplify/weight_trials.h"

#include <chrono>
#include <vector>

namespace cadlod {

namespace detail {

// The parameters of the trial kept, and the log line of all the trials in stats.weightTrials.
template <class MeshType>
SimplifyParams chooseWeights(MeshType& m, const SimplifyParams& params, vcg::CallBackPos* progress,
                             const RunTogether& together, SimplifyStats& stats)
{
    // The trials run two at a time on copies (`together`).
    // Distances within the flat tolerance move no plane a viewer could see: the trials' pick
    // does not tell them apart (an exact result then wins on slivers alone).
    const double diagonal = liveDiagonal(m);
    const double distanceFloor = params.flatTolerance * diagonal;
    const std::vector<WeightTrial> trials = runWeightTrials(
        m, params,
        [&](CoreMesh& copy, const SimplifyParams& p) {
            return simplify(copy, p, nullptr, runInSequence);
        },
        progress, together, distanceFloor);
    const std::size_t best = keptTrial(trials, distanceFloor);
    stats.weightTrials = describeTrials(trials, best, diagonal, params);
    return best < trials.size() ? trialParams(params, trials[best].weights) : params;
}

}  // namespace detail

template <class MeshType>
SimplifyStats bestOfTrials(MeshType& m, const SimplifyParams& params, vcg::CallBackPos* progress,
                           const RunTogether& together)
{
    const auto start = std::chrono::steady_clock::now();
    SimplifyStats stats;
    if (!detail::readyToSimplify(m, params, stats))
        return stats;
    const SimplifyParams chosen =
        weightTrialsApply(m, params) ? detail::chooseWeights(m, params, progress, together, stats) : params;
    return simplifyWith(m, chosen, stats, start, progress, together);
}

}  // namespace cadlod
