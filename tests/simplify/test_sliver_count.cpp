// The sliver count near a face target (SimplifyParams::sliverCountShare): while the target
// keeps at least that share of the input's faces, a collapse among slivers may not add to
// their number. The compactness floor alone (the worst face around the edge) lets it make
// new slivers as long as each beats the worst, and a tessellation's strips of slivers (a
// chip lead's bend) multiply instead of being coarsened.
#include "cad_meshes.h"
#include "indexed_mesh.h"
#include "simplify_test_util.h"
#include "test_mesh.h"

#include "measure/compactness.h"
#include "simplify/best_of_trials.h"

#include <gtest/gtest.h>

#include <functional>
#include <utility>

using namespace cadlod;
using namespace cadlod::test;

namespace {

Reduction reduce(const std::function<void(CadBuilder&)>& make, double percent, double sliverCountShare)
{
    SimplifyParams p;
    p.reductionPerc = percent;
    p.weightTrialsMaxFaces = 0;  // the guard itself, not the trials' pick
    p.sliverCountShare = sliverCountShare;
    return reduceWith(make, p);
}

constexpr double kNever = 2.0;  // a share above 1: the count never applies

void board(CadBuilder& b) { circuitBoard(b); }

}  // namespace

// The circuit board: its plate's sides are strips of slivers, and its parts stand on it. Near
// the target the count keeps the slivers from multiplying there, for a distance within a few
// percent of the run without it.
TEST(SliverCount, NearTheTargetTheBoardKeepsFewerSlivers)
{
    for (double percent : {50.0, 75.0}) {
        SCOPED_TRACE(percent);
        const Reduction counted = reduce(board, percent, 0.25), uncounted = reduce(board, percent, kNever);
        EXPECT_EQ(counted.faces, uncounted.faces);
        EXPECT_GT(uncounted.slivers, 0.01);
        EXPECT_LT(counted.slivers, 0.7 * uncounted.slivers);
        EXPECT_LT(counted.distance, 1.1 * uncounted.distance);
    }
}

// Below the share (90 % keeps a tenth of the faces) the count does not apply: the same run.
TEST(SliverCount, FartherDownItDoesNotApply)
{
    const Reduction counted = reduce(board, 90, 0.25), uncounted = reduce(board, 90, kNever);
    EXPECT_EQ(counted.faces, uncounted.faces);
    EXPECT_EQ(counted.slivers, uncounted.slivers);
    EXPECT_EQ(counted.distance, uncounted.distance);
    // A share of 0 counts at every target: the 90 % run changes.
    const Reduction always = reduce(board, 90, 0.0);
    EXPECT_NE(always.distance, uncounted.distance);
}

// What the count costs a viewer: on the board at 75 %, with the weight trials as a user gets
// them, at most a tenth more of the pixels shaded differently, for 2.5 times fewer slivers.
TEST(SliverCount, WithTheTrialsTheBoardShadesAlmostAsWell)
{
    auto visibleAndSlivers = [](double sliverCountShare) {
        TestMesh input, m;
        buildInputAndCopy(board, input, m);
        SimplifyParams p;
        p.reductionPerc = 75;
        p.sliverCountShare = sliverCountShare;
        const SimplifyStats s = bestOfTrials(m, p);
        EXPECT_TRUE(s.ok) << s.message;
        const shading::IndexedMesh a = toIndexed(input), r = toIndexed(m);
        return std::make_pair(shading::compare(a.ref(), r.ref()).visiblePercent, meshCompactness(m).shareBelow01);
    };
    const auto [countedVisible, countedSlivers] = visibleAndSlivers(0.25);
    const auto [uncountedVisible, uncountedSlivers] = visibleAndSlivers(kNever);
    EXPECT_LT(countedVisible, 1.1 * uncountedVisible);
    EXPECT_LT(countedSlivers, 0.5 * uncountedSlivers);
}

// Slivers first (SimplifyParams::sliverFirstShare): a collapse that removes a sliver along
// its shortest edge is ranked at a share of its priority. The assembly (a shaft, a tube and a
// plate) at half its faces keeps half the slivers at the same distance; at 1 the run is the
// plain one.
TEST(SliversFirst, TheAssemblyAtHalfKeepsFewerSlivers)
{
    auto reduceAssembly = [](double share) {
        SimplifyParams p;
        p.reductionPerc = 50;
        p.weightTrialsMaxFaces = 0;  // the ranking itself, not the trials' pick
        p.sliverFirstShare = share;
        return reduceWith([](CadBuilder& b) { assembly(b, 48); }, p);
    };
    const Reduction plain = reduceAssembly(1.0), first = reduceAssembly(0.7);
    EXPECT_EQ(first.faces, plain.faces);
    EXPECT_GT(plain.slivers, 0.02);
    EXPECT_LT(first.slivers, 0.6 * plain.slivers);
    EXPECT_LE(first.distance, 1.01 * plain.distance);
}
