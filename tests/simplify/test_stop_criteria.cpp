// Stop criteria: target face count (±2) on closed and open meshes, reduction
// percentage, and the maximum-error bound.
#include "simplify_test_util.h"

#include "measure/hausdorff.h"

#include <gtest/gtest.h>

using namespace cadlod;
using namespace cadlod::test;

TEST(SimplifyStop, ReachesTargetFacesOnClosedShaft)
{
    TestMesh m;
    makeShaft(m, 256);
    const int before = m.fn;
    ASSERT_EQ(before, shaftTriangles(256, 1, true));
    const SimplifyStats s = bestOfTrials(m, targetParams(before / 10));
    ASSERT_TRUE(s.ok) << s.message;
    EXPECT_EQ(s.facesBefore, before);
    EXPECT_NEAR(m.fn, before / 10, 2) << s.message;
    EXPECT_EQ(s.facesAfter, m.fn);
    EXPECT_GT(s.collapses, 0);
}

TEST(SimplifyStop, ReachesTargetFacesOnOpenTube)
{
    TestMesh m;
    makeTube(m, 200, 4);
    const int before = m.fn;
    const SimplifyStats s = bestOfTrials(m, targetParams(before / 4));
    ASSERT_TRUE(s.ok) << s.message;
    EXPECT_NEAR(m.fn, before / 4, 2) << s.message << " flip " << s.rejectedFlip << " shape " << s.rejectedCompactness
                                     << " feature " << s.rejectedFeature << " topo " << s.rejectedTopology;
    EXPECT_GT(s.boundaryEdges, 0);
}

TEST(SimplifyStop, ReductionPercentage)
{
    TestMesh m;
    makeShaft(m, 128);
    const int before = m.fn;
    SimplifyParams p;
    p.reductionPerc = 50;
    const SimplifyStats s = bestOfTrials(m, p);
    ASSERT_TRUE(s.ok) << s.message;
    EXPECT_EQ(s.targetFaces, before / 2);
    EXPECT_NEAR(m.fn, before / 2, 2);
}

TEST(SimplifyStop, MaxErrorIsHonoured)
{
    TestMesh original, m;
    makeShaft(original, 256);
    copyMesh(m, original);
    SimplifyParams p;
    p.maxError = 1e-3;
    const SimplifyStats s = bestOfTrials(m, p);
    ASSERT_TRUE(s.ok) << s.message;
    EXPECT_LT(m.fn, original.fn / 2);  // it did simplify ...
    // ... within the bound, measured independently of the simplifier's own error estimate:
    // the symmetric Hausdorff distance to the original. The bound is on the RMS distance to
    // the planes a collapse replaces, so the true maximum may exceed it a little.
    const SymmetricHausdorff h = symmetricHausdorff(original, m, 20000);
    EXPECT_LE(h.maxFraction(), 4 * p.maxError);

    // A tighter bound stops earlier, and is honoured too.
    TestMesh tight;
    copyMesh(tight, original);
    p.maxError = 1e-5;
    ASSERT_TRUE(bestOfTrials(tight, p).ok);
    EXPECT_GT(tight.fn, m.fn);
    EXPECT_LE(symmetricHausdorff(original, tight, 20000).maxFraction(), 4 * p.maxError);
}
