// A large mesh collapsed on two cores.
//
// One collapse session is a sequence: each collapse changes what the collapses beside it
// cost. Two collapses whose neighbourhoods never meet change nothing for each other,
// though. So the mesh is cut in two halves kept apart by a band that neither may change,
// and each half gets a session of its own; the two run at the same time.
//
// The cut: planes across the longest side of the box cut it into slabs, dealt to the two
// halves in turn (slabPlanes). Both ends of every edge between the halves form the band,
// whose vertices are made read-only as vcglib freezes the outside of a selection. A collapse
// reads and writes the faces around its two ends and the vertices of those faces; with the
// band two vertices wide, no face or vertex one half's session touches is the other's
// (tests/simplify: the same tests under ThreadSanitizer). Each half's session is a copy of
// the whole's context (the mesh's quadrics and per-face arrays shared, each half writing
// its own entries) with a heap, counts, clock and heap-entry pool of its own.
//
// The halves are collapsed in rounds, each up to a priority that doubles from round to
// round, so that both spend the same error at a time, as one session over both would: a
// half of flat plates gives more faces than its share, a half of fillets fewer. Within a
// half the collapses come in the order one session gives them. The rounds stop once the
// halves' own faces have lost kHalvesShare of the reduction the face target asks for (the
// band's faces are left to the whole-mesh session), but never more than one session would
// have taken from them had it taken the whole band first. In a round where both halves
// have collapses up to the threshold, each removes at most its share of what is left to
// that point, which binds in the last rounds; the threshold rises only once neither has
// any. A mesh whose band holds so many of its faces that the halves could not make half
// the removal is not cut. With only a maximum error, each half runs until no collapse
// within the error is left in it.
//
// Then the band is writable again, and the session over the whole mesh goes on from there
// (collapseToTarget, every edge back in its heap): it does the band's collapses, the rest of
// the removal, and what reaches beyond a half, which the halves leave out: removing small
// components whole, cutting tunnels, relaxing the shape guards.
//
// How the mesh is cut depends on the mesh alone, and a half's session on that half alone,
// so the result is the same whether the halves run on two threads or one after the other.
// Meshes below SimplifyParams::halvesMinFaces are not cut.
#pragma once

#include "simplify/cad_edge_collapse.h"
#include "simplify/collapse_heap.h"
#include "measure/hausdorff.h"  // liveVertexBox
#include "support/run_together.h"
#include "simplify/simplify_params.h"

#include <vcg/complex/algorithms/local_optimization.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace cadlod {

// The share of the face target's removal the halves make before the whole-mesh session.
inline constexpr double kHalvesShare = 0.9;

namespace detail {

// A mesh cut in two: the writable vertices of each half, and the band's vertices that were
// writable and are frozen while the halves run.
template <class MeshType>
struct HalvesCut {
    using VertexType = typename MeshType::VertexType;
    std::array<std::vector<VertexType*>, 2> writable;
    std::array<int, 2> faces{0, 0};
    std::vector<VertexType*> frozen;
    int bandFaces = 0;  // faces with two or more vertices in the band: no half's collapse deletes them
};

// The mesh is cut across the box's longest side into kHalvesSlabs slabs, dealt to the two
// halves in turn: each half gets parts of the mesh from along its whole length, so the two
// have about the same work at every cost (one slab each could give one half the fine end of
// a part and the other its plain one, and the cheap collapses of the first would wait for
// nothing while the second ran alone).
inline constexpr int kHalvesSlabs = 4;

// The planes between the slabs: near each of the face-centroid quantiles 1/4, 2/4 and 3/4
// (within 5 points), the one that the edges crossing it add up to the least length at. Every
// edge that crosses a plane goes into the band with both its ends, and freezes every face
// around them: a plane across a cylinder's long strips would freeze the whole cylinder, one
// across a chamfer two narrow rings.
struct SlabPlanes {
    int axis = 0;
    std::vector<double> at;  // ascending
    // 0 or 1: the half of a point at `coordinate` along the axis (on a plane: the slab above)
    int halfOf(double coordinate) const
    {
        return int(std::upper_bound(at.begin(), at.end(), coordinate) - at.begin()) % 2;
    }
};

template <class MeshType>
SlabPlanes slabPlanes(const MeshType& m)
{
    SlabPlanes planes;
    planes.axis = liveVertexBox(m).MaxDim();
    const int axis = planes.axis;
    std::vector<double> along;
    along.reserve(std::size_t(m.fn));
    for (const auto& f : m.face)
        if (!f.IsD())
            along.push_back((double(f.cP(0)[axis]) + f.cP(1)[axis] + f.cP(2)[axis]) / 3.0);
    if (along.empty())
        return planes;
    std::sort(along.begin(), along.end());
    // Candidate planes at every percentile, and the length of the edges each one cuts (an
    // edge [lo, hi] is cut by the planes lo < c <= hi), summed from differences.
    constexpr int kPercentiles = 101;
    std::vector<double> candidate(kPercentiles);
    for (int i = 0; i < kPercentiles; ++i)
        candidate[std::size_t(i)] = along[std::size_t(i * (along.size() - 1) / (kPercentiles - 1))];
    std::vector<double> crossing(kPercentiles + 1, 0.0);
    for (const auto& f : m.face) {
        if (f.IsD())
            continue;
        for (int j = 0; j < 3; ++j) {
            const auto& a = f.cP(j);
            const auto& b = f.cP((j + 1) % 3);
            const double lo = std::min(a[axis], b[axis]), hi = std::max(a[axis], b[axis]);
            const auto first = std::upper_bound(candidate.begin(), candidate.end(), lo) - candidate.begin();
            const auto last = std::upper_bound(candidate.begin(), candidate.end(), hi) - candidate.begin();
            const double length = vcg::Distance(a, b);
            crossing[std::size_t(first)] += length;
            crossing[std::size_t(last)] -= length;
        }
    }
    for (int i = 1; i < kPercentiles; ++i)
        crossing[std::size_t(i)] += crossing[std::size_t(i - 1)];
    for (int k = 1; k < kHalvesSlabs; ++k) {
        const int middle = k * (kPercentiles - 1) / kHalvesSlabs;
        int best = middle;  // the quantile itself wins ties, then the percentile nearest it
        for (int d = 1; d <= 5; ++d)
            for (const int i : {middle - d, middle + d})
                if (crossing[std::size_t(i)] < crossing[std::size_t(best)])
                    best = i;
        if (planes.at.empty() || candidate[std::size_t(best)] > planes.at.back())
            planes.at.push_back(candidate[std::size_t(best)]);
    }
    return planes;
}

// Cuts `m` in halves and freezes the band between them (see the file's comment): a vertex
// belongs to the half of its slab; the band is both ends of every edge between the halves,
// so a frozen vertex of one half is never next to a writable one of the other.
template <class MeshType>
HalvesCut<MeshType> cutInHalves(MeshType& m)
{
    const SlabPlanes planes = slabPlanes(m);
    auto index = [&](const typename MeshType::VertexType* v) { return std::size_t(v - &m.vert[0]); };
    auto halfOf = [&](const typename MeshType::VertexType* v) { return planes.halfOf(v->cP()[planes.axis]); };
    std::vector<bool> inBand(m.vert.size(), false);
    std::vector<bool> used(m.vert.size(), false);
    for (const auto& f : m.face) {
        if (f.IsD())
            continue;
        for (int j = 0; j < 3; ++j) {
            used[index(f.cV(j))] = true;
            if (halfOf(f.cV(j)) != halfOf(f.cV((j + 1) % 3)))
                inBand[index(f.cV(j))] = inBand[index(f.cV((j + 1) % 3))] = true;
        }
    }
    HalvesCut<MeshType> cut;
    for (const auto& f : m.face) {
        if (f.IsD())
            continue;
        const int banded = int(inBand[index(f.cV(0))]) + int(inBand[index(f.cV(1))]) + int(inBand[index(f.cV(2))]);
        cut.bandFaces += banded >= 2;
        if (halfOf(f.cV(0)) == halfOf(f.cV(1)) && halfOf(f.cV(1)) == halfOf(f.cV(2)))
            ++cut.faces[std::size_t(halfOf(f.cV(0)))];
    }
    for (std::size_t i = 0; i < m.vert.size(); ++i) {
        auto& v = m.vert[i];
        if (v.IsD() || !used[i])
            continue;
        if (inBand[i]) {
            if (v.IsW()) {
                v.ClearW();
                cut.frozen.push_back(&v);
            }
        } else if (v.IsRW()) {
            cut.writable[std::size_t(halfOf(&v))].push_back(&v);
        }
    }
    return cut;
}

// One half's collapse session.
template <class MeshType>
struct HalfSession {
    using Collapse = CadEdgeCollapse<MeshType>;
    explicit HalfSession(const CollapseContext<MeshType>& whole) : ctx(whole)
    {
        ctx.stats = &stats;
        ctx.heap = &heap;
        ctx.faceCounter = &liveFaces;
        ctx.vertexCounter = &deletedVertices;
        ctx.largestError = 0.0;
        ctx.largestFeatureBreak = 0.0;
        ctx.facingGaveWay = false;
        ctx.spareVertices.clear();  // no tunnel cuts: they add faces
        ctx.spareFaces.clear();
        // Nor the input's points of an LOD chain's level (far_field.h): both halves would
        // move them in one table. The halves are held to the quadric error alone, and the
        // whole session deals the points again after them (CollapseBuckets::collapse).
        if (ctx.farField && !ctx.farField->started())
            ctx.farField = nullptr;
    }
    HalfSession(const HalfSession&) = delete;
    HalfSession& operator=(const HalfSession&) = delete;
    ~HalfSession()
    {
        EntryPool::Use use(pool);
        for (auto& e : heap)
            delete e.locModPtr;
    }

    void fill(const std::vector<typename MeshType::VertexType*>& writable)
    {
        EntryPool::Use use(pool);
        for (auto* v : writable)
            Collapse::appendEdgesOf(v, heap, &ctx);
        heapMake(heap);
    }

    float lowest() const { return heap.empty() ? std::numeric_limits<float>::max() : heap.front().pri; }
    bool hasUpTo(float threshold) const { return !heap.empty() && heap.front().pri <= threshold; }

    // Collapses until the heap's first entry costs more than `threshold`, or `cap` faces
    // are gone in this round.
    void run(MeshType& m, float threshold, int cap)
    {
        EntryPool::Use use(pool);
        const int stopAt = liveFaces - cap;
        heapRun(
            heap, m, &ctx, stats.collapses,
            [&] { return liveFaces > stopAt && heap.front().pri <= threshold; },
            [&] { return std::size_t(Collapse::HeapSimplexRatio(nullptr) * std::max(liveFaces, 1)); });
    }

    CollapseContext<MeshType> ctx;
    SimplifyStats stats;
    typename vcg::LocalOptimization<MeshType>::HeapType heap;
    EntryPool pool;
    int liveFaces = 0;
    int deletedVertices = 0;  // counted down from 0
};

}  // namespace detail

// The first phase of a simplification of `m` (prepared: prepareCollapse), side by side on
// its two halves; collapseToTarget goes on from where it leaves `m`. Nothing is done when
// the mesh has fewer than params.halvesMinFaces faces (0: never).
template <class MeshType>
void collapseHalvesFirst(MeshType& m, CollapseContext<MeshType>& whole, SimplifyStats& stats,
                         const RunTogether& together, vcg::CallBackPos* progress)
{
    const int minFaces = whole.params.halvesMinFaces;
    if (minFaces <= 0 || m.fn < minFaces || whole.params.selectedOnly)
        return;
    const int facesBefore = m.fn;
    const int target = stats.targetFaces;
    detail::HalvesCut<MeshType> cut = detail::cutInHalves(m);
    // The halves' own faces lose kHalvesShare of the reduction the target asks for, the
    // band's are left to the whole-mesh session; but never more than one session would take
    // from the halves if it took the whole band first. Where the band is too large a share of
    // the mesh for that to be most of the work, the mesh is not worth cutting.
    const int removal = target > 0 ? facesBefore - target : 0;
    const int halvesRemoval =
        std::min(int(kHalvesShare * (facesBefore - cut.bandFaces) * removal / facesBefore), removal - cut.bandFaces);
    if (target > 0 && halvesRemoval < removal / 2) {
        for (auto* v : cut.frozen)
            v->SetW();
        return;
    }
    const int goal = facesBefore - halvesRemoval;

    std::array<std::unique_ptr<detail::HalfSession<MeshType>>, 2> halves;
    for (std::size_t h = 0; h < 2; ++h) {
        halves[h] = std::make_unique<detail::HalfSession<MeshType>>(whole);
        halves[h]->liveFaces = cut.faces[h];
    }
    together([&] { halves[0]->fill(cut.writable[0]); }, [&] { halves[1]->fill(cut.writable[1]); });

    auto live = [&] { return m.fn - (cut.faces[0] - halves[0]->liveFaces) - (cut.faces[1] - halves[1]->liveFaces); };
    float threshold = 0.0f;
    for (;;) {
        const int faces = live();
        if (target > 0 && faces <= goal)
            break;
        std::array<bool, 2> below;  // the half has collapses up to the threshold left
        for (std::size_t h = 0; h < 2; ++h)
            below[h] = halves[h]->hasUpTo(threshold);
        if (!below[0] && !below[1]) {
            const float lowest = std::min(halves[0]->lowest(), halves[1]->lowest());
            if (!(lowest < std::numeric_limits<float>::max()))
                break;  // nothing left but refused or locked edges
            threshold = target > 0 ? 2.0f * std::max(threshold, lowest) : std::numeric_limits<float>::max();
            for (std::size_t h = 0; h < 2; ++h)
                below[h] = halves[h]->hasUpTo(threshold);
        }
        // What is left to the goal, shared by the halves' faces when both have collapses up
        // to the threshold, all of it for one when the other has none.
        std::array<int, 2> cap{0, 0};
        for (std::size_t h = 0; h < 2; ++h)
            cap[h] = target == 0     ? std::numeric_limits<int>::max()
                     : !below[h]     ? 0
                     : !below[1 - h] ? faces - goal
                                     : int(std::ceil(double(faces - goal) * halves[h]->liveFaces / std::max(faces, 1)));
        together([&] { halves[0]->run(m, threshold, cap[0]); }, [&] { halves[1]->run(m, threshold, cap[1]); });
        if (progress && target > 0)
            progress(std::clamp(100 * (facesBefore - live()) / std::max(1, facesBefore - target), 0, 99),
                     "CAD edge collapse (two halves side by side)");
    }

    const int faces = live();
    for (auto* v : cut.frozen)
        v->SetW();
    for (const auto& h : halves) {
        m.vn += h->deletedVertices;
        stats.halvesCollapses += h->stats.collapses;
        for (int SimplifyStats::*count : kSessionCounts)
            stats.*count += h->stats.*count;
        whole.mark = std::max(whole.mark, h->ctx.mark);
        whole.largestError = std::max(whole.largestError, h->ctx.largestError);
        whole.largestFeatureBreak = std::max(whole.largestFeatureBreak, h->ctx.largestFeatureBreak);
    }
    m.fn = faces;
    stats.halvesBandVertices = int(cut.frozen.size());
}

}  // namespace cadlod
