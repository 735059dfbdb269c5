// The shading-error measure: zero for the same surface however it is triangulated or its
// vertices split, clearly above zero for a moved vertex, a tilted or flipped face or a
// missing part, and the same figures on every run.
#include "ply_read.h"
#include "shading_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using cadlod::shading::IndexedMesh;
using cadlod::shading::Result;

namespace {

std::uint32_t addVertex(IndexedMesh& m, double x, double y, double z)
{
    m.xyz.insert(m.xyz.end(), {x, y, z});
    return std::uint32_t(m.xyz.size() / 3 - 1);
}

void addTri(IndexedMesh& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) { m.tri.insert(m.tri.end(), {a, b, c}); }

enum class Top { DiagonalA, DiagonalB, CentreFan };

// Closed box [x0,x0+sx]x[0,sy]x[0,sz], outward faces; its top face (z = sz) triangulated as asked.
void addBox(IndexedMesh& m, double x0, double sx, double sy, double sz, Top top = Top::DiagonalA)
{
    std::uint32_t v[8];
    for (int i = 0; i < 8; ++i)
        v[i] = addVertex(m, x0 + ((i & 1) ? sx : 0), (i & 2) ? sy : 0, (i & 4) ? sz : 0);
    auto quad = [&](int a, int b, int c, int d) {  // counter-clockwise seen from outside
        addTri(m, v[a], v[b], v[c]);
        addTri(m, v[a], v[c], v[d]);
    };
    quad(0, 2, 3, 1);  // bottom
    quad(0, 1, 5, 4);  // y = 0
    quad(1, 3, 7, 5);  // x = x0 + sx
    quad(3, 2, 6, 7);  // y = sy
    quad(2, 0, 4, 6);  // x = x0
    switch (top) {
    case Top::DiagonalA: quad(4, 5, 7, 6); break;
    case Top::DiagonalB:
        addTri(m, v[4], v[5], v[6]);
        addTri(m, v[5], v[7], v[6]);
        break;
    case Top::CentreFan: {
        const std::uint32_t c = addVertex(m, x0 + 0.37 * sx, 0.61 * sy, sz);
        addTri(m, v[4], v[5], c);
        addTri(m, v[5], v[7], c);
        addTri(m, v[7], v[6], c);
        addTri(m, v[6], v[4], c);
        break;
    }
    }
}

// Closed cylinder along z, radius r, height h, `segments` around, flat caps (centre fans).
IndexedMesh cylinder(int segments, double r = 1.0, double h = 2.0)
{
    IndexedMesh m;
    const std::uint32_t bottomCentre = addVertex(m, 0, 0, 0), topCentre = addVertex(m, 0, 0, h);
    for (int i = 0; i < segments; ++i) {
        const double a = 2 * M_PI * i / segments;
        addVertex(m, r * std::cos(a), r * std::sin(a), 0);
        addVertex(m, r * std::cos(a), r * std::sin(a), h);
    }
    for (int i = 0; i < segments; ++i) {
        const std::uint32_t b0 = 2 + 2 * i, t0 = b0 + 1;
        const std::uint32_t b1 = 2 + 2 * ((i + 1) % segments), t1 = b1 + 1;
        addTri(m, b0, b1, t1);
        addTri(m, b0, t1, t0);
        addTri(m, bottomCentre, b1, b0);
        addTri(m, topCentre, t0, t1);
    }
    return m;
}

// Every triangle with its own three vertices (as an unwelded VRML export writes them).
IndexedMesh unwelded(const IndexedMesh& m)
{
    IndexedMesh out;
    for (std::uint32_t v : m.tri) {
        addVertex(out, m.xyz[3 * v], m.xyz[3 * v + 1], m.xyz[3 * v + 2]);
        out.tri.push_back(std::uint32_t(out.tri.size()));
    }
    return out;
}

Result measure(const IndexedMesh& a, const IndexedMesh& b) { return cadlod::shading::compare(a.ref(), b.ref()); }

}  // namespace

TEST(ShadingError, ViewsAreTwelveUnitDirectionsOffTheCoordinatePlanes)
{
    const auto dirs = cadlod::shading::viewDirections();
    ASSERT_EQ(dirs.size(), 12u);
    double closest = 2;
    for (std::size_t i = 0; i < dirs.size(); ++i) {
        EXPECT_NEAR(dirs[i][0] * dirs[i][0] + dirs[i][1] * dirs[i][1] + dirs[i][2] * dirs[i][2], 1.0, 1e-12);
        for (double c : dirs[i])
            EXPECT_GT(std::abs(c), 0.02);  // no view along a coordinate plane of a box
        for (std::size_t j = 0; j < i; ++j) {
            const double d = dirs[i][0] * dirs[j][0] + dirs[i][1] * dirs[j][1] + dirs[i][2] * dirs[j][2];
            closest = std::min(closest, std::acos(std::max(-1.0, std::min(1.0, d))));
        }
    }
    EXPECT_NEAR(closest * 180 / M_PI, 63.43, 0.1);  // icosahedron: neighbours 63.4° apart
}

TEST(ShadingError, IdenticalMeshesDifferNowhere)
{
    IndexedMesh m = cylinder(48);
    addBox(m, 1.5, 1, 1, 1);
    const Result r = measure(m, m);
    EXPECT_GT(r.either, 10000);
    EXPECT_EQ(r.silhouette, 0);
    EXPECT_EQ(r.shading, 0);
    EXPECT_EQ(r.visiblePercent, 0.0);
    EXPECT_EQ(r.meanAbsDelta, 0.0);
}

TEST(ShadingError, RetriangulatedFlatFaceLooksTheSame)
{
    IndexedMesh a, b, c;
    addBox(a, 0, 2, 1, 0.5, Top::DiagonalA);
    addBox(b, 0, 2, 1, 0.5, Top::DiagonalB);
    addBox(c, 0, 2, 1, 0.5, Top::CentreFan);
    for (const IndexedMesh* other : {&b, &c}) {
        const Result r = measure(a, *other);
        EXPECT_GT(r.either, 10000);
        EXPECT_LT(r.visiblePercent, 0.05);
        EXPECT_LT(r.meanAbsDelta, 0.05);
    }
}

TEST(ShadingError, SplitVerticesDoNotChangeTheNormals)
{
    const IndexedMesh m = cylinder(40);
    const Result r = measure(m, unwelded(m));
    EXPECT_EQ(r.visiblePercent, 0.0);
    EXPECT_EQ(r.meanAbsDelta, 0.0);
}

TEST(ShadingError, NormalsAreSmoothAcrossSmallAnglesAndSplitAtCreases)
{
    // Two triangles folded along the edge (0,0,0)-(0,1,0) by `fold` degrees.
    auto normalsOfFold = [](double fold) {
        IndexedMesh m;
        const double a = fold * M_PI / 180;
        addVertex(m, 0, 0, 0);
        addVertex(m, 0, 1, 0);
        addVertex(m, -1, 0, 0);
        addVertex(m, std::cos(a), 0, std::sin(a));
        addTri(m, 0, 1, 2);
        addTri(m, 1, 0, 3);
        return cadlod::shading::cornerNormals(m.ref(), 30.0);
    };
    for (double fold : {20.0, 40.0}) {
        const std::vector<float> n = normalsOfFold(fold);
        ASSERT_EQ(n.size(), 18u);
        // Corner 0 of face 0 and corner 1 of face 1 are both vertex 0.
        const double dot = n[0] * n[12] + n[1] * n[13] + n[2] * n[14];
        if (fold < 30)
            EXPECT_NEAR(dot, 1.0, 1e-6) << "one smooth fan at " << fold << " degrees";
        else
            EXPECT_NEAR(dot, std::cos(fold * M_PI / 180), 1e-6) << "a crease at " << fold << " degrees";
    }
    // A 48-sided cylinder (7.5 degrees between wall faces) shades smooth, a 12-sided one
    // (30 degrees: a crease) faceted; a viewer sees the facets.
    const Result r = measure(cylinder(48), cylinder(12));
    EXPECT_GT(r.shading, r.silhouette);
    EXPECT_GT(r.visiblePercent, 5.0);
}

TEST(ShadingError, MovedVertexIsVisible)
{
    const IndexedMesh m = cylinder(48);
    IndexedMesh moved = m;
    // Vertex 2 + 2*5 is on the bottom rim; push it outwards by 15 % of the radius.
    const std::uint32_t v = 2 + 2 * 5;
    moved.xyz[3 * v] *= 1.15;
    moved.xyz[3 * v + 1] *= 1.15;
    const Result r = measure(m, moved);
    EXPECT_GT(r.visiblePercent, 0.2);
    EXPECT_GT(r.shading, 0);
    EXPECT_GT(r.meanAbsDelta, 0.0);
}

TEST(ShadingError, TiltedFaceIsVisible)
{
    IndexedMesh a, b;
    addBox(a, 0, 1, 1, 1);
    addBox(b, 0, 1, 1, 1);
    b.xyz[3 * 7 + 2] += 0.15;  // one top corner raised: the top face's triangles tilt by ~8°
    const Result r = measure(a, b);
    EXPECT_GT(r.visiblePercent, 2.0);
    EXPECT_GT(r.shading, r.silhouette / 4);
}

TEST(ShadingError, FlippedFaceIsCulledAndCounted)
{
    IndexedMesh a;
    addBox(a, 0, 1, 1, 1);
    IndexedMesh b = a;
    std::swap(b.tri[0], b.tri[1]);  // the first bottom triangle now faces inwards
    const Result r = measure(a, b);
    EXPECT_GT(r.visiblePercent, 0.5);
}

TEST(ShadingError, MissingPartIsASilhouetteMismatch)
{
    IndexedMesh both, one;
    addBox(both, 0, 1, 1, 1);
    addBox(both, 2, 0.5, 0.5, 0.5);
    addBox(one, 0, 1, 1, 1);
    const Result r = measure(both, one);
    EXPECT_GT(r.silhouettePercent, 3.0);
    EXPECT_GE(r.visiblePercent, r.silhouettePercent);
    EXPECT_GT(r.meanAbsDelta, 1.0);
    // Shifted, not missing: the part still shows, only its outline differs.
    IndexedMesh shifted;
    addBox(shifted, 0, 1, 1, 1);
    addBox(shifted, 2.02, 0.5, 0.5, 0.5);
    const Result s = measure(both, shifted);
    EXPECT_GT(s.silhouette, 0);
    EXPECT_LT(s.silhouettePercent, r.silhouettePercent);
}

TEST(ShadingError, SameInputsSameFigures)
{
    const IndexedMesh m = cylinder(64);
    IndexedMesh moved = m;
    for (std::size_t i = 0; i < moved.xyz.size(); i += 7)
        moved.xyz[i] += 0.01 * std::sin(double(i));
    const Result r1 = measure(m, moved);
    const Result r2 = measure(m, moved);
    EXPECT_GT(r1.visiblePercent, 0.0);
    EXPECT_EQ(r1.either, r2.either);
    EXPECT_EQ(r1.silhouette, r2.silhouette);
    EXPECT_EQ(r1.shading, r2.shading);
    EXPECT_EQ(r1.meanAbsDelta, r2.meanAbsDelta);
}

TEST(ShadingError, ResolutionIsAnOption)
{
    const IndexedMesh m = cylinder(32);
    cadlod::shading::Options small;
    small.resolution = 64;
    const Result r = cadlod::shading::Reference(m.ref(), small).compare(m.ref());
    EXPECT_GT(r.either, 0);
    EXPECT_LE(r.either, 12 * 64 * 64);
}

TEST(ShadingError, WritesDifferenceImagesAndReadsPly)
{
    const IndexedMesh m = cylinder(16);
    const std::string dir = ::testing::TempDir();
    cadlod::shading::compare(m.ref(), cylinder(8).ref(), {}, dir + "shading_test_");
    std::ifstream png(dir + "shading_test_view00.png", std::ios::binary);
    char sig[4] = {};
    png.read(sig, 4);
    EXPECT_EQ(std::string(sig + 1, 3), "PNG");
    for (int v = 0; v < 12; ++v) {
        char name[64];
        std::snprintf(name, sizeof name, "shading_test_view%02d.png", v);
        std::remove((dir + name).c_str());
    }

    const std::string ply = dir + "shading_test.ply";
    {
        std::ofstream out(ply);
        out << "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
               "element face 1\nproperty list uchar int vertex_indices\nproperty int part\nend_header\n"
               "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 7\n";
    }
    IndexedMesh read;
    std::string error;
    std::vector<int> parts;
    ASSERT_TRUE(cadlod::shading::readPly(ply, read, error, &parts)) << error;
    EXPECT_EQ(read.xyz.size(), 12u);
    EXPECT_EQ(read.tri, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
    EXPECT_EQ(parts, (std::vector<int>{7, 7}));
    std::remove(ply.c_str());
}
