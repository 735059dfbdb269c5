// Weight trials: how much a large face's plane weighs in the quadrics
// (SimplifyParams::largeFaceWeight) and what breaking a feature costs (featurePenalty) decide
// what a far reduction gives up. Light planes, and a small part keeps its tabs and bumps
// while a long cylinder is merged into a few facets; heavy, and the cylinder stays round
// while the small details go, and all the more readily when their creases cost no more than
// their distance. Which is closer to the input depends on the part, so a mesh small enough to
// simplify in about a second is simplified once per pair of weights on a copy, each result is
// measured against the input (symmetric Hausdorff distance, the share a viewer sees lit
// differently, sliver share), and the weights of the closest are used, or the closest run
// once more with slivers removed first where that costs nothing a viewer sees
// (kSliversFirstShare). simplify() then runs with those weights on the mesh itself; the
// trials never touch it.
#pragma once

#include "measure/compactness.h"
#include "measure/hausdorff.h"
#include "measure/input_surface.h"
#include "mesh/layer_metadata.h"
#include "support/run_together.h"
#include "measure/shading_deviation.h"
#include "simplify/simplify_params.h"

#include "mesh/core_mesh.h"

#include <vcg/complex/algorithms/update/topology.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace cadlod {

// One trial's weights: its plane weight as a multiple of the caller's largeFaceWeight, and
// whether features keep the caller's featurePenalty or cost only their quadric error (a
// penalty of 1; a caller's hard locks, 0, stay locks). A face turned away from the input
// surface keeps the caller's price either way (facingPenalty). keepSmoothJoins: the trial
// folds no smooth join past the crease angle (SimplifyParams::keepSmoothJoins).
// constraintPlanes: the weight of the planes that hold creases and boundaries in place, as a
// multiple of the caller's boundaryWeight. shapeGuard: the caller's minCompactness; off, a
// collapse may make a sliver (SimplifyParams::minCompactness 0).
struct TrialWeights {
    double plane = 1.0;
    bool featuresPriced = true;
    bool keepSmoothJoins = false;
    double constraintPlanes = 1.0;
    bool shapeGuard = true;
    double sliversFirst = 1.0;
};
// The trials, the caller's own weights first. The heaviest plane weight runs with features
// at their quadric cost, once with their constraint planes and once without: a part whose
// long cylinders decide what a viewer sees (a battery holder's trough) gives up its small
// creased details for them, and without the planes a detail's crease costs no more than the
// faces it bends (a chip's leads, a board's parts at 95 %). One keeps smooth joins: a part
// whose fillets a viewer sees around its outline (a transformer's bobbin, a pump cover) keeps
// them drawn round and gives up distance elsewhere. One runs the caller's weights with the
// constraint planes at a quarter, at every target: a crease vertex may then leave its place
// on a curved crease where that makes fewer slivers, judged like the others by how close the
// result stays. The last
// runs without the shape guard, at near targets (kUnguardedTrialShare), and with the
// constraint planes at a tenth: on a fine part's curved creases (a chip lead's bend and the
// strips of its sides) the planes hold crease vertices whose going costs nothing a viewer
// sees, and the guard keeps the strips' slivers; without both the result is often closer
// and has fewer slivers.
inline constexpr TrialWeights kTrials[] = {
    {1.0, true, false},          // the caller's weights
    {10.0, true, false},         // heavier planes
    {40.0, true, false},         // heavier planes
    {200.0, false, false},       // features at their cost
    {10.0, true, true},          // keeping smooth joins
    {200.0, false, false, 0.0},  // features at their cost, no constraint planes
    {1.0, true, false, 0.25},    // the constraint planes at a quarter
    {1.0, true, false, 0.1, false}};  // no shape guard, the constraint planes at a tenth (near targets only)
// Features go at their cost, and smooth joins are kept, only where the target leaves at most
// this share of the faces: there, keeping every crease takes the faces the large surfaces
// need; above it, a feature keeps its price (a tube's rim stays on its polyline at 75 %). The
// far reductions are where coarse fillets fold, and each trial costs a run.
inline constexpr double kFeaturesAtCostShare = 0.1;
// The trial without the shape guard runs only where the target leaves at least this share of
// the faces. There the collapses coarsen the input's own strips of slivers (a chip lead's
// bend, a bottle's fillets), which the guard would keep: without it the result is often
// closer and has fewer slivers. Farther down the guard is what keeps the faces compact, and
// the trials' pick, judging slivers only beyond a margin, took the unguarded result where it
// cost slivers.
inline constexpr double kUnguardedTrialShare = 0.5;
// A sliver share more than this above the lowest of the trials counts against a trial, as
// one more "best distance" per kTrialSliverStep beyond it: a heavier weight may buy its
// distance with slivers, and that is not closer to the input.
inline constexpr double kTrialSliverMargin = 0.01;
inline constexpr double kTrialSliverStep = 0.05;
// A trial's shading deviation (shading_deviation.h) over the lowest of the trials counts
// this much against it, beside its distance over the lowest; below kTrialShadingFloor of the
// surfaces, shading differences count as that floor (too few to tell trials apart). Chosen
// on the tuning corpus (docs/benchmarks.md).
inline constexpr double kTrialShadingWeight = 0.7;
inline constexpr double kTrialShadingFloor = 0.005;
// Each face a trial turns away from the input surface nearest it (lit as the far side)
// beyond the fewest any trial turns counts as one more "best distance" against it: a turned
// face is taken only for a distance more than halved.
inline constexpr double kTrialTurnedFaceWeight = 1.0;
// Seeds of the trials' surface samples (the bench and the report use others), and the
// fewest samples per side: the largest distance of a coarse result is a spot a few
// thousand samples miss, and a trial that misses it looks closer than it is.
inline constexpr unsigned kTrialSeedForward = 101, kTrialSeedBackward = 102;
inline constexpr std::size_t kTrialMinSamples = 100000;
// A trial is judged by the largest distance only, so most of those points need not be
// looked up in full: one in kTrialFullLookupEvery is, and the others only where no face
// lies within the largest distance found so far (distancesToSurface's `meanEvery`; the
// maximum is exact, the same as from full lookups of every point).
inline constexpr std::size_t kTrialFullLookupEvery = 64;
// Points per side the shading deviation is measured with, and their seed.
inline constexpr std::size_t kTrialShadingSamples = 50000;
inline constexpr unsigned kTrialShadingSeed = 103;

struct WeightTrial {
    TrialWeights weights;    // what the trial ran with (trialParams)
    double hausdorff = 0.0;  // symmetric maximum, model units
    double slivers = 0.0;    // share of faces with compactness < 0.1
    double shading = 0.0;    // share of the surfaces lit visibly differently (shading_deviation.h)
    bool reached = false;    // the trial reached its face target
    int turned = 0;          // faces turned away from the input surface nearest them (input_surface.h)
};

// The caller's parameters with a trial's weights, for the trial and for the run with the
// weights kept. The facing price stays the caller's.
inline SimplifyParams trialParams(const SimplifyParams& caller, const TrialWeights& w)
{
    SimplifyParams p = caller;
    p.largeFaceWeight = caller.largeFaceWeight * w.plane;
    p.facingPenalty = facingPenaltyOf(caller);
    p.keepSmoothJoins = caller.keepSmoothJoins || w.keepSmoothJoins;
    p.boundaryWeight = caller.boundaryWeight * w.constraintPlanes;
    if (!w.shapeGuard)
        p.minCompactness = 0.0;
    p.sliverFirstShare = caller.sliverFirstShare * w.sliversFirst;
    if (!w.featuresPriced && caller.featurePenalty > 0)
        p.featurePenalty = std::min(caller.featurePenalty, 1.0);
    p.weightTrialsMaxFaces = 0;
    return p;
}

// Whether a trial runs for `caller` toward `target` faces of an input of `faces`: the plane
// weights with the caller's feature price always; features at their cost and smooth joins
// only where the target leaves at most kFeaturesAtCostShare of the faces, and smooth joins
// only toward a target above 0 (the shape guards they are one of relax only toward a face
// target). Without constraint planes to weigh (boundaryWeight 0), a trial that varies only
// them would repeat another; the one without the shape guard still differs.
inline bool trialRunsAt(const TrialWeights& w, const SimplifyParams& caller, int target, int faces)
{
    if (!w.shapeGuard)
        return caller.minCompactness > 0 && target >= kUnguardedTrialShare * faces - 0.5;
    if (w.constraintPlanes != 1.0 && caller.boundaryWeight <= 0)
        return false;
    const bool farTarget = target <= kFeaturesAtCostShare * faces + 0.5;
    if (w.keepSmoothJoins)
        return farTarget && target > 0;
    return w.featuresPriced || farTarget;
}

// Whether simplify() runs trials for this mesh and these parameters: a face target, a
// plane weight to vary, the whole mesh to work on, and a mesh below the size limit.
template <class MeshType>
bool weightTrialsApply(const MeshType& m, const SimplifyParams& p)
{
    const bool faceTarget = p.targetFaces > 0 || p.reductionPerc > 0;
    return faceTarget && p.weightTrialsMaxFaces > 0 && m.fn < p.weightTrialsMaxFaces && p.largeFaceWeight > 0 &&
           !p.selectedOnly;
}

// The kept weights run once more with the collapses that remove a sliver along its shortest
// edge ranked at this share of their priority (SimplifyParams::sliverFirstShare): among
// collapses of about the same error those go first, and fewer slivers are left. Ranked by
// anything but the error the largest distance may grow, so the result is kept only where it
// costs next to nothing a viewer sees: its distance within kSliversFirstDistance times the
// kept trial's, its shading within kSliversFirstShading times (kTrialShadingFloor alike), no
// more faces turned, and at least kTrialSliverMargin fewer slivers (docs/benchmarks.md,
// "Slivers first, where it costs nothing").
inline constexpr double kSliversFirstShare = 0.7;
inline constexpr double kSliversFirstDistance = 1.1;
inline constexpr double kSliversFirstShading = 1.15;

// Whether a trial is the kept weights run again slivers first (and not one of kTrials).
inline bool isSliversFirstRun(const WeightTrial& t) { return t.weights.sliversFirst != 1.0; }

// The closest trial: the lowest sum of its Hausdorff distance over the least of the trials
// and its shading deviation over the least (kTrialShadingWeight), a trial's excess slivers
// (kTrialSliverStep) and every face it turns away from the input surface beyond the fewest
// (kTrialTurnedFaceWeight) counted against it. Trials that stopped above their target are
// taken only when none reached it. Distances below `distanceFloor` (model units) count as
// that floor: a result a hair from exact is not many times farther than an exact one.
inline std::size_t closestTrial(const std::vector<WeightTrial>& trials, double distanceFloor = 0.0)
{
    const bool anyReached = std::any_of(trials.begin(), trials.end(),
                                        [](const WeightTrial& t) { return t.reached && !isSliversFirstRun(t); });
    auto candidate = [&](const WeightTrial& t) { return (t.reached || !anyReached) && !isSliversFirstRun(t); };
    int fewestTurned = std::numeric_limits<int>::max();
    for (const WeightTrial& t : trials)
        if (candidate(t))
            fewestTurned = std::min(fewestTurned, t.turned);
    double leastDistance = std::numeric_limits<double>::max(), leastSlivers = 1.0, leastShading = 1.0;
    for (const WeightTrial& t : trials)
        if (candidate(t)) {
            leastDistance = std::min(leastDistance, t.hausdorff);
            leastSlivers = std::min(leastSlivers, t.slivers);
            leastShading = std::min(leastShading, t.shading);
        }
    auto score = [&](const WeightTrial& t) {
        const double least = std::max(leastDistance, distanceFloor), own = std::max(t.hausdorff, distanceFloor);
        const double distance = least > 0 ? own / least : (own > 0 ? 2.0 : 1.0);
        const double shading =
            std::max(t.shading, kTrialShadingFloor) / std::max(leastShading, kTrialShadingFloor);
        return distance + kTrialShadingWeight * shading +
               std::max(0.0, t.slivers - leastSlivers - kTrialSliverMargin) / kTrialSliverStep +
               kTrialTurnedFaceWeight * (t.turned - fewestTurned);
    };
    std::size_t best = trials.size();
    for (std::size_t i = 0; i < trials.size(); ++i)
        if (candidate(trials[i]) && (best == trials.size() || score(trials[i]) < score(trials[best])))
            best = i;
    return best;
}

// Whether `refined`, the kept trial `kept` run again slivers first, is kept instead: see
// kSliversFirstShare.
inline bool sliversFirstKept(const WeightTrial& refined, const WeightTrial& kept, double distanceFloor)
{
    const bool closeEnough = std::max(refined.hausdorff, distanceFloor) <=
                             kSliversFirstDistance * std::max(kept.hausdorff, distanceFloor);
    const bool shadedAlike = std::max(refined.shading, kTrialShadingFloor) <=
                             kSliversFirstShading * std::max(kept.shading, kTrialShadingFloor);
    return (refined.reached || !kept.reached) && refined.turned <= kept.turned && closeEnough && shadedAlike &&
           refined.slivers <= kept.slivers - kTrialSliverMargin;
}

// The trial whose weights simplify the mesh: the closest of kTrials (closestTrial), or its
// run slivers first when that is kept (sliversFirstKept). trials.size() when there is none.
inline std::size_t keptTrial(const std::vector<WeightTrial>& trials, double distanceFloor = 0.0)
{
    const std::size_t best = closestTrial(trials, distanceFloor);
    if (best == trials.size())
        return best;
    for (std::size_t i = 0; i < trials.size(); ++i)
        if (isSliversFirstRun(trials[i]) && sliversFirstKept(trials[i], trials[best], distanceFloor))
            return i;
    return best;
}

namespace detail {

// What the simplifier reads of `from`, as a CoreMesh: points, faces, face colours (white
// where it has none: its colour borders are features), part ids and the part table.
template <class MeshType>
void copyForTrial(CoreMesh& to, MeshType& from)
{
    to.Clear();
    const bool parts = vcg::tri::HasPerFaceAttribute(from, kPartAttribute);
    const bool colors = vcg::tri::HasPerFaceColor(from);
    auto vi = vcg::tri::Allocator<CoreMesh>::AddVertices(to, from.vn);
    std::vector<int> index(from.vert.size(), -1);
    for (std::size_t i = 0; i < from.vert.size(); ++i)
        if (!from.vert[i].IsD()) {
            index[i] = int(vi - to.vert.begin());
            vi->P() = vcg::Point3f::Construct(from.vert[i].cP());
            ++vi;
        }
    auto partOf = parts ? facePartHandle(from) : typename MeshType::template PerFaceAttributeHandle<int>();
    auto trialPartOf = parts ? facePartHandle(to) : CoreMesh::PerFaceAttributeHandle<int>();
    if (hasParts(from))
        partTableHandle(to)() = partTableHandle(from)();
    auto fi = vcg::tri::Allocator<CoreMesh>::AddFaces(to, from.fn);
    for (auto& f : from.face) {
        if (f.IsD())
            continue;
        for (int k = 0; k < 3; ++k)
            fi->V(k) = &to.vert[std::size_t(index[std::size_t(vcg::tri::Index(from, f.cV(k)))])];
        fi->C() = colors ? f.cC() : vcg::Color4b(vcg::Color4b::White);
        if (parts)
            trialPartOf[*fi] = partOf[f];
        ++fi;
    }
    vcg::tri::UpdateTopology<CoreMesh>::VertexFace(to);
}

// "0.2", or "1 with feature penalty 1" where the trial's penalty is not the caller's, and
// what else differs from the caller's parameters.
inline std::string describeWeights(const char* what, const SimplifyParams& caller, const TrialWeights& w)
{
    const SimplifyParams p = trialParams(caller, w);
    char text[160];
    int n = std::snprintf(text, sizeof text, "%s%s%.4g", what, *what ? " " : "", p.largeFaceWeight);
    if (p.featurePenalty != caller.featurePenalty)
        n += std::snprintf(text + n, sizeof text - std::size_t(n), " with feature penalty %.4g", p.featurePenalty);
    if (p.boundaryWeight != caller.boundaryWeight)
        n += std::snprintf(text + n, sizeof text - std::size_t(n), ", constraint planes x %.4g", w.constraintPlanes);
    if (w.keepSmoothJoins)
        n += std::snprintf(text + n, sizeof text - std::size_t(n), " keeping smooth joins");
    if (p.minCompactness != caller.minCompactness)
        n += std::snprintf(text + n, sizeof text - std::size_t(n), ", no shape guard");
    if (p.sliverFirstShare != caller.sliverFirstShare)
        std::snprintf(text + n, sizeof text - std::size_t(n), ", slivers first x %.4g", w.sliversFirst);
    return text;
}

inline std::string describeTrials(const std::vector<WeightTrial>& trials, std::size_t chosen, double diagonal,
                                  const SimplifyParams& caller)
{
    std::string line = "plane weights tried (Hausdorff % of the diagonal, shading %, slivers %, faces turned):";
    char item[128];
    for (std::size_t i = 0; i < trials.size(); ++i) {
        std::snprintf(item, sizeof item, " (%.4f, %.2f, %.1f, %d%s)",
                      diagonal > 0 ? 100 * trials[i].hausdorff / diagonal : 0.0, 100 * trials[i].shading,
                      100 * trials[i].slivers, trials[i].turned, trials[i].reached ? "" : ", short of the target");
        line += (i ? "; " : " ") + describeWeights("", caller, trials[i].weights) + item;
    }
    if (chosen < trials.size())
        line += "; kept " + describeWeights("", caller, trials[chosen].weights);
    return line;
}

}  // namespace detail

// Simplifies copies of `m` once per weight with `simplifyCopy(copy, params)` and returns
// the trials, measured against `m` (unchanged), and last the closest of them run again
// slivers first (keptTrial chooses between them; `distanceFloor` as for closestTrial).
// `together` runs two trials at once (each on its own copy; the measures of the input are
// only read), or one after the other. `progress` (may be null) is told of each pair, from
// the calling thread.
template <class MeshType, class SimplifyCopy>
std::vector<WeightTrial> runWeightTrials(MeshType& m, const SimplifyParams& params, const SimplifyCopy& simplifyCopy,
                                         vcg::CallBackPos* progress, const RunTogether& together = runInSequence,
                                         double distanceFloor = 0.0)
{
    CoreMesh input;
    detail::copyForTrial(input, m);
    // The input's side of both measures, drawn once for all the trials.
    detail::ClosestFace<CoreMesh> toInput(input);
    const std::size_t samples = std::max(std::size_t(input.fn), kTrialMinSamples);
    const HausdorffSamples onInput = hausdorffSamples(input, samples, kTrialSeedForward);
    const ShadingInput<CoreMesh> shadingInput(input, toInput, kTrialShadingSamples, kTrialShadingSeed);
    // Turned faces count where simplify() checks them: not when the target is in the far
    // field. At 95 % the target is about the far field's floor; every collapse down to it
    // is checked, so its turned faces count.
    const int target = targetFaceCount(params, input.fn);
    std::optional<InputSurface> surface;
    if (target >= farFieldFloor(input.fn))
        surface.emplace(input, liveDiagonal(input));
    std::vector<WeightTrial> trials;
    for (const TrialWeights& w : kTrials)
        if (trialRunsAt(w, params, target, input.fn))
            trials.push_back({w});
    // The copies are made before the trials run: `m` is read from one thread only.
    std::vector<CoreMesh> copies(trials.size() + 1);
    auto run = [&](std::size_t k) {
        WeightTrial& t = trials[k];
        CoreMesh& trial = copies[k];
        const SimplifyStats s = simplifyCopy(trial, trialParams(params, t.weights));
        t.reached = s.ok && trial.fn <= s.targetFaces;
        const detail::ClosestFace<CoreMesh> toTrial(trial);
        const double forward = distancesToSurface(onInput, toTrial, nullptr, {}, kTrialFullLookupEvery).max;
        const double backward =
            oneSidedHausdorff(trial, toInput, samples, kTrialSeedBackward, nullptr, {}, kTrialFullLookupEvery).max;
        t.hausdorff = std::max(forward, backward);
        t.slivers = meshCompactness(trial).shareBelow01;
        t.shading = shadingDeviation(shadingInput, trial, toTrial).share();
        t.turned = surface ? surface->turnedFaces(trial) : 0;
        trial.Clear();
    };
    const std::size_t count = trials.size();
    for (std::size_t k = 0; k < count; k += 2) {
        if (progress)
            progress(int(100 * k / (count + 2)),
                     detail::describeWeights("Trying plane weight", params, trials[k].weights).c_str());
        detail::copyForTrial(copies[k], m);
        if (k + 1 < count) {
            detail::copyForTrial(copies[k + 1], m);
            together([&] { run(k + 1); }, [&] { run(k); });
        } else {
            run(k);
        }
    }
    const std::size_t closest = closestTrial(trials, distanceFloor);
    if (closest < count) {
        WeightTrial refined{trials[closest].weights};
        refined.weights.sliversFirst = kSliversFirstShare;
        trials.push_back(refined);
        if (progress)
            progress(int(100 * count / (count + 2)),
                     detail::describeWeights("Trying plane weight", params, refined.weights).c_str());
        detail::copyForTrial(copies[count], m);
        run(count);
    }
    return trials;
}

}  // namespace cadlod
