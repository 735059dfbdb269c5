// Where a collapse may put its vertex: the quadric's own minimum, and where the merged
// planes meet in a line (a crease, a cylinder's strips) so that no single minimum exists,
// the point of that line nearest the edge.
#include "simplify/cad_edge_collapse.h"

#include <gtest/gtest.h>

using namespace cadlod;

namespace {

Quadric planes(std::initializer_list<std::pair<vcg::Point3d, double>> list)
{
    Quadric q;
    q.SetZero();
    for (const auto& [normal, offset] : list)
        q += planeQuadric(normal, offset, 1.0);
    return q;
}

}  // namespace

TEST(Placement, TwoPlanesMeetInALineWithoutASingleMinimum)
{
    // x = 1 and y = 2: every point (1, 2, z) costs nothing.
    const Quadric q = planes({{vcg::Point3d(1, 0, 0), 1.0}, {vcg::Point3d(0, 1, 0), 2.0}});
    vcg::Point3d x(0, 0, 0);
    EXPECT_FALSE(quadricMinimum(q, x));

    ASSERT_TRUE(nearestMinimum(q, vcg::Point3d(0.9, 2.2, 5.0), x));
    EXPECT_NEAR(x[0], 1.0, 1e-3);
    EXPECT_NEAR(x[1], 2.0, 1e-3);
    EXPECT_NEAR(x[2], 5.0, 1e-9);  // along the line, the point nearest the edge's middle
    EXPECT_LT(applyQuadric(q, x), 1e-5);
}

TEST(Placement, ThreePlanesGiveTheirCorner)
{
    const Quadric q = planes({{vcg::Point3d(1, 0, 0), 1.0}, {vcg::Point3d(0, 1, 0), 2.0}, {vcg::Point3d(0, 0, 1), 3.0}});
    vcg::Point3d exact(0, 0, 0), near(0, 0, 0);
    ASSERT_TRUE(quadricMinimum(q, exact));
    ASSERT_TRUE(nearestMinimum(q, vcg::Point3d(0, 0, 0), near));
    EXPECT_LT(vcg::Distance(exact, vcg::Point3d(1, 2, 3)), 1e-9);
    // Pulled towards the middle by a thousandth of the trace: a small share of the way.
    EXPECT_LT(vcg::Distance(near, exact), 0.01 * vcg::Distance(exact, vcg::Point3d(0, 0, 0)));
}

TEST(Placement, NoPlanesNoMinimum)
{
    Quadric q;
    q.SetZero();
    vcg::Point3d x(0, 0, 0);
    EXPECT_FALSE(nearestMinimum(q, vcg::Point3d(1, 1, 1), x));
}
