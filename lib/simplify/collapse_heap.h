// The collapse sessions' heap: vcglib's LocalOptimization::HeapType (a vector of HeapElem,
// whose operator< puts the cheapest operation on top), kept as a four-ary heap instead of
// std's binary one. A session on a million faces holds millions of entries, and a pop
// walks from the root to a leaf: every level beyond the cache is a memory load. Four
// children side by side (a HeapElem is a pointer and a float) take about one cache line,
// so a four-ary heap has half the levels of a binary one for the same loads per level.
// All pushes and pops of a session go through these functions; vcglib's own
// (Init, ClearHeap) leave a binary heap, which heapMake re-orders.
#pragma once

#include <cstddef>

namespace cadlod {

namespace detail {

inline constexpr std::size_t kHeapArity = 4;

// Moves `e` down from slot i to where no child is above it.
template <class Heap>
void heapSiftDown(Heap& h, std::size_t i, typename Heap::value_type e)
{
    const std::size_t n = h.size();
    for (;;) {
        const std::size_t first = kHeapArity * i + 1;
        if (first >= n)
            break;
        std::size_t top = first;
        const std::size_t end = first + kHeapArity < n ? first + kHeapArity : n;
        for (std::size_t c = first + 1; c < end; ++c)
            if (h[top] < h[c])
                top = c;
        if (!(e < h[top]))
            break;
        h[i] = h[top];
        i = top;
    }
    h[i] = e;
}

}  // namespace detail

template <class Heap>
void heapPush(Heap& h, typename Heap::value_type e)
{
    std::size_t i = h.size();
    h.push_back(e);
    while (i > 0) {
        const std::size_t parent = (i - 1) / detail::kHeapArity;
        if (!(h[parent] < e))
            break;
        h[i] = h[parent];
        i = parent;
    }
    h[i] = e;
}

// Removes the top (h.front()) and returns it.
template <class Heap>
typename Heap::value_type heapPop(Heap& h)
{
    const typename Heap::value_type top = h.front();
    const typename Heap::value_type last = h.back();
    h.pop_back();
    if (!h.empty())
        detail::heapSiftDown(h, 0, last);
    return top;
}

template <class Heap>
void heapMake(Heap& h)
{
    if (h.size() < 2)
        return;
    for (std::size_t i = (h.size() - 2) / detail::kHeapArity + 1; i-- > 0;)
        detail::heapSiftDown(h, i, h[i]);
}

// Deletes the entries whose operation is out of date (a vertex of it changed or went), as
// vcglib's LocalOptimization::ClearHeap does, and orders the rest again.
template <class Heap>
void heapDropStale(Heap& h)
{
    std::size_t kept = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
        if (h[i].locModPtr->IsUpToDate())
            h[kept++] = h[i];
        else
            delete h[i].locModPtr;
    }
    h.resize(kept);
    heapMake(h);
}

// Runs the heap's operations, cheapest first, while it has entries and `goOn()` holds, as
// vcglib's LocalOptimization does: one that is up to date and feasible is executed and
// pushes its neighbours again; `performed` counts those. Stale entries are dropped whenever
// the heap holds more than `maxEntries()`. Returns whether entries are left.
template <class Heap, class MeshType, class Params, class GoOn, class MaxEntries>
bool heapRun(Heap& h, MeshType& m, Params* pp, int& performed, const GoOn& goOn, const MaxEntries& maxEntries)
{
    while (!h.empty() && goOn()) {
        if (h.size() > maxEntries()) {
            heapDropStale(h);
            if (h.empty())
                break;
        }
        const auto top = heapPop(h);
        auto* operation = top.locModPtr;
        if (!h.empty())
            __builtin_prefetch(h.front().locModPtr);  // most likely the next one
        if (operation->IsUpToDate() && operation->IsFeasible(pp)) {
            ++performed;
            operation->Execute(m, pp);
            operation->UpdateHeap(h, pp);
        }
        delete operation;
    }
    return !h.empty();
}

}  // namespace cadlod
