// The simplifier's heap is lazy: an edge enters it with a bound computed from the quadrics
// alone and is evaluated in full when it reaches the top. That is only the same order as
// eager evaluation if the bound never exceeds the full priority, for every edge, on the
// input and on a partly simplified mesh (moved vertices, merged quadrics and features).
#include "simplify_test_util.h"

#include "simplify/simplify_impl.h"

#include <gtest/gtest.h>

#include <limits>
#include <set>
#include <utility>

using namespace cadlod;
using namespace cadlod::test;

namespace {

struct BoundCheck {
    int edges = 0;
    int feasible = 0;     // full evaluation found an acceptable placement
    int loose = 0;        // bound strictly below the full priority
    int violations = 0;   // bound above it
};

BoundCheck checkEveryEdge(TestMesh& m, const SimplifyParams& params)
{
    using Collapse = CadEdgeCollapse<TestMesh>;
    BoundCheck check;
    SimplifyStats stats;
    CollapseContext<TestMesh> ctx;
    if (!prepareCollapse(m, params, ctx, stats)) {
        releaseCollapse(m, ctx);
        return check;
    }
    std::set<std::pair<TVertex*, TVertex*>> seen;
    for (TFace& f : m.face) {
        if (f.IsD())
            continue;
        for (int j = 0; j < 3; ++j) {
            TVertex* a = f.V(j);
            TVertex* b = f.V((j + 1) % 3);
            if (!seen.insert({std::min(a, b), std::max(a, b)}).second)
                continue;
            Collapse collapse(vcg::tri::BasicVertexPair<TVertex>(a, b), 0, &ctx);
            const float bound = collapse.Priority();
            const float full = collapse.ComputePriority(&ctx);
            ++check.edges;
            check.feasible += full < std::numeric_limits<float>::max();
            check.loose += bound < full;
            if (bound > full) {
                ++check.violations;
                ADD_FAILURE() << "edge " << vcg::tri::Index(m, a) << "-" << vcg::tri::Index(m, b) << ": bound "
                              << bound << " > priority " << full;
            }
        }
    }
    releaseCollapse(m, ctx);
    return check;
}

void expectBoundHolds(TestMesh& m)
{
    const BoundCheck c = checkEveryEdge(m, SimplifyParams{});
    EXPECT_GT(c.edges, 1000);
    EXPECT_GT(c.feasible, c.edges / 10);  // real placements were compared, not only refusals
    EXPECT_GT(c.loose, 0);                // and the bound is a bound, not the priority itself
    EXPECT_EQ(c.violations, 0);
}

}  // namespace

TEST(LazyPriority, BoundHoldsOnInputShaft)
{
    TestMesh m;
    makeShaft(m, 200, 3);
    expectBoundHolds(m);
}

TEST(LazyPriority, BoundHoldsOnPartlySimplifiedShaft)
{
    TestMesh m;
    makeShaft(m, 300, 2);
    const SimplifyStats s = bestOfTrials(m, targetParams(m.fn / 3));
    ASSERT_TRUE(s.ok) << s.message;
    expectBoundHolds(m);
}

TEST(LazyPriority, BoundHoldsOnPartlySimplifiedAssembly)
{
    TestMesh m;
    CadBuilder b;
    assembly(b, 256);
    b.build(m, true);
    const SimplifyStats s = bestOfTrials(m, targetParams(m.fn / 2));
    ASSERT_TRUE(s.ok) << s.message;
    expectBoundHolds(m);
}
