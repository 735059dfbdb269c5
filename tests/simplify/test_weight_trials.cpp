// Weight trials (weight_trials.h): a small mesh with a face target is simplified on copies
// with the large-face weight times 1, 10 and 40, times 200 with features at their quadric
// cost (with their constraint planes and without), keeping smooth joins, and with the
// constraint planes loosened (near the input also without the shape guard), each result
// measured against the input, and the weights of the closest are used on the mesh itself.
#include "cad_meshes.h"
#include "mesh_checks.h"
#include "simplify_test_util.h"
#include "test_mesh.h"

#include "measure/hausdorff.h"
#include "measure/shading_deviation.h"
#include "simplify/best_of_trials.h"
#include "simplify/weight_trials.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <functional>
#include <string>
#include <vector>

using namespace cadlod;
using namespace cadlod::test;

namespace {

// `make`'s part reduced by `percent`, with the trials or with the default weight alone.
Reduction reduce(const std::function<void(CadBuilder&)>& make, double percent, bool trials)
{
    SimplifyParams p;
    p.reductionPerc = percent;
    if (!trials)
        p.weightTrialsMaxFaces = 0;
    return reduceWith(make, p);
}

// The trials' log line for `make`'s part simplified with `p`.
std::string trialsLog(const std::function<void(CadBuilder&)>& make, const SimplifyParams& p)
{
    TestMesh input, m;
    buildInputAndCopy(make, input, m);
    const SimplifyStats s = bestOfTrials(m, p);
    EXPECT_TRUE(s.ok) << s.message;
    return s.weightTrials;
}

void chip(CadBuilder& b) { gullWingChip(b, 8); }
void shaft(CadBuilder& b) { revolve(b, shaftProfile(), shaftSpec(96, 4)); }
void board(CadBuilder& b) { circuitBoard(b); }
void tube(CadBuilder& b) { tubeWithFin(b, 48); }

// A roller 100 long, radius 10 around in 32 long strips, whose last 12 carry 12 V-grooves
// 0.6 deep: a long smooth cylinder beside many small creased details (a battery holder's
// trough beside its spring).
void threadedRoller(CadBuilder& b)
{
    std::vector<ProfilePoint> profile = {{0, 0}, {0, 10}, {88, 10}};
    for (int g = 0; g < 12; ++g)
        profile.insert(profile.end(), {{88 + g + 0.5, 9.4}, {88 + g + 1.0, 10}});
    profile.push_back({100, 0});
    RevolveSpec spec;
    spec.segments = 32;
    revolve(b, profile, spec);
}

}  // namespace

// Where the given weight flattens what a heavier one keeps (the chip's body top, the
// shaft's long cylinders at 95 %), a heavier weight is kept and the result is closer to
// the input by a margin no sampling explains; the log line names every trial.
TEST(WeightTrials, AFarReductionKeepsTheWeightClosestToTheInput)
{
    struct Case {
        const char* name;
        void (*make)(CadBuilder&);
        double percent;
    };
    for (const Case& c : {Case{"gull-wing chip", chip, 90.0}, Case{"shaft", shaft, 95.0}}) {
        const Reduction with = reduce(c.make, c.percent, true), without = reduce(c.make, c.percent, false);
        EXPECT_EQ(with.faces, without.faces) << c.name;
        EXPECT_LT(with.distance, 0.85 * without.distance) << c.name << ": " << with.stats.weightTrials;
        EXPECT_NE(with.stats.weightTrials.find("0.005 ("), std::string::npos) << with.stats.weightTrials;
        EXPECT_EQ(with.stats.weightTrials.find("kept 0.005"), std::string::npos) << with.stats.weightTrials;
    }
}

// Where a long smooth surface decides what a viewer sees, a heavier plane weight is kept
// where by distance and slivers alone a lighter one would be (at 90 %, 0.05 against 0.2): the
// roller stays round and loses its grooves, and far less of it is lit differently than with
// the default weight, which keeps the grooves' creases and facets the roller.
TEST(WeightTrials, ALongCylinderOutweighsSmallCreasedDetails)
{
    TestMesh input, with, without;
    buildInputAndCopy(threadedRoller, input, with);
    buildInputAndCopy(threadedRoller, input, without);
    SimplifyParams p;
    p.reductionPerc = 90;
    const SimplifyStats s = bestOfTrials(with, p);
    p.weightTrialsMaxFaces = 0;
    bestOfTrials(without, p);
    EXPECT_EQ(with.fn, without.fn);
    EXPECT_EQ(s.weightTrials.find("kept 0.005"), std::string::npos) << s.weightTrials;
    const detail::ClosestFace<TestMesh> toInput(input);
    const ShadingInput<TestMesh> shading(input, toInput, 100000, 7);
    const double kept = shadingDeviation(shading, with, detail::ClosestFace<TestMesh>(with)).share();
    const double flat = shadingDeviation(shading, without, detail::ClosestFace<TestMesh>(without)).share();
    EXPECT_LT(kept, 0.5 * flat) << s.weightTrials;
}

// Elsewhere the trials cost nothing: the result is never farther from the input than the
// default weight's (within the sampling of the measure), whichever weight is kept.
TEST(WeightTrials, NeverFartherThanTheDefaultWeight)
{
    struct Case {
        const char* name;
        void (*make)(CadBuilder&);
        double percent;
    };
    for (const Case& c : {Case{"circuit board", board, 50.0}, Case{"circuit board", board, 90.0},
                          Case{"shaft", shaft, 75.0}, Case{"tube with fin", tube, 90.0}}) {
        const Reduction with = reduce(c.make, c.percent, true), without = reduce(c.make, c.percent, false);
        EXPECT_EQ(with.faces, without.faces) << c.name << " at " << c.percent;
        EXPECT_LE(with.distance, 1.02 * without.distance)
            << c.name << " at " << c.percent << " %: " << with.stats.weightTrials;
    }
}

// The choice: the lowest distance among the trials that reached their target; excess
// slivers (over the fewest plus one point) count one best distance per five points.
TEST(WeightTrials, TheClosestTrialWinsUnlessItMakesSlivers)
{
    // weights, distance, slivers, shading deviation, reached
    std::vector<WeightTrial> t = {
        {{}, 3.0, 0.02, 0.0, true}, {{}, 2.0, 0.02, 0.0, true}, {{}, 4.0, 0.02, 0.0, true}};
    EXPECT_EQ(closestTrial(t), 1u);
    t[1].slivers = 0.12;  // 10 points more: 1 + 1.8 against 1.5
    EXPECT_EQ(closestTrial(t), 0u);
    t[1].slivers = 0.025;  // within the point of margin
    EXPECT_EQ(closestTrial(t), 1u);
    t[1].reached = false;  // short of the target: not a candidate while another reached it
    EXPECT_EQ(closestTrial(t), 0u);
    for (WeightTrial& x : t)
        x.reached = false;
    EXPECT_EQ(closestTrial(t), 1u);
    EXPECT_EQ(closestTrial({}), 0u);
}

// Below the distance floor (the flat tolerance, in bestOfTrials()) distances count alike: a
// result a hair from exact is not a thousand times farther than an exact one, and slivers
// decide between them.
TEST(WeightTrials, DistancesBelowTheFloorCountAlike)
{
    std::vector<WeightTrial> t = {{{}, 1e-9, 0.48, 0.0, true}, {{}, 1e-12, 0.56, 0.0, true}};
    EXPECT_EQ(closestTrial(t), 1u);        // 1000 times closer, without a floor
    EXPECT_EQ(closestTrial(t, 1e-6), 0u);  // both at the floor: 8 points fewer slivers
    t[0].hausdorff = 3e-6;                 // 3 floors against 1 + 1.4 for the slivers
    EXPECT_EQ(closestTrial(t, 1e-6), 1u);
}

// Shading counts beside distance: a trial a little farther that a viewer sees lit like the
// input over far more of its surface wins; below the floor, shading cannot tell trials apart.
TEST(WeightTrials, ShadingCountsBesideDistance)
{
    std::vector<WeightTrial> t = {{{}, 2.2, 0.02, 0.06, true}, {{}, 2.0, 0.02, 0.12, true}};
    EXPECT_EQ(closestTrial(t), 0u);  // 1.1 + 0.7 against 1 + 1.4
    t[0].shading = 0.11;             // 1.1 + 0.7 against 1 + 0.7 · 1.09
    EXPECT_EQ(closestTrial(t), 1u);
    t[0].shading = 0.001;  // both under the floor of 0.5 %: distance decides
    t[1].shading = 0.004;
    EXPECT_EQ(closestTrial(t), 1u);
}

// Each face a trial turns away from the input surface beyond the fewest of the trials counts
// as one more best distance against it.
TEST(WeightTrials, ATurnedFaceCountsAsMuchAsTheBestDistance)
{
    std::vector<WeightTrial> t = {{{}, 3.0, 0.02, 0.0, true}, {{}, 2.0, 0.02, 0.0, true},
                                  {{}, 2.5, 0.02, 0.0, true}};
    t[1].turned = 2;
    EXPECT_EQ(closestTrial(t), 2u);
    t[2].turned = 1;
    EXPECT_EQ(closestTrial(t), 0u);
    t[0].turned = 3;  // none turns none: the fewest is 1
    EXPECT_EQ(closestTrial(t), 2u);
    t[2].reached = false;  // short of its target: the fewest among those that reached it
    EXPECT_EQ(closestTrial(t), 1u);
    // One face more for a third of the distance: 1 + 0.7 + 1 against 3 + 0.7.
    t = {{{}, 6.0, 0.02, 0.0, true}, {{}, 2.0, 0.02, 0.0, true}};
    t[1].turned = 1;
    EXPECT_EQ(closestTrial(t), 1u);
    t[1].turned = 3;
    EXPECT_EQ(closestTrial(t), 0u);
}

// The closest trial run again slivers first is kept instead only where it costs next to
// nothing a viewer sees: within 1.1 times the distance and 1.15 times the shading (floors
// alike), no more faces turned, at least a point fewer slivers. closestTrial never picks it.
TEST(WeightTrials, SliversFirstIsKeptOnlyWhereItCostsNothingSeen)
{
    TrialWeights again;
    again.sliversFirst = kSliversFirstShare;
    // weights, distance, slivers, shading deviation, reached
    const std::vector<WeightTrial> base = {{{}, 3.0, 0.10, 0.02, true}, {{}, 2.0, 0.10, 0.02, true},
                                           {again, 2.18, 0.08, 0.022, true}};
    EXPECT_EQ(closestTrial(base), 1u);
    EXPECT_EQ(keptTrial(base), 2u);
    auto keptWith = [&](auto change) {
        std::vector<WeightTrial> t = base;
        change(t[2]);
        return keptTrial(t);
    };
    EXPECT_EQ(keptWith([](WeightTrial& r) { r.hausdorff = 2.24; }), 1u);  // 1.12 times farther
    EXPECT_EQ(keptWith([](WeightTrial& r) { r.shading = 0.024; }), 1u);   // 1.2 times the shading
    EXPECT_EQ(keptWith([](WeightTrial& r) { r.shading = 0.004; }), 2u);   // less is fine
    EXPECT_EQ(keptWith([](WeightTrial& r) { r.turned = 1; }), 1u);
    EXPECT_EQ(keptWith([](WeightTrial& r) { r.slivers = 0.095; }), 1u);   // half a point fewer
    EXPECT_EQ(keptWith([](WeightTrial& r) { r.reached = false; }), 1u);
    EXPECT_EQ(keptWith([](WeightTrial& r) { r.hausdorff = 0.5; }), 2u);  // closer still: kept
    // The distance floor: a hair from exact counts as exact on both sides.
    const std::vector<WeightTrial> exact = {{{}, 1e-12, 0.20, 0.0, true}, {again, 3e-9, 0.15, 0.0, true}};
    EXPECT_EQ(keptTrial(exact), 0u);
    EXPECT_EQ(keptTrial(exact, 1e-6), 1u);
    // Much closer but never a candidate of its own: the first trial stays the closest.
    std::vector<WeightTrial> alone = base;
    alone[2].hausdorff = 0.1;
    EXPECT_EQ(closestTrial(alone), 1u);
}

// The trials' weights: the caller's first; the heaviest plane weight with features at their
// quadric cost (a penalty of 1), a caller's hard locks (0) kept; the facing price is the
// caller's in every trial, whatever its feature penalty.
TEST(WeightTrials, TheHeaviestTrialPricesFeaturesAtTheirCost)
{
    SimplifyParams caller;
    caller.reductionPerc = 90;
    const SimplifyParams first = trialParams(caller, kTrials[0]);
    EXPECT_EQ(first.largeFaceWeight, caller.largeFaceWeight);
    EXPECT_EQ(first.featurePenalty, caller.featurePenalty);
    EXPECT_EQ(first.weightTrialsMaxFaces, 0);
    const TrialWeights& last =
        *std::find_if(std::begin(kTrials), std::end(kTrials), [](const TrialWeights& w) { return !w.featuresPriced; });
    EXPECT_EQ(last.plane, std::max_element(std::begin(kTrials), std::end(kTrials), [](auto& a, auto& b) {
                              return a.plane < b.plane;
                          })->plane);
    const SimplifyParams heavy = trialParams(caller, last);
    EXPECT_GT(heavy.largeFaceWeight, 100 * caller.largeFaceWeight);
    EXPECT_EQ(heavy.featurePenalty, 1.0);
    EXPECT_EQ(facingPenaltyOf(heavy), facingPenaltyOf(caller));
    EXPECT_EQ(facingPenaltyOf(caller), kFacingOverFeature * caller.featurePenalty);
    caller.featurePenalty = 0;  // hard locks
    EXPECT_EQ(trialParams(caller, last).featurePenalty, 0.0);
    EXPECT_EQ(facingPenaltyOf(trialParams(caller, last)), 0.0);
}

// Features at their cost are tried without their constraint planes too (boundaryWeight 0):
// with them, a lead's creases hold its bends in place at the price of the whole chip's
// outline; without them, the leads' creases cost what their faces' planes say. On the chip
// at 95 % that run is far closer to the input, and the trials keep it.
TEST(WeightTrials, FeaturesAtCostAreTriedWithoutTheirConstraintPlanes)
{
    auto featuresAtCost = [](double planes) {
        return std::find_if(std::begin(kTrials), std::end(kTrials), [&](const TrialWeights& w) {
            return !w.featuresPriced && w.constraintPlanes == planes;
        });
    };
    ASSERT_NE(featuresAtCost(1.0), std::end(kTrials));
    ASSERT_NE(featuresAtCost(0.0), std::end(kTrials));
    SimplifyParams caller;
    caller.reductionPerc = 95;
    const SimplifyParams held = trialParams(caller, *featuresAtCost(1.0));
    const SimplifyParams free = trialParams(caller, *featuresAtCost(0.0));
    EXPECT_EQ(held.boundaryWeight, caller.boundaryWeight);
    EXPECT_EQ(free.boundaryWeight, 0.0);
    EXPECT_EQ(free.featurePenalty, 1.0);
    EXPECT_EQ(free.largeFaceWeight, held.largeFaceWeight);

    auto distanceWith = [](const SimplifyParams& p) {
        const Reduction r = reduceWith(chip, p);
        EXPECT_LE(r.faces, r.stats.targetFaces);
        return r.distance;
    };
    EXPECT_LT(distanceWith(free), 0.8 * distanceWith(held));
    const Reduction with = reduce(chip, 95, true);
    EXPECT_NE(with.stats.weightTrials.find("kept 1 with feature penalty 1, constraint planes x 0"), std::string::npos)
        << with.stats.weightTrials;
}

// One trial runs the caller's weights with the constraint planes at a fraction of their
// weight, at every target (where a crease vertex leaving its curved crease makes fewer
// slivers); the log names it.
TEST(WeightTrials, OneTrialLoosensTheConstraintPlanesAtEveryTarget)
{
    const auto loosened = std::find_if(std::begin(kTrials), std::end(kTrials), [](const TrialWeights& w) {
        return w.featuresPriced && w.constraintPlanes > 0 && w.constraintPlanes < 1;
    });
    ASSERT_NE(loosened, std::end(kTrials));
    EXPECT_TRUE(trialRunsAt(*loosened, SimplifyParams{}, 500, 1000));
    SimplifyParams withoutPlanes;
    withoutPlanes.boundaryWeight = 0;
    EXPECT_FALSE(trialRunsAt(*loosened, withoutPlanes, 500, 1000));
    EXPECT_TRUE(trialRunsAt(kTrials[0], withoutPlanes, 500, 1000));
    SimplifyParams caller;
    caller.boundaryWeight = 2;
    EXPECT_EQ(trialParams(caller, *loosened).boundaryWeight, 2 * loosened->constraintPlanes);
    EXPECT_EQ(trialParams(caller, *loosened).featurePenalty, caller.featurePenalty);
    const Reduction half = reduce(board, 50, true);
    EXPECT_NE(half.stats.weightTrials.find(", constraint planes x 0.25 ("), std::string::npos)
        << half.stats.weightTrials;
    // Without constraint planes (boundary weight 0) there is nothing to loosen: not tried.
    SimplifyParams none;
    none.reductionPerc = 50;
    none.boundaryWeight = 0;
    const std::string log = trialsLog(board, none);
    EXPECT_FALSE(log.empty());
    EXPECT_EQ(log.find("constraint planes"), std::string::npos) << log;
}

// One trial runs without the shape guard (SimplifyParams::minCompactness 0) and with the
// constraint planes at a tenth where the target leaves at least half of the faces: on strips
// of slivers (a lead's bend) the guard refuses the collapses that would coarsen them. Not
// tried when the caller has no guard to drop.
TEST(WeightTrials, OneTrialRunsWithoutTheShapeGuard)
{
    const auto unguarded = std::find_if(std::begin(kTrials), std::end(kTrials),
                                        [](const TrialWeights& w) { return !w.shapeGuard; });
    ASSERT_NE(unguarded, std::end(kTrials));
    SimplifyParams caller;
    EXPECT_TRUE(trialRunsAt(*unguarded, caller, 500, 1000));
    EXPECT_FALSE(trialRunsAt(*unguarded, caller, 499, 1000));
    EXPECT_FALSE(trialRunsAt(*unguarded, caller, 100, 1000));
    EXPECT_EQ(trialParams(caller, *unguarded).minCompactness, 0.0);
    EXPECT_EQ(trialParams(caller, kTrials[0]).minCompactness, caller.minCompactness);
    SimplifyParams unguardedCaller;
    unguardedCaller.minCompactness = 0;
    EXPECT_FALSE(trialRunsAt(*unguarded, unguardedCaller, 500, 1000));

    // The same trial loosens the constraint planes to a tenth: on a fine part's curved
    // creases (a chip lead's bend) they hold crease vertices a viewer would not miss.
    caller.boundaryWeight = 2.0;
    EXPECT_DOUBLE_EQ(trialParams(caller, *unguarded).boundaryWeight, 0.2);
    EXPECT_EQ(trialParams(caller, *unguarded).largeFaceWeight, caller.largeFaceWeight);
    SimplifyParams withoutPlanes;  // nothing to loosen, but the guard is still dropped
    withoutPlanes.boundaryWeight = 0;
    EXPECT_TRUE(trialRunsAt(*unguarded, withoutPlanes, 500, 1000));

    // A board whose parts' rounded edges are strips of long faces: without the guard the
    // trial at 50 % comes closer, and it is kept.
    const Reduction unguardedKept = reduce(board, 50, true);
    const Reduction guarded = reduce(board, 50, false);
    EXPECT_NE(unguardedKept.stats.weightTrials.find("kept 0.005, constraint planes x 0.1, no shape guard"),
              std::string::npos)
        << unguardedKept.stats.weightTrials;
    EXPECT_LT(unguardedKept.distance, 0.9 * guarded.distance);
    SimplifyParams none;
    none.reductionPerc = 50;
    none.minCompactness = 0;
    const std::string log = trialsLog(chip, none);
    EXPECT_FALSE(log.empty());
    EXPECT_EQ(log.find("shape guard"), std::string::npos) << log;
}

// One trial keeps smooth joins (SimplifyParams::keepSmoothJoins, test_smooth_joins.cpp), the
// others leave it to the caller; like the features-at-cost trial it runs only where the
// target leaves at most a tenth of the faces, and the log names it.
TEST(WeightTrials, OneTrialKeepsSmoothJoinsAtFarTargets)
{
    const auto keeping = std::count_if(std::begin(kTrials), std::end(kTrials),
                                       [](const TrialWeights& w) { return w.keepSmoothJoins; });
    EXPECT_EQ(keeping, 1);
    SimplifyParams caller;
    for (const TrialWeights& w : kTrials)
        EXPECT_EQ(trialParams(caller, w).keepSmoothJoins, w.keepSmoothJoins);
    const TrialWeights joins{10.0, true, true};
    EXPECT_TRUE(trialRunsAt(joins, caller, 100, 1000));
    EXPECT_FALSE(trialRunsAt(joins, caller, 500, 1000));
    EXPECT_FALSE(trialRunsAt(joins, caller, 0, 1000));  // the shape guards relax only toward a face target
    EXPECT_TRUE(trialRunsAt(TrialWeights{200.0, false}, caller, 0, 1000));
    for (double percent : {50.0, 90.0}) {
        TestMesh m;
        makeShaft(m, 48);
        SimplifyParams p;
        p.reductionPerc = percent;
        const SimplifyStats s = bestOfTrials(m, p);
        ASSERT_TRUE(s.ok) << s.message;
        EXPECT_EQ(s.weightTrials.find("keeping smooth joins") != std::string::npos, percent >= 90) << s.weightTrials;
    }
}

// Trials run only with a face target, a weight to vary, the whole mesh to work on and a mesh
// below the size limit; when they do not, the log line stays empty.
TEST(WeightTrials, OnlySmallMeshesWithAFaceTarget)
{
    TestMesh m;
    CadBuilder b;
    board(b);
    b.build(m, true);
    SimplifyParams p;
    p.reductionPerc = 75;
    EXPECT_TRUE(weightTrialsApply(m, p));
    SimplifyParams q = p;
    q.weightTrialsMaxFaces = m.fn;
    EXPECT_FALSE(weightTrialsApply(m, q));
    q = p;
    q.largeFaceWeight = 0;
    EXPECT_FALSE(weightTrialsApply(m, q));
    q = p;
    q.selectedOnly = true;
    EXPECT_FALSE(weightTrialsApply(m, q));
    q = p;
    q.reductionPerc = 0;
    q.maxError = 0.01;
    EXPECT_FALSE(weightTrialsApply(m, q));
    q.weightTrialsMaxFaces = 0;
    q.reductionPerc = 75;
    q.maxError = 0;
    EXPECT_TRUE(bestOfTrials(m, q).weightTrials.empty());
}

// A trial's faces turned over count wherever bestOfTrials() checks its collapses against the
// input surface: down to the far field's floor, the whole 5 % of the faces included. The
// chip with eight bent leads (2 052 faces) toward 102 faces, under 5 % (102.6) but not under
// the floor: each trial's count is the bench's own count (mesh_checks.h) on the same run,
// and one trial at least turns a face, so a count of 0 would show.
TEST(WeightTrials, TurnedFacesCountDownToTheFarFieldsFloor)
{
    TestMesh input, m;
    buildInputAndCopy(chip, input, m);
    SimplifyParams p;
    p.targetFaces = farFieldFloor(input.fn);
    ASSERT_LT(p.targetFaces, kFacingFarField * input.fn);
    const std::vector<WeightTrial> trials = runWeightTrials(m, p, [](CoreMesh& copy, const SimplifyParams& q) {
        return simplify(copy, q);
    }, nullptr);
    ASSERT_GE(trials.size(), 4u);
    int turned = 0;
    for (const WeightTrial& t : trials) {
        TestMesh run;
        copyMesh(run, input);
        const SimplifyStats s = simplify(run, trialParams(p, t.weights));
        ASSERT_TRUE(s.ok) << s.message;
        EXPECT_EQ(t.turned, foldedFaces(run, input)) << detail::describeWeights("trial", p, t.weights);
        turned += t.turned;
    }
    EXPECT_GT(turned, 0) << "no trial turns a face: the chip no longer tests the count";
}

// A trial is judged by its largest distance, looked up in full for one point in
// kTrialFullLookupEvery and for the others only where they could raise it: the figure is
// the one every point looked up in full gives, from the same points (the input's and the
// trial's, with the trials' seeds), to the last bit. The chip at 90 %, where the trials
// differ from each other.
TEST(WeightTrials, EachTrialsDistanceIsTheFullMaximumOfItsPoints)
{
    TestMesh input, m;
    buildInputAndCopy(chip, input, m);
    SimplifyParams p;
    p.reductionPerc = 90;
    const std::vector<WeightTrial> trials = runWeightTrials(m, p, [](CoreMesh& copy, const SimplifyParams& q) {
        return simplify(copy, q);
    }, nullptr);
    ASSERT_GE(trials.size(), 4u);
    const std::size_t samples = std::max(std::size_t(input.fn), kTrialMinSamples);
    const HausdorffSamples onInput = hausdorffSamples(input, samples, kTrialSeedForward);
    detail::ClosestFace<TestMesh> toInput(input);
    std::vector<double> distances;
    for (const WeightTrial& t : trials) {
        TestMesh run;
        copyMesh(run, input);
        const SimplifyStats s = simplify(run, trialParams(p, t.weights));
        ASSERT_TRUE(s.ok) << s.message;
        const detail::ClosestFace<TestMesh> toRun(run);
        const double forward = distancesToSurface(onInput, toRun).max;
        const double backward = oneSidedHausdorff(run, toInput, samples, kTrialSeedBackward).max;
        EXPECT_EQ(t.hausdorff, std::max(forward, backward)) << detail::describeWeights("trial", p, t.weights);
        distances.push_back(t.hausdorff);
    }
    EXPECT_GT(*std::max_element(distances.begin(), distances.end()),
              *std::min_element(distances.begin(), distances.end()))
        << "every trial equally far: the chip no longer tells them apart";
}

// After the trials the closest of them runs once more slivers first: the last trial, the
// closest one's weights with SimplifyParams::sliverFirstShare at kSliversFirstShare, measured
// like the others. The chip at 75 % and 90 %.
TEST(WeightTrials, TheClosestRunsAgainSliversFirst)
{
    for (double percent : {75.0, 90.0}) {
        SCOPED_TRACE(percent);
        TestMesh input, m;
        buildInputAndCopy(chip, input, m);
        SimplifyParams p;
        p.reductionPerc = percent;
        const std::vector<WeightTrial> trials = runWeightTrials(m, p, [](CoreMesh& copy, const SimplifyParams& q) {
            return simplify(copy, q);
        }, nullptr);
        ASSERT_GE(trials.size(), 5u);
        const WeightTrial& again = trials.back();
        EXPECT_EQ(std::count_if(trials.begin(), trials.end(), isSliversFirstRun), 1);
        ASSERT_TRUE(isSliversFirstRun(again));
        const std::size_t closest = closestTrial(trials);
        ASSERT_LT(closest, trials.size() - 1);
        TrialWeights expected = trials[closest].weights;
        expected.sliversFirst = kSliversFirstShare;
        EXPECT_EQ(detail::describeWeights("", p, again.weights), detail::describeWeights("", p, expected));
        EXPECT_EQ(trialParams(p, again.weights).sliverFirstShare, kSliversFirstShare);
        EXPECT_GT(again.hausdorff, 0.0);
        EXPECT_TRUE(again.reached);
    }
}

namespace {

// The live vertex positions of `m` in memory order.
std::vector<vcg::Point3f> livePositions(const TestMesh& m)
{
    std::vector<vcg::Point3f> positions;
    for (const auto& v : m.vert)
        if (!v.IsD())
            positions.push_back(v.cP());
    return positions;
}

}  // namespace

// simplify() simplifies once, with the caller's weights, where bestOfTrials tries several:
// on the chip at 90 % the trials run and change the result, and simplify()'s result is the
// one bestOfTrials gives with the trials turned off, to the last coordinate.
TEST(WeightTrials, SimplifyRunsOnceWhereBestOfTrialsTriesWeights)
{
    TestMesh input, once, best, untried;
    buildInputAndCopy(chip, input, once);
    copyMesh(best, input);
    copyMesh(untried, input);
    SimplifyParams p;
    p.reductionPerc = 90;
    ASSERT_TRUE(weightTrialsApply(input, p));

    const SimplifyStats s = simplify(once, p);
    ASSERT_TRUE(s.ok) << s.message;
    EXPECT_TRUE(s.weightTrials.empty()) << s.weightTrials;

    SimplifyParams off = p;
    off.weightTrialsMaxFaces = 0;
    ASSERT_TRUE(bestOfTrials(untried, off).ok);
    EXPECT_EQ(once.fn, untried.fn);
    EXPECT_EQ(livePositions(once), livePositions(untried));

    const SimplifyStats t = bestOfTrials(best, p);
    ASSERT_TRUE(t.ok) << t.message;
    EXPECT_FALSE(t.weightTrials.empty());
    EXPECT_NE(livePositions(once), livePositions(best)) << "the trials kept the caller's weights: the chip no longer tells";
}
