// A large mesh is first collapsed as two halves side by side (core/collapse_halves.h). The
// cut must keep the halves apart (no vertex or face one half's collapses touch is the
// other's), the result must not depend on whether the halves run on two threads or one,
// and it must be a simplification as good as one session over the whole mesh. The tests
// lower SimplifyParams::halvesMinFaces so that meshes of test size are cut.
#include "simplify_test_util.h"

#include "mesh_checks.h"

#include "simplify/collapse_halves.h"
#include "measure/hausdorff.h"
#include "support/run_together.h"

#include <gtest/gtest.h>

#include <array>
#include <set>
#include <vector>

using namespace cadlod;
using namespace cadlod::test;

namespace {

SimplifyParams halvesParams(double reduction)
{
    SimplifyParams p;
    p.reductionPerc = reduction;
    p.halvesMinFaces = 1000;
    return p;
}

void makeAssembly(TestMesh& m, int segments)
{
    CadBuilder b;
    assembly(b, segments);
    b.build(m, true);
}

}  // namespace

TEST(CollapseHalves, TheCutKeepsTheHalvesApart)
{
    TestMesh m;
    makeAssembly(m, 96);
    vcg::tri::UpdateTopology<TestMesh>::VertexFace(m);
    const detail::HalvesCut<TestMesh> cut = detail::cutInHalves(m);
    ASSERT_FALSE(cut.frozen.empty());
    ASSERT_FALSE(cut.writable[0].empty());
    ASSERT_FALSE(cut.writable[1].empty());
    std::vector<int> halfOf(m.vert.size(), -1);
    for (int h = 0; h < 2; ++h)
        for (auto* v : cut.writable[std::size_t(h)]) {
            EXPECT_TRUE(v->IsW());
            halfOf[std::size_t(v - &m.vert[0])] = h;
        }
    for (auto* v : cut.frozen)
        EXPECT_FALSE(v->IsW());
    // No face holds writable vertices of both halves, and no frozen vertex is next to
    // writable vertices of both: what one half's collapses write, the other's never do.
    for (const auto& f : m.face) {
        std::set<int> halves;
        for (int j = 0; j < 3; ++j)
            if (halfOf[std::size_t(f.cV(j) - &m.vert[0])] >= 0)
                halves.insert(halfOf[std::size_t(f.cV(j) - &m.vert[0])]);
        EXPECT_LE(halves.size(), 1u);
    }
    for (auto* v : cut.frozen) {
        std::set<int> halves;
        for (vcg::face::VFIterator<TFace> x(v); !x.End(); ++x)
            for (const TVertex* w : {x.V1(), x.V2()})
                if (halfOf[std::size_t(w - &m.vert[0])] >= 0)
                    halves.insert(halfOf[std::size_t(w - &m.vert[0])]);
        EXPECT_LE(halves.size(), 1u);
    }
    // Both halves have work: neither holds more than two thirds of the faces.
    EXPECT_LT(cut.faces[0], 2 * m.fn / 3);
    EXPECT_LT(cut.faces[1], 2 * m.fn / 3);
    for (auto* v : cut.frozen)
        v->SetW();
}

TEST(CollapseHalves, TwoThreadsGiveTheSameMeshAsOne)
{
    TestMesh sequential, parallel;
    makeAssembly(sequential, 128);
    makeAssembly(parallel, 128);
    const SimplifyStats a = bestOfTrials(sequential, halvesParams(90), nullptr, runInSequence);
    const SimplifyStats b = bestOfTrials(parallel, halvesParams(90), nullptr, runOnTwoThreads);
    ASSERT_TRUE(a.ok && b.ok) << a.message << b.message;
    EXPECT_GT(a.halvesCollapses, a.collapses / 2);  // the halves made most of the collapses
    EXPECT_EQ(a.halvesCollapses, b.halvesCollapses);
    EXPECT_EQ(a.collapses, b.collapses);
    EXPECT_TRUE(snapshot(sequential) == snapshot(parallel));
}

TEST(CollapseHalves, ReachTheTargetWithAConsistentMesh)
{
    TestMesh m, original;
    makeAssembly(m, 128);
    makeAssembly(original, 128);
    const SimplifyStats s = bestOfTrials(m, halvesParams(90), nullptr, runOnTwoThreads);
    ASSERT_TRUE(s.ok) << s.message;
    EXPECT_GT(s.halvesCollapses, 0);
    EXPECT_GT(s.halvesBandVertices, 0);
    EXPECT_NEAR(m.fn, s.targetFaces, 2);
    int faces = 0, vertices = 0;
    for (const auto& f : m.face)
        faces += !f.IsD();
    for (const auto& v : m.vert) {
        vertices += !v.IsD();
        if (!v.IsD()) {
            EXPECT_TRUE(v.IsW());  // the band is writable again
        }
    }
    EXPECT_EQ(faces, m.fn);
    EXPECT_EQ(vertices, m.vn);
    EXPECT_TRUE(vfAdjacencyConsistent(m));
    EXPECT_EQ(nonManifoldEdges(m), nonManifoldEdges(original));
    EXPECT_EQ(foldedFaces(m, original), 0);
}

// The halves make the collapses one session would make within them, in the same order; what
// differs is that the band's wait for the whole-mesh session. The result's distance to the
// input stays that of one session's.
TEST(CollapseHalves, AsAccurateAsOneSession)
{
    for (const double reduction : {50.0, 90.0}) {
        TestMesh halves, whole, original;
        makeAssembly(halves, 128);
        makeAssembly(whole, 128);
        makeAssembly(original, 128);
        SimplifyParams oneSession = halvesParams(reduction);
        oneSession.halvesMinFaces = 0;
        const SimplifyStats a = bestOfTrials(halves, halvesParams(reduction), nullptr, runOnTwoThreads);
        const SimplifyStats b = bestOfTrials(whole, oneSession, nullptr);
        ASSERT_TRUE(a.ok && b.ok);
        EXPECT_GT(a.halvesCollapses, 0);
        EXPECT_EQ(b.halvesCollapses, 0);
        EXPECT_EQ(halves.fn, whole.fn);
        const double dHalves = symmetricHausdorff(original, halves, 100000).maxFraction();
        const double dWhole = symmetricHausdorff(original, whole, 100000).maxFraction();
        EXPECT_LE(dHalves, 1.25 * dWhole) << reduction << " %: halves " << dHalves << ", one session " << dWhole;
    }
}

TEST(CollapseHalves, WithAMaximumErrorOnly)
{
    TestMesh m, original;
    makeShaft(m, 256, 4);
    makeShaft(original, 256, 4);
    SimplifyParams p;
    p.maxError = 1e-3;
    p.halvesMinFaces = 1000;
    const SimplifyStats s = bestOfTrials(m, p, nullptr, runOnTwoThreads);
    ASSERT_TRUE(s.ok) << s.message;
    EXPECT_GT(s.halvesCollapses, 0);
    EXPECT_LT(m.fn, original.fn / 2);
    EXPECT_LE(s.largestError, 1e-3 * s.diagonal);
    EXPECT_TRUE(vfAdjacencyConsistent(m));
}

TEST(CollapseHalves, SmallMeshesAreNotCut)
{
    TestMesh m;
    makeShaft(m, 64);
    SimplifyParams p;
    p.reductionPerc = 90;
    ASSERT_LT(m.fn, p.halvesMinFaces);
    const SimplifyStats s = bestOfTrials(m, p, nullptr, runOnTwoThreads);
    ASSERT_TRUE(s.ok);
    EXPECT_EQ(s.halvesCollapses, 0);
    EXPECT_EQ(s.halvesBandVertices, 0);
}
