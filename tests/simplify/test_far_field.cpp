// The input's points an LOD chain's sessions measure the distance of each collapse from
// (core/far_field.h): the vertices, the centroids and, before the far field, points along
// the edges, each edge once.
#include "test_mesh.h"

#include "simplify/far_field.h"

#include <vcg/complex/algorithms/update/topology.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <tuple>

using namespace cadlod;
using namespace cadlod::test;

namespace {

// The unit square in z = 0 as two faces sharing the diagonal (0,0)-(1,1).
void makeSquare(TestMesh& m)
{
    addFaces(m, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
    vcg::tri::UpdateTopology<TestMesh>::VertexFace(m);
}

std::set<std::tuple<long, long, long>> distinct(const std::vector<vcg::Point3d>& points)
{
    std::set<std::tuple<long, long, long>> keys;
    for (const vcg::Point3d& p : points)
        keys.insert({std::lround(p[0] * 1e6), std::lround(p[1] * 1e6), std::lround(p[2] * 1e6)});
    return keys;
}

}  // namespace

TEST(FarFieldPoints, CornersAndCentroidsAlone)
{
    TestMesh m;
    makeSquare(m);
    const FarFieldDistances<TestMesh> points(m);
    EXPECT_EQ(points.points().size(), 6u);  // 4 vertices, 2 centroids
}

TEST(FarFieldPoints, EdgesAreSplitAtTheSpacingAndTheSharedOneIsTakenOnce)
{
    TestMesh m;
    makeSquare(m);
    const FarFieldDistances<TestMesh> points(m, 0, 0.25);
    // 6, and 3 points inside each of the 4 sides (length 1, 4 pieces), and 5 inside the
    // diagonal (length 1.41, 6 pieces), which both faces hold.
    EXPECT_EQ(points.points().size(), 6u + 4 * 3 + 5);
    EXPECT_EQ(distinct(points.points()).size(), points.points().size());
    for (const vcg::Point3d& p : points.points()) {
        EXPECT_GE(std::min(p[0], p[1]), -1e-12);
        EXPECT_LE(std::max(p[0], p[1]), 1 + 1e-12);
    }
    // No two points along one side are farther apart than the spacing.
    std::vector<double> bottom;
    for (const vcg::Point3d& p : points.points())
        if (std::abs(p[1]) < 1e-12)
            bottom.push_back(p[0]);
    std::sort(bottom.begin(), bottom.end());
    ASSERT_EQ(bottom.size(), 5u);
    for (std::size_t i = 1; i < bottom.size(); ++i)
        EXPECT_LE(bottom[i] - bottom[i - 1], 0.25 + 1e-12);
}

TEST(FarFieldPoints, TheFarFieldKeepsCornersAndCentroidsOnly)
{
    TestMesh m;
    makeSquare(m);
    FarFieldDistances<TestMesh> points(m, 0, 0.25);
    points.start(m);
    EXPECT_EQ(points.points().size(), 6u);
    EXPECT_TRUE(points.started());
}

TEST(FarFieldPoints, AtMostMaxPointsAreKept)
{
    TestMesh m;
    makeSquare(m);
    const FarFieldDistances<TestMesh> points(m, 10, 0.25);
    EXPECT_EQ(points.points().size(), 8u);  // every third of 23: at most 10
}
