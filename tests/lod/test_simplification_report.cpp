#include "measure/simplification_report.h"
#include "simplify/simplify.h"
#include "test_mesh.h"

#include <gtest/gtest.h>

#include <vcg/complex/algorithms/create/platonic.h>

#include <numeric>

using namespace cadlod;
using cadlod::test::TestMesh;

namespace {

void sphere(TestMesh& m, int subdivisions)
{
    vcg::tri::Sphere(m, subdivisions);
    vcg::tri::UpdateTopology<TestMesh>::VertexFace(m);
}

}  // namespace

TEST(SimplificationReport, IdenticalMeshesAreAtZeroDistance)
{
    TestMesh a, b;
    sphere(a, 3);
    sphere(b, 3);
    const SimplificationReport r = compareWithOriginal(a, b, 2000);
    EXPECT_EQ(r.facesBefore, r.facesAfter);
    EXPECT_LT(r.distance.max(), 1e-6);
    EXPECT_NEAR(r.before.mean, r.after.mean, 1e-12);
    EXPECT_EQ(r.histogramBefore, r.histogramAfter);
}

TEST(SimplificationReport, CoarserSphereIsFurtherAndCountsAddUp)
{
    TestMesh fine, coarse;
    sphere(fine, 4);
    sphere(coarse, 2);
    std::vector<double> vertexDistance;
    const SimplificationReport r = compareWithOriginal(fine, coarse, 5000, &vertexDistance);
    EXPECT_EQ(r.facesBefore, 5120);
    EXPECT_EQ(r.facesAfter, 320);
    // The coarse sphere's vertices lie on the unit sphere, its faces cut inside it: the
    // distance is the sagitta of its triangles, a few hundredths.
    EXPECT_GT(r.distance.max(), 0.01);
    EXPECT_LT(r.distance.max(), 0.1);
    EXPECT_LE(r.distance.mean(), r.distance.rms());
    EXPECT_LE(r.distance.rms(), r.distance.max());
    EXPECT_NEAR(r.distance.diagonal, 2.0 * std::sqrt(3.0), 1e-3);
    EXPECT_EQ(std::accumulate(r.histogramBefore.begin(), r.histogramBefore.end(), std::size_t(0)), 5120u);
    EXPECT_EQ(std::accumulate(r.histogramAfter.begin(), r.histogramAfter.end(), std::size_t(0)), 320u);
    // Both spheres are made of near-equilateral triangles.
    EXPECT_GT(r.after.mean, 0.9);
    ASSERT_EQ(vertexDistance.size(), coarse.vert.size());
    for (double d : vertexDistance)  // vertices of the coarse sphere are on the fine one, almost
        EXPECT_LT(d, 0.02);
    EXPECT_EQ(histogramLines(r).size(), 10u);
    EXPECT_NE(histogramLines(r)[9].find("0.9-1.0 | before"), std::string::npos) << histogramLines(r)[9];
}
