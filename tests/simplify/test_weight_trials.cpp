// Plane-weight trials (weight_trials.h): a small mesh with a face target is simplified on
// copies with the large-face weight times 1, 10 and 40, each result measured against the
// input, and the weight of the closest is used on the mesh itself.
#include "cad_meshes.h"
#include "simplify_test_util.h"
#include "test_mesh.h"

#include "core/hausdorff.h"
#include "core/simplify.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

using namespace cadlod;
using namespace cadlod::test;

namespace {

struct Outcome {
    double distance = 0.0;  // symmetric Hausdorff distance to the input, % of the diagonal
    int faces = 0;
    SimplifyStats stats;
};

// `make`'s part reduced by `percent`, with the trials or with the default weight alone,
// measured with other samples than the trials' own (seeds 1 and 2, 100 000 per side).
Outcome reduce(const std::function<void(CadBuilder&)>& make, double percent, bool trials)
{
    TestMesh input, m;
    buildInputAndCopy(make, input, m);
    SimplifyParams p;
    p.reductionPerc = percent;
    if (!trials)
        p.weightTrialsMaxFaces = 0;
    Outcome o;
    o.stats = simplify(m, p);
    EXPECT_TRUE(o.stats.ok) << o.stats.message;
    o.faces = m.fn;
    const double forward = oneSidedHausdorff(input, m, 100000, 1).max;
    const double backward = oneSidedHausdorff(m, input, 100000, 2).max;
    o.distance = 100 * std::max(forward, backward) / liveDiagonal(input);
    return o;
}

void chip(CadBuilder& b) { gullWingChip(b, 8); }
void shaft(CadBuilder& b) { revolve(b, shaftProfile(), shaftSpec(96, 4)); }
void board(CadBuilder& b) { circuitBoard(b); }
void tube(CadBuilder& b) { tubeWithFin(b, 48); }

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
        const Outcome with = reduce(c.make, c.percent, true), without = reduce(c.make, c.percent, false);
        EXPECT_EQ(with.faces, without.faces) << c.name;
        EXPECT_LT(with.distance, 0.8 * without.distance) << c.name << ": " << with.stats.weightTrials;
        EXPECT_NE(with.stats.weightTrials.find("0.005 ("), std::string::npos) << with.stats.weightTrials;
        EXPECT_NE(with.stats.weightTrials.find("kept 0.2"), std::string::npos) << with.stats.weightTrials;
    }
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
        const Outcome with = reduce(c.make, c.percent, true), without = reduce(c.make, c.percent, false);
        EXPECT_EQ(with.faces, without.faces) << c.name << " at " << c.percent;
        EXPECT_LE(with.distance, 1.02 * without.distance)
            << c.name << " at " << c.percent << " %: " << with.stats.weightTrials;
    }
}

// The choice: the lowest distance among the trials that reached their target; excess
// slivers (over the fewest plus one point) count one best distance per five points.
TEST(WeightTrials, TheClosestTrialWinsUnlessItMakesSlivers)
{
    // weight, distance, slivers, shading deviation, reached
    std::vector<WeightTrial> t = {
        {0.005, 3.0, 0.02, 0.0, true}, {0.05, 2.0, 0.02, 0.0, true}, {0.2, 4.0, 0.02, 0.0, true}};
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

// Shading counts beside distance: a trial a little farther that a viewer sees lit like the
// input over far more of its surface wins; below the floor, shading cannot tell trials apart.
TEST(WeightTrials, ShadingCountsBesideDistance)
{
    std::vector<WeightTrial> t = {{0.005, 2.2, 0.02, 0.06, true}, {0.05, 2.0, 0.02, 0.12, true}};
    EXPECT_EQ(closestTrial(t), 0u);  // 1.1 + 0.7 against 1 + 1.4
    t[0].shading = 0.11;             // 1.1 + 0.7 against 1 + 0.7 · 1.09
    EXPECT_EQ(closestTrial(t), 1u);
    t[0].shading = 0.001;  // both under the floor of 0.5 %: distance decides
    t[1].shading = 0.004;
    EXPECT_EQ(closestTrial(t), 1u);
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
    EXPECT_TRUE(simplify(m, q).weightTrials.empty());
}
