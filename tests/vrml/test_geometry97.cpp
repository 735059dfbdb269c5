// VRML97 geometry: transforms, winding, triangulation, normals, index rules, parts,
// primitives and grouping nodes, checked against hand-computed values.
#include "vrml_test_util.h"

#include <gtest/gtest.h>

using namespace cadlod::vrml;
using namespace cadlod::vrml::test;

TEST(Vrml97Transform, FullTransformOrderMatchesHandComputedPoint)
{
    // P' = T·C·R·SR·S·-SR·-C·P with P = (2,0,0), C = (1,0,0), S = (2,1,1), R = 90° about z,
    // SR = identity, T = (0,0,5): -C -> (1,0,0); S -> (2,0,0); R -> (0,2,0); C -> (1,2,0); T -> (1,2,5).
    const Scene s = load(R"(#VRML V2.0 utf8
Transform { translation 0 0 5 center 1 0 0 rotation 0 0 1 1.5707963 scale 2 1 1
  children Shape { geometry IndexedFaceSet { coord Coordinate { point [ 2 0 0, 2 1 0, 2 0 1 ] } coordIndex [ 0 1 2 ] } } }
)");
    EXPECT_TRUE(hasPoint(s, 1, 2, 5));
    // (2,1,0): -C (1,1,0); S (2,1,0); R (-1,2,0); C (0,2,0); T (0,2,5)
    EXPECT_TRUE(hasPoint(s, 0, 2, 5));
}

TEST(Vrml97Transform, ScaleOrientationRotatesTheScaleAxes)
{
    // Scale 2 along the axis x rotated 90° about z (i.e. along y): (0,1,0) -> (0,2,0).
    const Scene s = load(R"(#VRML V2.0 utf8
Transform { scale 2 1 1 scaleOrientation 0 0 1 1.5707963
  children Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 1 0, 1 0 0, 0 0 1 ] } coordIndex [ 0 1 2 ] } } }
)");
    EXPECT_TRUE(hasPoint(s, 0, 2, 0, 1e-4f));
    EXPECT_TRUE(hasPoint(s, 1, 0, 0, 1e-4f));
}

TEST(Vrml97Transform, NestedTransformsComposeParentTimesChildAndUnitScaleApplies)
{
    ImportOptions mm;
    mm.unitScale = 0.001;
    const Scene s = load(R"(#VRML V2.0 utf8
Transform { translation 1000 0 0 children Transform { scale 10 10 10
  children Shape { geometry IndexedFaceSet { coord Coordinate { point [ 1 0 0, 0 1 0, 0 0 1 ] } coordIndex [ 0 1 2 ] } } } }
)", mm);
    EXPECT_TRUE(hasPoint(s, 1.01f, 0, 0));
    EXPECT_TRUE(hasPoint(s, 1.0f, 0.01f, 0));
}

TEST(Vrml97Winding, CcwFalseAndMirroringFlipTriangles)
{
    const std::string tri = "coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] } coordIndex [ 0 1 2 ]";
    auto nz = [](const Scene& s) { return triangleNormal(triangles(s).at(0))[2]; };
    EXPECT_GT(nz(load("#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { " + tri + " } }")), 0);
    EXPECT_LT(nz(load("#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { ccw FALSE " + tri + " } }")), 0);
    // Mirror in x: the geometric winding flips, so the triangle is reversed to keep its front (+z).
    EXPECT_GT(nz(load("#VRML V2.0 utf8\nTransform { scale -1 1 1 children Shape { geometry IndexedFaceSet { " + tri +
                      " } } }")),
              0);
}

TEST(Vrml97Triangulation, ConcavePolygonIsEarClippedInsideItsOutline)
{
    // An L-shaped hexagon (area 3) in the plane x + y + z = const is not fan-triangulable from vertex 0.
    const std::string points = "0 0 0, 2 0 0, 2 1 0, 1 1 0, 1 2 0, 0 2 0";
    const std::string text = "#VRML V2.0 utf8\nTransform { rotation 1 1 0 0.7 children Shape { geometry IndexedFaceSet "
                             "{ convex FALSE coord Coordinate { point [ " + points + " ] } coordIndex [ 3 4 5 0 1 2 ] } } }";
    const Scene s = load(text);
    const auto tris = triangles(s);
    ASSERT_EQ(tris.size(), 4u);
    double total = 0;
    for (const auto& t : tris) total += area(t);
    EXPECT_NEAR(total, 3.0, 1e-4);  // no overlap, nothing outside the L
    const Vec3f n0 = triangleNormal(tris[0]);
    for (const auto& t : tris) {
        const Vec3f n = triangleNormal(t);
        EXPECT_GT(n[0] * n0[0] + n[1] * n0[1] + n[2] * n0[2], 0) << "consistent winding";
    }
}

TEST(Vrml97Faces, BadAndDegenerateFacesAreSkippedAndCounted)
{
    const Scene s = load(ifs97("0 0 0, 1 0 0, 1 1 0, 0 1 0", "0 1 2 -1 0 1 -1 0 1 99 -1 -5 1 2 -1 3 3 3 -1 0 2 3"));
    EXPECT_EQ(s.triangleCount(), 2u);
    EXPECT_EQ(s.stats.skippedFaces, 4u);
    EXPECT_EQ(s.diagnostics.count("bad index"), 2);
    EXPECT_EQ(s.diagnostics.count("degenerate face"), 2);
}

TEST(Vrml97Normals, CreaseAngleSplitsSharpEdgesAndSmoothsShallowOnes)
{
    // Two quads meeting at 90° along x = 1; a third continues the second at ~11°.
    const std::string pts = "0 0 0, 1 0 0, 1 1 0, 0 1 0, 1 0 -1, 1 1 -1, 1.2 0 -2, 1.2 1 -2";
    const std::string idx = "0 1 2 3 -1 1 4 5 2 -1 4 6 7 5 -1";
    auto distinctNormals = [](const Scene& s) {
        std::vector<Vec3f> n;
        for (const Part& p : s.parts)
            for (const Vec3f& v : p.normals)
                if (std::find(n.begin(), n.end(), v) == n.end()) n.push_back(v);
        return n.size();
    };
    const Scene flat = load(ifs97(pts, idx));                          // creaseAngle 0: faceted
    const Scene half = load(ifs97(pts, idx, "creaseAngle 0.5"));       // 90° sharp, 11° smooth
    const Scene smooth = load(ifs97(pts, idx, "creaseAngle 3.14159"));  // all smooth
    EXPECT_EQ(distinctNormals(flat), 3u);
    EXPECT_EQ(flat.vertexCount(), 12u);
    EXPECT_EQ(half.vertexCount(), 10u);  // split only along the 90° edge
    EXPECT_EQ(smooth.vertexCount(), 8u);
    EXPECT_GT(distinctNormals(half), 3u);
}

TEST(Vrml97Normals, FileNormalsAreKeptOrRecomputedOnRequest)
{
    const std::string text = ifs97("0 0 0, 1 0 0, 0 1 0", "0 1 2",
                                   "normal Normal { vector [ 0 1 0 ] } normalPerVertex FALSE");
    const Scene kept = load(text);
    EXPECT_EQ(kept.parts[0].normals[0], (Vec3f{0, 1, 0}));
    ImportOptions recompute;
    recompute.recomputeNormals = true;
    const Scene redone = load(text, recompute);
    EXPECT_EQ(redone.parts[0].normals[0], (Vec3f{0, 0, 1}));
}

TEST(Vrml97Colors, PerFaceWithAndWithoutIndexAndPerVertexFallbackToCoordIndex)
{
    const std::string pts = "0 0 0, 1 0 0, 1 1 0, 0 1 0";
    const std::string colors = "color Color { color [ 1 0 0, 0 1 0, 0 0 1, 1 1 1 ] } ";
    const Scene byOrder = load(ifs97(pts, "0 1 2 -1 0 2 3", colors + "colorPerVertex FALSE"));
    ASSERT_EQ(byOrder.parts[0].faceColors.size(), 2u);
    EXPECT_EQ(byOrder.parts[0].faceColors[1], (Rgba8{0, 255, 0, 255}));
    const Scene indexed = load(ifs97(pts, "0 1 2 -1 0 2 3", colors + "colorPerVertex FALSE colorIndex [ 2 3 ]"));
    EXPECT_EQ(indexed.parts[0].faceColors[0], (Rgba8{0, 0, 255, 255}));
    const Scene perVertex = load(ifs97(pts, "0 1 2 -1 0 2 3", colors));
    const Part& p = perVertex.parts[0];
    ASSERT_EQ(p.colors.size(), p.positions.size());
    for (size_t i = 0; i < p.positions.size(); ++i)
        if (p.positions[i] == Vec3f{1, 1, 0}) {
            EXPECT_EQ(p.colors[i], (Rgba8{0, 0, 255, 255}));
        }
    const Scene perCorner = load(ifs97(pts, "0 1 2 -1 0 2 3", colors + "colorIndex [ 3 3 3 -1 1 1 1 -1 ]"));
    EXPECT_EQ(perCorner.parts[0].colors.size(), 6u);  // vertex 0 and 2 split by color
}

TEST(Vrml97Parts, NamedByNearestDefWithMaterialColorAndUseGivesASecondInstance)
{
    const Scene s = load(R"(#VRML V2.0 utf8
DEF Bolt Transform { children Shape {
  appearance Appearance { material Material { diffuseColor 0 0 1 transparency 0.5 } }
  geometry Box {} } }
Transform { translation 5 0 0 children USE Bolt }
Group { children Shape { geometry Sphere {} } }
)");
    ASSERT_EQ(s.parts.size(), 3u);
    EXPECT_EQ(s.parts[0].name, "Bolt");
    EXPECT_EQ(s.parts[1].name, "Bolt");
    EXPECT_FLOAT_EQ(s.parts[0].color[2], 1.0f);
    EXPECT_FLOAT_EQ(s.parts[0].color[3], 0.5f);
    EXPECT_NE(s.parts[2].name.find("Shape"), std::string::npos);
    EXPECT_TRUE(hasPoint(s, 6, 1, 1));
}

TEST(Vrml97Parts, UsedInstancesAreNamedAfterTheirEnclosingDef)
{
    // CAD assemblies DEF each placement and USE the shared part geometry in it.
    const Scene s = load(R"(#VRML V2.0 utf8
DEF HOUSING_A Transform { children DEF HOUSING Shape { geometry Box {} } }
DEF HOUSING_B Transform { translation 5 0 0 children USE HOUSING }
DEF SHAFT Transform { children Shape { geometry Sphere {} } }
)");
    ASSERT_EQ(s.parts.size(), 3u);
    EXPECT_EQ(s.parts[0].name, "HOUSING_A/HOUSING");
    EXPECT_EQ(s.parts[1].name, "HOUSING_B/HOUSING");
    EXPECT_EQ(s.parts[2].name, "SHAFT");  // a DEF used once keeps its plain name
}

TEST(Vrml97Grouping, SwitchChoosesOneLodTakesTheFinestBillboardAnchorCollisionGroup)
{
    const Scene s = load(R"(#VRML V2.0 utf8
Switch { whichChoice 1 choice [ Shape { geometry Sphere {} } Shape { geometry Box {} } ] }
Switch { whichChoice -1 choice Shape { geometry Box {} } }
LOD { range [ 10 ] level [ Shape { geometry Box {} } Shape { geometry Sphere {} } ] }
Billboard { children Anchor { children Collision { children Shape { geometry Box {} } } } }
)");
    EXPECT_EQ(s.triangleCount(), 36u);  // three boxes
}

TEST(Vrml97Primitives, TriangleCountsAndExtents)
{
    const Scene box = load("#VRML V2.0 utf8\nShape { geometry Box { size 2 4 6 } }");
    EXPECT_EQ(box.triangleCount(), 12u);
    EXPECT_TRUE(hasPoint(box, 1, 2, 3));
    const Scene cyl = load("#VRML V2.0 utf8\nShape { geometry Cylinder { radius 2 height 3 top FALSE } }");
    EXPECT_EQ(cyl.triangleCount(), size_t(2 * 24 + 22));
    EXPECT_TRUE(hasPoint(cyl, 0, 1.5f, 2));
    const Scene cone = load("#VRML V2.0 utf8\nShape { geometry Cone { bottom FALSE } }");
    EXPECT_EQ(cone.triangleCount(), 24u);
    const Scene sphere = load("#VRML V2.0 utf8\nShape { geometry Sphere { radius 3 } }");
    for (const Part& p : sphere.parts)
        for (const Vec3f& v : p.positions)
            EXPECT_NEAR(std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), 3.0, 1e-5);
}

TEST(Vrml97Primitives, ElevationGridHeightsAndUpwardFaces)
{
    const Scene s = load(R"(#VRML V2.0 utf8
Shape { geometry ElevationGrid { xDimension 3 zDimension 2 xSpacing 2 zSpacing 1 height [ 0 1 2 3 4 5 ] } }
)");
    EXPECT_EQ(s.triangleCount(), 4u);
    EXPECT_TRUE(hasPoint(s, 4, 5, 1));
    for (const auto& t : triangles(s)) EXPECT_GT(triangleNormal(t)[1], 0);
}

TEST(Vrml97Primitives, ExtrusionAlongAStraightSpineIsAClosedPrism)
{
    const Scene s = load(R"(#VRML V2.0 utf8
Shape { geometry Extrusion { crossSection [ 1 1, 1 -1, -1 -1, -1 1, 1 1 ] spine [ 0 0 0, 0 2 0, 0 4 0 ] } }
)");
    EXPECT_EQ(s.triangleCount(), size_t(2 * 4 * 2 + 2 * 2));
    EXPECT_TRUE(hasPoint(s, 1, 4, -1));
    double total = 0;
    for (const auto& t : triangles(s)) total += area(t);
    EXPECT_NEAR(total, 4 * 2 * 4 + 2 * 4, 1e-4);
}

TEST(Vrml97Geometry, LineAndPointSetsAreCountedNotImported)
{
    const Scene s = load(R"(#VRML V2.0 utf8
Shape { geometry IndexedLineSet { coord Coordinate { point [ 0 0 0, 1 0 0 ] } coordIndex [ 0 1 ] } }
Shape { geometry PointSet { coord Coordinate { point [ 0 0 0 ] } } }
Shape { geometry Text { string "x" } }
)");
    EXPECT_EQ(s.triangleCount(), 0u);
    EXPECT_EQ(s.stats.lineSets, 1u);
    EXPECT_EQ(s.stats.pointSets, 1u);
    EXPECT_EQ(s.diagnostics.count("unsupported geometry"), 1);
}

TEST(Vrml97Primitives, ClosedPrimitivesFaceOutwards)
{
    const char* shapes[] = {
        "Box { size 2 2 2 }", "Sphere {}", "Cylinder {}", "Cone {}",
        "Extrusion { crossSection [ 1 1, 1 -1, -1 -1, -1 1, 1 1 ] spine [ 0 -1 0, 0 1 0 ] }",
        "Extrusion { }"};
    for (const char* shape : shapes) {
        SCOPED_TRACE(shape);
        const Scene s = load(std::string("#VRML V2.0 utf8\nShape { geometry ") + shape + " }\n");
        ASSERT_GT(s.triangleCount(), 0u);
        Vec3f center{0, 0, 0};
        size_t n = 0;
        for (const Part& p : s.parts)
            for (const Vec3f& v : p.positions) {
                for (int k = 0; k < 3; ++k) center[size_t(k)] += v[size_t(k)];
                ++n;
            }
        for (float& c : center) c /= float(n);
        for (const auto& t : triangles(s)) {
            const Vec3f nrm = triangleNormal(t);
            float out = 0;
            for (int k = 0; k < 3; ++k) out += nrm[size_t(k)] * ((t[0][size_t(k)] + t[1][size_t(k)] + t[2][size_t(k)]) / 3 - center[size_t(k)]);
            EXPECT_GT(out, 0);
        }
    }
}
