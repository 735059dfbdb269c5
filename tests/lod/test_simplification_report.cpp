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

// The rule by which `cadlod report` and the GUI's Simplification Report refuse a pair:
// sizes more than 1.5x apart (a unit ratio named), boxes apart or barely overlapping.
TEST(SimplificationReport, PairsThatCannotBeASimplificationAreNamed)
{
    using Box = vcg::Box3d;
    const Box part(vcg::Point3d(0, 0, 0), vcg::Point3d(180, 100, 40));
    EXPECT_EQ(whyNotASimplification(part, part), "");
    const Box slightlySmaller(vcg::Point3d(1, 1, 1), vcg::Point3d(170, 95, 38));
    EXPECT_EQ(whyNotASimplification(part, slightlySmaller), "");
    const Box inMetres(vcg::Point3d(0, 0, 0), vcg::Point3d(0.18, 0.1, 0.04));
    const std::string metres = whyNotASimplification(part, inMetres);
    EXPECT_NE(metres.find("the result is 1000x smaller"), std::string::npos) << metres;
    EXPECT_NE(metres.find("a different unit (mm and m)?"), std::string::npos) << metres;
    const Box apart(vcg::Point3d(500, 0, 0), vcg::Point3d(680, 100, 40));
    EXPECT_EQ(whyNotASimplification(part, apart).rfind("their bounding boxes do not overlap", 0), 0u);
    const Box corner(vcg::Point3d(170, 90, 30), vcg::Point3d(350, 190, 70));
    EXPECT_NE(whyNotASimplification(part, corner).find("barely overlap"), std::string::npos);
    const Box twiceAsLarge(vcg::Point3d(0, 0, 0), vcg::Point3d(360, 200, 80));
    EXPECT_NE(whyNotASimplification(part, twiceAsLarge).find("2.0x larger"), std::string::npos);
    // A flat board and its flat simplification (zero thickness) do overlap.
    const Box board(vcg::Point3d(0, 0, 0), vcg::Point3d(100, 80, 0));
    EXPECT_EQ(whyNotASimplification(board, board), "");
}
