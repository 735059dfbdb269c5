// The collapse sessions' four-ary heap (collapse_heap.h): the order of pops, building a
// heap from any vector (what vcglib's Init leaves), and dropping stale entries.
#include "test_mesh.h"

#include "simplify/collapse_heap.h"

#include <vcg/complex/algorithms/local_optimization.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

using namespace cadlod;

namespace {

// Ordered like vcglib's HeapElem: the lowest priority is the greatest, the top.
struct Entry {
    float pri;
    bool operator<(const Entry& other) const { return pri > other.pri; }
};

std::vector<float> randomPriorities(int n, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> value(0, n / 3);  // many ties
    std::vector<float> p(std::size_t(n), 0.0f);
    for (float& x : p)
        x = float(value(random));
    return p;
}

std::vector<float> popAll(std::vector<Entry>& h)
{
    std::vector<float> out;
    while (!h.empty())
        out.push_back(heapPop(h).pri);
    return out;
}

class Probe : public vcg::LocalModification<cadlod::test::TestMesh>
{
public:
    Probe(bool upToDate, float priority, int& deleted) : upToDate_(upToDate), priority_(priority), deleted_(deleted) {}
    ~Probe() override { ++deleted_; }
    vcg::ModifierType IsOfType() override { return vcg::TriEdgeCollapseOp; }
    bool IsUpToDate() const override { return upToDate_; }
    bool IsFeasible(vcg::BaseParameterClass*) override { return true; }
    ScalarType ComputePriority(vcg::BaseParameterClass*) override { return priority_; }
    ScalarType Priority() const override { return priority_; }
    void Execute(cadlod::test::TestMesh&, vcg::BaseParameterClass*) override {}
    void UpdateHeap(HeapType&, vcg::BaseParameterClass*) override {}

private:
    bool upToDate_;
    float priority_;
    int& deleted_;
};

}  // namespace

TEST(CollapseHeap, PushedEntriesPopCheapestFirst)
{
    for (int n : {1, 2, 5, 17, 1000}) {
        std::vector<float> p = randomPriorities(n, unsigned(n));
        std::vector<Entry> h;
        for (float x : p)
            heapPush(h, Entry{x});
        std::sort(p.begin(), p.end());
        EXPECT_EQ(popAll(h), p) << n << " entries";
    }
}

TEST(CollapseHeap, AnyVectorMadeAHeapPopsInOrder)
{
    for (int n : {0, 1, 3, 4, 5, 21, 1000}) {
        std::vector<float> p = randomPriorities(n, 7u + unsigned(n));
        std::vector<Entry> h;
        for (float x : p)
            h.push_back(Entry{x});
        std::make_heap(h.begin(), h.end());  // binary, as vcglib leaves it: not yet four-ary
        heapMake(h);
        std::sort(p.begin(), p.end());
        EXPECT_EQ(popAll(h), p) << n << " entries";
    }
}

TEST(CollapseHeap, PushesAndPopsInterleavedKeepTheOrder)
{
    const std::vector<float> p = randomPriorities(2000, 3u);
    std::vector<Entry> h;
    float lastPopped = -1.0f;
    for (std::size_t i = 0; i < p.size(); ++i) {
        // Entries pushed after a pop are never cheaper than it, as in a session (costs grow).
        heapPush(h, Entry{std::max(p[i], lastPopped)});
        if (i % 3 == 2) {
            const float popped = heapPop(h).pri;
            EXPECT_GE(popped, lastPopped);
            lastPopped = popped;
        }
    }
    const std::vector<float> rest = popAll(h);
    EXPECT_TRUE(std::is_sorted(rest.begin(), rest.end()));
    EXPECT_GE(rest.front(), lastPopped);
}

TEST(CollapseHeap, DroppingStaleEntriesDeletesThemAndKeepsTheRestInOrder)
{
    using Heap = vcg::LocalOptimization<cadlod::test::TestMesh>::HeapType;
    using Elem = vcg::LocalOptimization<cadlod::test::TestMesh>::HeapElem;
    int deleted = 0;
    Heap h;
    for (int i = 0; i < 50; ++i)
        heapPush(h, Elem(new Probe(i % 5 != 0, float(50 - i), deleted)));
    heapDropStale(h);
    EXPECT_EQ(deleted, 10);
    ASSERT_EQ(h.size(), 40u);
    float last = 0.0f;
    while (!h.empty()) {
        const Elem e = heapPop(h);
        EXPECT_TRUE(e.locModPtr->IsUpToDate());
        EXPECT_GT(e.pri, last);
        last = e.pri;
        delete e.locModPtr;
    }
    EXPECT_EQ(deleted, 50);
}
