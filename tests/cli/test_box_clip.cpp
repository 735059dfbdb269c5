// A triangle cut to a box (box_clip.h): what lies inside, with its corners' attributes
// interpolated along the cut edges.
#include "assembly/box_clip.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cadlod::test {
namespace {

double areaOf(const flt::Part& part)
{
    double area = 0;
    for (const flt::Triangle& t : part.triangles) {
        const flt::Vec3d &a = part.positions[t[0]], &b = part.positions[t[1]], &c = part.positions[t[2]];
        const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
        area += std::abs(ux * vy - uy * vx) / 2;
    }
    return area;
}

Box3 box(double x0, double y0, double x1, double y1)
{
    Box3 b;
    b.add(flt::Vec3d{x0, y0, -1});
    b.add(flt::Vec3d{x1, y1, 1});
    return b;
}

}  // namespace

// The right triangle (0,0) (2,0) (0,2), with a colour per corner: a unit box at the origin
// holds a square of it; a box past its hypotenuse, nothing; a box around it, all of it.
TEST(BoxClip, KeepsWhatLiesInsideWithItsAttributesInterpolated)
{
    flt::Part part;
    part.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    part.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    part.vertexColors = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 1, 1}};
    part.triangles = {{0, 1, 2}};

    flt::Part square;
    appendClippedTriangle(part, 0, box(0, 0, 1, 1), square);
    EXPECT_NEAR(areaOf(square), 1.0, 1e-12);
    ASSERT_EQ(square.positions.size(), square.vertexColors.size());
    ASSERT_EQ(square.positions.size(), square.normals.size());
    for (std::size_t v = 0; v < square.positions.size(); ++v) {
        const flt::Vec3d& p = square.positions[v];
        EXPECT_LE(p[0], 1 + 1e-12);
        EXPECT_LE(p[1], 1 + 1e-12);
        // Linear colours: green is x / 2, blue y / 2.
        EXPECT_NEAR(square.vertexColors[v][1], p[0] / 2, 1e-6);
        EXPECT_NEAR(square.vertexColors[v][2], p[1] / 2, 1e-6);
        EXPECT_NEAR(square.normals[v][2], 1.0f, 1e-6);
    }

    flt::Part none;
    appendClippedTriangle(part, 0, box(1.5, 1.5, 3, 3), none);
    EXPECT_TRUE(none.triangles.empty());

    flt::Part whole;
    appendClippedTriangle(part, 0, box(-1, -1, 3, 3), whole);
    EXPECT_NEAR(areaOf(whole), 2.0, 1e-12);
}

}  // namespace cadlod::test
