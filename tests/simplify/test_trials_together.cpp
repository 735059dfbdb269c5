// The weight trials (weight_trials.h) run two at a time when bestOfTrials() is given a
// RunTogether that runs tasks at once. The result must not depend on it, and the bit flags
// the trials' copies share must go back to vcglib's pool. Also built under ThreadSanitizer
// (simplify_race_tests), which reports any memory two trials both touch.
#include "cad_meshes.h"
#include "mesh_checks.h"
#include "simplify_test_util.h"

#include "support/run_together.h"
#include "simplify/best_of_trials.h"

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

TEST(TrialsTogether, TheSharedBitFlagsGoBack)
{
    const int faceBits = CoreMesh::FaceType::FirstUnusedBitFlag();
    const int vertexBits = CoreMesh::VertexType::FirstUnusedBitFlag();
    const int testFaceBits = TestMesh::FaceType::FirstUnusedBitFlag();
    TestMesh m;
    makeChip(m);
    SimplifyParams p;
    p.reductionPerc = 90;
    const SimplifyStats s = bestOfTrials(m, p, nullptr, runOnTwoThreads);
    ASSERT_TRUE(s.ok) << s.message;
    ASSERT_FALSE(s.weightTrials.empty());
    EXPECT_EQ(CoreMesh::FaceType::FirstUnusedBitFlag(), faceBits);
    EXPECT_EQ(CoreMesh::VertexType::FirstUnusedBitFlag(), vertexBits);
    EXPECT_EQ(TestMesh::FaceType::FirstUnusedBitFlag(), testFaceBits);
}
