// VRML 1.0 traversal-state machine.
#include "vrml_test_util.h"

#include <gtest/gtest.h>

using namespace cadlod::vrml;
using namespace cadlod::vrml::test;

namespace {
const char* kQuadCoords = "Coordinate3 { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0 ] }\n";
}

TEST(Vrml1State, SeparatorRestoresTransformAndPropertiesGroupDoesNot)
{
    const Scene s = load(std::string("#VRML V1.0 ascii\nSeparator {\n") + kQuadCoords +
                         "Separator { Translation { translation 10 0 0 } }\n"   // restored
                         "Group { Translation { translation 0 10 0 } }\n"      // not restored
                         "TransformSeparator { Translation { translation 0 0 10 } }\n"
                         "IndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }\n}\n");
    EXPECT_EQ(s.triangleCount(), 1u);
    EXPECT_EQ(s.version, 1);
    EXPECT_TRUE(hasPoint(s, 1, 10, 0));
    EXPECT_FALSE(hasPoint(s, 11, 10, 0));
}

TEST(Vrml1State, TransformNodesComposeInTraversalOrder)
{
    // Translation then Rotation(90° z) then Scale 2: P' = T·R·S·P; (1,0,0) -> (0,2,0) + (5,0,0).
    const Scene s = load(std::string("#VRML V1.0 ascii\nSeparator {\n") +
                         "Translation { translation 5 0 0 }\nRotation { rotation 0 0 1 1.5707963 }\n"
                         "Scale { scaleFactor 2 2 2 }\nCoordinate3 { point [ 1 0 0, 0 0 1, 0 0 2 ] }\n"
                         "IndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }\n}\n");
    EXPECT_TRUE(hasPoint(s, 5, 2, 0, 1e-4f));
}

TEST(Vrml1State, MatrixTransformUsesRowVectors)
{
    const Scene s = load(std::string("#VRML V1.0 ascii\nSeparator {\n") +
                         "MatrixTransform { matrix 1 0 0 0  0 1 0 0  0 0 1 0  3 4 5 1 }\n" + kQuadCoords +
                         "IndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }\n}\n");
    EXPECT_TRUE(hasPoint(s, 4, 5, 5));
}

TEST(Vrml1Materials, PerFaceIndexedAndPerVertexBindings)
{
    const std::string head = std::string("#VRML V1.0 ascii\nSeparator {\n") + kQuadCoords +
                             "Material { diffuseColor [ 1 0 0, 0 1 0, 0 0 1 ] }\n";
    const Scene perFace = load(head + "MaterialBinding { value PER_FACE }\n"
                                      "IndexedFaceSet { coordIndex [ 0, 1, 2, -1, 0, 2, 3, -1 ] }\n}\n");
    ASSERT_EQ(perFace.parts[0].faceColors.size(), 2u);
    EXPECT_EQ(perFace.parts[0].faceColors[1], (Rgba8{0, 255, 0, 255}));
    const Scene indexed = load(head + "MaterialBinding { value PER_FACE_INDEXED }\n"
                                      "IndexedFaceSet { coordIndex [ 0, 1, 2, -1, 0, 2, 3, -1 ] materialIndex [ 2, 0 ] }\n}\n");
    EXPECT_EQ(indexed.parts[0].faceColors[0], (Rgba8{0, 0, 255, 255}));
    EXPECT_EQ(indexed.parts[0].faceColors[1], (Rgba8{255, 0, 0, 255}));
    const Scene perVertex = load(head + "MaterialBinding { value PER_VERTEX }\n"
                                        "IndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }\n}\n");
    const Part& p = perVertex.parts[0];
    ASSERT_EQ(p.colors.size(), 3u);
    for (size_t i = 0; i < 3; ++i)
        if (p.positions[i] == Vec3f{1, 1, 0}) {
            EXPECT_EQ(p.colors[i], (Rgba8{0, 0, 255, 255}));
        }
    const Scene overall = load(head + "IndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }\n}\n");
    EXPECT_FLOAT_EQ(overall.parts[0].color[0], 1.0f);  // OVERALL: the first material
    EXPECT_TRUE(overall.parts[0].faceColors.empty());
}

TEST(Vrml1ShapeHints, ClockwiseOrderingFlipsAndUnknownFaceTypeTriangulates)
{
    const Scene cw = load(std::string("#VRML V1.0 ascii\nSeparator {\n") + kQuadCoords +
                          "ShapeHints { vertexOrdering CLOCKWISE }\nIndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }\n}\n");
    EXPECT_LT(triangleNormal(triangles(cw)[0])[2], 0);
    const Scene concave = load(std::string("#VRML V1.0 ascii\nSeparator {\n") +
                               "Coordinate3 { point [ 0 0 0, 2 0 0, 2 1 0, 1 1 0, 1 2 0, 0 2 0 ] }\n"
                               "ShapeHints { faceType UNKNOWN_FACE_TYPE }\n"
                               "IndexedFaceSet { coordIndex [ 3, 4, 5, 0, 1, 2, -1 ] }\n}\n");
    double total = 0;
    for (const auto& t : triangles(concave)) total += area(t);
    EXPECT_NEAR(total, 3.0, 1e-5);
}

TEST(Vrml1Primitives, CubeSphereCylinderConeAndSwitch)
{
    const Scene s = load(R"(#VRML V1.0 ascii
Separator {
  Cube { width 2 height 4 depth 6 }
  Switch { whichChild -1 Sphere {} }
  Switch { whichChild 0 Cylinder { parts SIDES } }
  Cone { parts BOTTOM }
}
)");
    EXPECT_EQ(s.triangleCount(), size_t(12 + 2 * 24 + 22));
    EXPECT_TRUE(hasPoint(s, 1, 2, 3));
}

TEST(Vrml1Parts, DefSeparatorNamesItsPart)
{
    const Scene s = load(std::string("#VRML V1.0 ascii\nDEF Housing Separator {\n") + kQuadCoords +
                         "IndexedFaceSet { coordIndex [ 0, 1, 2, -1 ] }\n Cube {}\n}\n");
    ASSERT_EQ(s.parts.size(), 1u);
    EXPECT_EQ(s.parts[0].name, "Housing");
    EXPECT_EQ(s.triangleCount(), 13u);
}
