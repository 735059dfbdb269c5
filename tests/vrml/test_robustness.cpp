// Hostile input: huge counts, huge faces, garbage, and the exact vertex welding.
#include "vrml/vertex_welding.h"
#include "vrml_test_util.h"

#include <gtest/gtest.h>

using namespace cadlod::vrml;
using namespace cadlod::vrml::test;

TEST(VrmlRobustness, AbsurdElevationGridDimensionsAreSkippedNotAllocated)
{
    const Scene s = load("#VRML V2.0 utf8\nShape { geometry ElevationGrid { xDimension 2000000000 zDimension 2000000000 "
                         "height [ 0 0 0 0 ] } }\n");
    EXPECT_EQ(s.triangleCount(), 0u);
    EXPECT_EQ(s.diagnostics.count("bad ElevationGrid"), 1);
}

TEST(VrmlRobustness, HugeConcaveFaceIsFannedInsteadOfStalling)
{
    std::string points, indices;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        points += std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0,";
        indices += std::to_string(i) + " ";
    }
    const Scene s = load(ifs97(points, indices, "convex FALSE"));
    EXPECT_EQ(s.triangleCount(), size_t(n - 2));
    EXPECT_EQ(s.diagnostics.count("huge face"), 1);
}

TEST(VrmlRobustness, GarbageAfterAValidHeaderKeepsEarlierGeometry)
{
    const Scene s = load("#VRML V2.0 utf8\nShape { geometry Box {} }\n} ] \x01\x02 {{{ \"unterminated\n");
    EXPECT_EQ(s.triangleCount(), 12u);
    EXPECT_EQ(s.diagnostics.count("syntax error"), 1);
}

TEST(VrmlRobustness, EmptyAndHeaderOnlyFiles)
{
    EXPECT_FALSE(importVrmlText("", "empty.wrl").ok());
    const Scene s = load("#VRML V1.0 ascii\n");
    EXPECT_EQ(s.triangleCount(), 0u);
}

TEST(VrmlWelding, CoincidentPointsAcrossPartsBecomeOneVertex)
{
    // Two face sets (CATIA style: one per face) sharing an edge, in different parts.
    const Scene s = load(R"(#VRML V2.0 utf8
DEF A Shape { geometry IndexedFaceSet { coord DEF P Coordinate { point [ 0 0 0, 1 0 0, 1 1 0, 0 1 0, -0 0 0 ] } coordIndex [ 0 1 2 ] } }
DEF B Shape { geometry IndexedFaceSet { coord USE P coordIndex [ 4 2 3 ] } }
)");
    ASSERT_EQ(s.parts.size(), 2u);
    ASSERT_EQ(s.vertexCount(), 6u);
    const Welding w = weldCoincidentVertices(s);
    EXPECT_EQ(w.weldedCount, 4u);  // -0 equals +0
    ASSERT_EQ(w.weldedIndex.size(), 6u);
    auto welded = [&](size_t part, float x, float y) {
        size_t offset = part == 0 ? 0 : s.parts[0].positions.size();
        for (size_t i = 0; i < s.parts[part].positions.size(); ++i)
            if (s.parts[part].positions[i][0] == x && s.parts[part].positions[i][1] == y) return w.weldedIndex[offset + i];
        return UINT32_MAX;
    };
    EXPECT_EQ(welded(0, 0, 0), welded(1, 0, 0));
    EXPECT_EQ(welded(0, 1, 1), welded(1, 1, 1));
    EXPECT_NE(welded(0, 1, 0), welded(1, 0, 1));
}

TEST(VrmlRobustness, ByteOrderMarkAndWindowsLineEndings)
{
    const Scene s = load("\xEF\xBB\xBF#VRML V2.0 utf8\r\nShape {\r\n geometry Box { size 1 1 1 }\r\n}\r\n");
    EXPECT_EQ(s.triangleCount(), 12u);
    EXPECT_EQ(s.diagnostics.total(), 0);
}

TEST(VrmlRobustness, WindowsNanTextEndsTheValueLikeAComment)
{
    // Some Windows exporters print 1.#QNAN: '#' starts a comment, the number reads as 1.
    const Scene s = load(ifs97("0 0 0, 1 0 0, 0 1.#QNAN\n 0", "0 1 2"));
    EXPECT_EQ(s.triangleCount(), 1u);
}
