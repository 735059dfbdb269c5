// The weight trials (weight_trials.h) run two at a time when bestOfTrials() is given a
// RunTogether that runs tasks at once. The result must not depend on it, and the bit flags
// the simplifications share are taken from vcglib's pool once. Also built under ThreadSanitizer
// (simplify_race_tests), which reports any memory two trials both touch.
#include "cad_meshes.h"
#include "mesh_checks.h"
#include "simplify_test_util.h"

#include "support/run_together.h"
#include "simplify/best_of_trials.h"
#include "simplify/simplify.h"
#include "simplify/simplify_impl.h"

#include <gtest/gtest.h>

using namespace cadlod;
using namespace cadlod::test;

namespace {

void makeChip(TestMesh& m)
{
    CadBuilder b;
    gullWingChip(b, 4);
    b.build(m, true);
}

}  // namespace

TEST(TrialsTogether, TwoThreadsGiveTheSameMeshAsOne)
{
    TestMesh sequential, parallel;
    makeChip(sequential);
    makeChip(parallel);
    SimplifyParams p;
    p.reductionPerc = 95;  // every trial runs at this target
    const SimplifyStats a = bestOfTrials(sequential, p, nullptr, runInSequence);
    const SimplifyStats b = bestOfTrials(parallel, p, nullptr, runOnTwoThreads);
    ASSERT_TRUE(a.ok && b.ok) << a.message << b.message;
    ASSERT_FALSE(a.weightTrials.empty());
    EXPECT_EQ(a.weightTrials, b.weightTrials);  // every trial measured alike, the same one kept
    EXPECT_EQ(a.collapses, b.collapses);
    EXPECT_TRUE(snapshot(sequential) == snapshot(parallel));
    EXPECT_TRUE(vfAdjacencyConsistent(parallel));
}

// The bit flags that mark features are taken from vcglib's pool once for the process and
// kept: simplifications of different meshes run at once (an assembly's parts) would take
// and give them back out of order, and a pool given back out of order only grows.
TEST(TrialsTogether, TheFeatureBitFlagsAreTakenOnce)
{
    SimplifyParams p;
    p.reductionPerc = 90;
    TestMesh first;
    makeChip(first);
    ASSERT_TRUE(bestOfTrials(first, p, nullptr, runInSequence).ok);
    const int faceBits = CoreMesh::FaceType::FirstUnusedBitFlag();
    const int vertexBits = CoreMesh::VertexType::FirstUnusedBitFlag();
    const int testFaceBits = TestMesh::FaceType::FirstUnusedBitFlag();
    const int testVertexBits = TestMesh::VertexType::FirstUnusedBitFlag();
    for (int round = 0; round < 3; ++round) {
        TestMesh a, b;
        makeChip(a);
        makeChip(b);
        SimplifyStats sa, sb;
        runOnTwoThreads([&] { sa = bestOfTrials(a, p, nullptr, runOnTwoThreads); },
                        [&] { sb = simplify(b, p, nullptr, runInSequence); });
        ASSERT_TRUE(sa.ok && sb.ok) << sa.message << sb.message;
        EXPECT_GT(sa.featureBreaks + sb.featureBreaks, 0);  // the features were marked on both threads
    }
    EXPECT_EQ(CoreMesh::FaceType::FirstUnusedBitFlag(), faceBits);
    EXPECT_EQ(CoreMesh::VertexType::FirstUnusedBitFlag(), vertexBits);
    EXPECT_EQ(TestMesh::FaceType::FirstUnusedBitFlag(), testFaceBits);
    EXPECT_EQ(TestMesh::VertexType::FirstUnusedBitFlag(), testVertexBits);
}

// Two sessions on two meshes, ended in the order they began (not as a stack), as two threads
// may end them: the pool of bit flags is the same afterwards, and both marked their features.
TEST(TrialsTogether, SessionsEndedOutOfOrderGiveBackNoBitFlags)
{
    TestMesh a, b;
    makeChip(a);
    makeChip(b);
    SimplifyParams p;
    p.reductionPerc = 90;
    SimplifyStats statsA, statsB;
    CollapseContext<TestMesh> ctxA, ctxB;
    ASSERT_TRUE(prepareCollapse(a, p, ctxA, statsA));
    releaseCollapse(a, ctxA);  // the first session takes the flags if none did before
    const int faceBits = TestMesh::FaceType::FirstUnusedBitFlag();
    const int vertexBits = TestMesh::VertexType::FirstUnusedBitFlag();
    for (int round = 0; round < 3; ++round) {
        ASSERT_TRUE(prepareCollapse(a, p, ctxA, statsA));
        ASSERT_TRUE(prepareCollapse(b, p, ctxB, statsB));
        releaseCollapse(a, ctxA);
        releaseCollapse(b, ctxB);
    }
    EXPECT_EQ(TestMesh::FaceType::FirstUnusedBitFlag(), faceBits);
    EXPECT_EQ(TestMesh::VertexType::FirstUnusedBitFlag(), vertexBits);
    EXPECT_NE(ctxA.bits.locked, 0);
    EXPECT_NE(ctxA.bits.edge[0], 0);
}
