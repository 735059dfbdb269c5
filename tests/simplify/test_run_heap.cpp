// The collapse sessions' heap loop (simplify.h's detail::runHeap). Once the heap outgrows
// the mesh, vcglib's DoOptimization drops the stale entries and then pops without looking:
// a far-field session whose entries were all stale popped from the empty heap (the KUKA
// robot's chain). The loop must end there, and still run what is left after the dropping.
#include "test_mesh.h"

#include "simplify/simplify_impl.h"

#include <gtest/gtest.h>

using namespace cadlod;
using cadlod::test::TestMesh;
using cadlod::test::addFaces;

namespace {

// An operation that only says whether it is up to date and counts its runs.
class Probe : public vcg::LocalModification<TestMesh>
{
public:
    Probe(bool upToDate, double priority, int& runs) : upToDate_(upToDate), priority_(priority), runs_(runs) {}
    vcg::ModifierType IsOfType() override { return vcg::TriEdgeCollapseOp; }
    bool IsUpToDate() const override { return upToDate_; }
    bool IsFeasible(vcg::BaseParameterClass*) override { return true; }
    ScalarType ComputePriority(vcg::BaseParameterClass*) override { return ScalarType(priority_); }
    ScalarType Priority() const override { return ScalarType(priority_); }
    void Execute(TestMesh&, vcg::BaseParameterClass*) override { ++runs_; }
    void UpdateHeap(HeapType&, vcg::BaseParameterClass*) override {}

private:
    bool upToDate_;
    double priority_;
    int& runs_;
};

// A mesh of two faces, and a session whose goal (no faces) the probes never reach: the
// heap alone decides when it ends. It drops stale entries above 1 entry per face.
struct Session {
    TestMesh m;
    vcg::BaseParameterClass params;
    vcg::LocalOptimization<TestMesh> run{m, &params};
    int runs = 0;

    Session()
    {
        addFaces(m, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
        run.HeapSimplexRatio = 1;
        run.SetTargetSimplices(0);
    }
    void add(bool upToDate, double priority)
    {
        heapPush(run.h, vcg::LocalOptimization<TestMesh>::HeapElem(new Probe(upToDate, priority, runs)));
    }
    // Ten times as many entries as faces, none up to date.
    void addStale()
    {
        for (int i = 0; i < 10; ++i)
            add(false, i);
    }
};

}  // namespace

TEST(RunHeap, AHeapOfStaleEntriesEndsTheSessionCleanly)
{
    Session s;
    s.addStale();
    EXPECT_FALSE(detail::runHeap(s.run));
    EXPECT_TRUE(s.run.h.empty());
    EXPECT_EQ(s.runs, 0);
    EXPECT_EQ(s.run.nPerformedOps, 0);
}

TEST(RunHeap, WhatTheDroppingLeavesStillRuns)
{
    Session s;
    s.addStale();
    s.add(true, 5.5);
    EXPECT_FALSE(detail::runHeap(s.run));
    EXPECT_TRUE(s.run.h.empty());
    EXPECT_EQ(s.runs, 1);
    EXPECT_EQ(s.run.nPerformedOps, 1);
}

TEST(RunHeap, StaleEntriesBelowTheLimitArePoppedAndSkipped)
{
    Session s;
    s.add(false, 1);
    s.add(true, 2);  // two entries for two faces: no dropping
    EXPECT_FALSE(detail::runHeap(s.run));
    EXPECT_EQ(s.runs, 1);
}
