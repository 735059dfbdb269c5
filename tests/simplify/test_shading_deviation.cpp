// The shading deviation (core/shading_deviation.h): the share of two surfaces lit visibly
// differently, each point's interpolated crease-split normal against the other surface's
// at the closest point.
#include "cad_meshes.h"
#include "test_mesh.h"

#include "measure/shading_deviation.h"

#include <gtest/gtest.h>

using namespace cadlod;
using namespace cadlod::test;

namespace {

// A closed cylinder of radius 10 and length 40, `segments` around, with fan end caps.
void cylinder(TestMesh& m, int segments)
{
    CadBuilder b;
    RevolveSpec spec;
    spec.segments = segments;
    revolve(b, {{0, 0}, {0, 10}, {40, 10}, {40, 0}}, spec);
    b.build(m);
}

double deviation(TestMesh& input, TestMesh& result)
{
    const detail::ClosestFace<TestMesh> toInput(input), toResult(result);
    const ShadingDeviation d = shadingDeviation(ShadingInput<TestMesh>(input, toInput, 20000, 7), result, toResult);
    EXPECT_EQ(d.samples, 40000u);
    return d.share();
}

}  // namespace

TEST(ShadingDeviation, ASurfaceAgainstItselfIsLitTheSame)
{
    TestMesh a, b;
    cylinder(a, 48);
    cylinder(b, 48);
    EXPECT_EQ(deviation(a, b), 0.0);
}

// Ten facets 36° apart are drawn flat (split at the 30° crease), each lit differently from
// the round cylinder across most of its width; 24 facets 15° apart are smooth and their
// interpolated normals follow the round one. The end caps are flat in all three.
TEST(ShadingDeviation, FacetsPastTheCreaseAngleShowWhereSmoothOnesDoNot)
{
    TestMesh fine, faceted, smooth;
    cylinder(fine, 96);
    cylinder(faceted, 10);
    cylinder(smooth, 24);
    const double facets = deviation(fine, faceted);
    const double round = deviation(fine, smooth);
    // The side is 800π of the surface's 1000π; on a 36° facet the flat normal is more than
    // 0.06 (3.4°) from the round one on all but about a fifth of its width.
    EXPECT_GT(facets, 0.5);
    EXPECT_LT(round, 0.05);
    EXPECT_LT(round * 10, facets);
}

// One face turned over in the result shows over its own area and what lies under it in the
// input, and beside it only where its neighbours' corner normals lose it from their fans
// (it meets them at 180°): a few times its area at most, not the whole side.
TEST(ShadingDeviation, AFaceTurnedOverCountsItsArea)
{
    TestMesh input, result;
    cylinder(input, 24);
    cylinder(result, 24);
    auto& f = result.face[30];  // a side face: the first 24 are the start cap's fan
    std::swap(f.V(1), f.V(2));
    double area = 0, turnedArea = 0;
    for (const auto& g : input.face)
        area += 0.5 * vcg::DoubleArea(g);
    turnedArea = 0.5 * vcg::DoubleArea(input.face[30]);
    const double share = deviation(input, result);
    EXPECT_GT(share, 0.5 * turnedArea / area);
    EXPECT_LT(share, 4.0 * turnedArea / area);
}
