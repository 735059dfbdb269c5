// Property test: random meshes (fixed seeds) of random triangles over a small vertex set,
// so they are full of non-manifold edges, duplicates, slivers and flipped faces. After
// simplification the mesh must stay valid and the target be met or a message say why.
#include "mesh_validity.h"
#include "simplify_test_util.h"

#include <gtest/gtest.h>

#include <random>

using namespace cadlod;
using namespace cadlod::test;

namespace {

void randomMesh(TestMesh& m, std::mt19937& rng, int vertices, int faces)
{
    std::uniform_real_distribution<float> coord(-1.0f, 1.0f);
    std::uniform_int_distribution<int> pick(0, vertices - 1);
    auto v = vcg::tri::Allocator<TestMesh>::AddVertices(m, size_t(vertices));
    for (int i = 0; i < vertices; ++i) m.vert[size_t(i)].P() = vcg::Point3f(coord(rng), coord(rng), coord(rng));
    (void)v;
    for (int i = 0; i < faces; ++i) {
        int a = pick(rng), b = pick(rng), c = pick(rng);
        vcg::tri::Allocator<TestMesh>::AddFace(m, &m.vert[size_t(a)], &m.vert[size_t(b)], &m.vert[size_t(c)]);
    }
    vcg::tri::UpdateBounding<TestMesh>::Box(m);
}

// A grid surface with random heights: manifold, so collapses really happen.
void randomTerrain(TestMesh& m, std::mt19937& rng, int n)
{
    std::uniform_real_distribution<float> height(0.0f, 0.3f);
    vcg::tri::Allocator<TestMesh>::AddVertices(m, size_t((n + 1) * (n + 1)));
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) m.vert[size_t(j * (n + 1) + i)].P() = vcg::Point3f(float(i), float(j), height(rng));
    auto at = [&](int i, int j) { return &m.vert[size_t(j * (n + 1) + i)]; };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            vcg::tri::Allocator<TestMesh>::AddFace(m, at(i, j), at(i + 1, j), at(i + 1, j + 1));
            vcg::tri::Allocator<TestMesh>::AddFace(m, at(i, j), at(i + 1, j + 1), at(i, j + 1));
        }
    vcg::tri::UpdateBounding<TestMesh>::Box(m);
}

void checkOutcome(const TestMesh& m, const SimplifyStats& s, int target)
{
    ASSERT_TRUE(s.ok) << s.message;
    expectValidMesh(m);
    EXPECT_EQ(s.facesAfter, m.fn);
    if (m.fn > target) {
        EXPECT_FALSE(s.message.empty()) << m.fn << " faces for a target of " << target;
    }
}

}  // namespace

TEST(RandomMeshes, TriangleSoupsOverFewVerticesStayValid)
{
    for (unsigned seed = 1; seed <= 40; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937 rng(seed);
        TestMesh m;
        const int vertices = 8 + int(seed % 7) * 10, faces = 20 + int(seed * 37 % 300);
        randomMesh(m, rng, vertices, faces);
        const int target = faces / int(2 + seed % 5);
        const SimplifyStats s = bestOfTrials(m, targetParams(std::max(target, 1)));
        checkOutcome(m, s, std::max(target, 1));
    }
}

TEST(RandomMeshes, RandomTerrainsMeetTheTargetOrSayWhy)
{
    for (unsigned seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE("seed " + std::to_string(seed));
        std::mt19937 rng(seed);
        TestMesh m;
        randomTerrain(m, rng, 10 + int(seed));
        const int target = m.fn / int(2 + seed % 6);
        const SimplifyStats s = bestOfTrials(m, targetParams(target));
        checkOutcome(m, s, target);
        EXPECT_LT(m.fn, s.facesBefore);
    }
}
