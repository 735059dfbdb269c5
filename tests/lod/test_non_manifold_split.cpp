// Cutting a mesh apart along its non-manifold edges (core/non_manifold_split.h): each such
// edge keeps the two faces that continue each other, the others get vertices of their own.
#include "cad_meshes.h"
#include "test_mesh.h"

#include "simplify/non_manifold_split.h"

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <utility>
#include <vector>

using namespace cadlod;
using namespace cadlod::test;

namespace {

using EdgeKey = std::pair<const void*, const void*>;

// Edge k of `f` (from corner k to the next), by its vertices' addresses, lower first.
EdgeKey edgeKey(const TestMesh::FaceType& f, int k)
{
    const void* a = f.cV(k);
    const void* b = f.cV((k + 1) % 3);
    return a < b ? EdgeKey{a, b} : EdgeKey{b, a};
}

// How many faces hold each edge of `m`.
std::map<EdgeKey, int> facesPerEdge(const TestMesh& m)
{
    std::map<EdgeKey, int> count;
    for (const auto& f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k)
                ++count[edgeKey(f, k)];
    return count;
}

int edgesWith(const TestMesh& m, int faces)
{
    int n = 0;
    for (const auto& [edge, count] : facesPerEdge(m))
        n += count == faces;
    return n;
}

// The corners' points of every face, in order.
std::vector<std::array<double, 9>> cornerPoints(const TestMesh& m)
{
    std::vector<std::array<double, 9>> points;
    for (const auto& f : m.face)
        if (!f.IsD())
            points.push_back({f.cP(0)[0], f.cP(0)[1], f.cP(0)[2], f.cP(1)[0], f.cP(1)[1], f.cP(1)[2], f.cP(2)[0],
                              f.cP(2)[1], f.cP(2)[2]});
    return points;
}

bool shareAVertex(const TestMesh::FaceType& f, const TestMesh::FaceType& g)
{
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (f.cV(i) == g.cV(j))
                return true;
    return false;
}

CadBuilder tubeWithFinBuilder(int segments)
{
    CadBuilder b;
    tubeWithFin(b, segments);
    return b;
}

}  // namespace

// Three pages on one spine: the two that lie flat on either side of it (running the spine in
// opposite directions, normals agreeing) stay one sheet; the page standing up gets its own
// copies of both spine vertices.
TEST(NonManifoldSplit, ABookOfThreePagesKeepsTheFlatSheetAndCutsOffTheThird)
{
    CadBuilder b;
    const int a = b.addPoint(0, 0, 0), e = b.addPoint(1, 0, 0);
    const int up = b.addPoint(0.5, 0, 1), left = b.addPoint(0.5, 1, 0), right = b.addPoint(0.5, -1, 0);
    b.addTriangle(a, e, up);     // standing up, normal -y
    b.addTriangle(a, e, left);   // flat, normal +z
    b.addTriangle(e, a, right);  // flat, normal +z, the spine the other way
    TestMesh m;
    b.build(m);
    const auto before = cornerPoints(m);
    ASSERT_EQ(edgesWith(m, 3), 1);

    const NonManifoldSplit split = splitNonManifoldEdges(m);

    EXPECT_EQ(split.edges, 1);
    EXPECT_EQ(split.edgesLeft, 0);
    EXPECT_EQ(split.vertexCopies, 2);
    EXPECT_EQ(m.vn, 7);
    EXPECT_EQ(cornerPoints(m), before);  // nothing moved, no face changed its corners' order
    EXPECT_EQ(edgesWith(m, 3), 0);
    EXPECT_TRUE(shareAVertex(m.face[1], m.face[2]));
    EXPECT_FALSE(shareAVertex(m.face[0], m.face[1]));
    EXPECT_FALSE(shareAVertex(m.face[0], m.face[2]));
}

TEST(NonManifoldSplit, AManifoldMeshIsLeftAsItIs)
{
    CadBuilder b;
    RevolveSpec spec;
    spec.segments = 32;
    revolve(b, shaftProfile(), spec);
    TestMesh m;
    b.build(m);
    const int vertices = m.vn;
    const auto before = cornerPoints(m);

    const NonManifoldSplit split = splitNonManifoldEdges(m);

    EXPECT_EQ(split.edges, 0);
    EXPECT_EQ(split.vertexCopies, 0);
    EXPECT_EQ(m.vn, vertices);
    EXPECT_EQ(cornerPoints(m), before);
}

// The tube goes on under the fin: it stays closed, and the fin's inner rim becomes a
// boundary with vertices of its own.
TEST(NonManifoldSplit, AFinWeldedAroundATubeComesOffAndTheTubeStaysClosed)
{
    const int n = 48;
    TestMesh m;
    tubeWithFinBuilder(n).build(m, true);
    const int vertices = m.vn;
    ASSERT_EQ(edgesWith(m, 3), n);

    const NonManifoldSplit split = splitNonManifoldEdges(m);

    EXPECT_EQ(split.edges, n);
    EXPECT_EQ(split.edgesLeft, 0);
    EXPECT_EQ(split.vertexCopies, n);
    EXPECT_EQ(m.vn, vertices + n);
    EXPECT_EQ(edgesWith(m, 3), 0);
    EXPECT_EQ(edgesWith(m, 1), 2 * n);  // the fin's two rims; the tube has none
    auto part = facePartHandle(m);
    const auto count = facesPerEdge(m);
    for (const auto& f : m.face)
        for (int k = 0; k < 3; ++k)
            if (count.at(edgeKey(f, k)) == 1)
                EXPECT_EQ(part[f], 1) << "a boundary edge of the tube";
}
