// Independent pieces of a model, simplified side by side (the parts of an assembly
// simplify in parallel). A collapse never crosses from one connected component
// to another, and under an error bound a component's collapses depend on that component
// alone, so the model is dealt into a few buckets of whole components, each simplified by
// a collapse session of its own; with a RunTogether that runs tasks at once, the buckets
// run on all cores.
//
// What would differ from one session over the whole model is kept the same: every session
// prices with the model's diagonal; components that touch (a vertex of one where a vertex
// of another stands) go into one bucket, because removing either alone opens a hole; the
// model's largest component stays the only one never removed whole. How the components
// are dealt depends on the model alone, never on the number of threads, so neither does
// the result.
#pragma once

#include "simplify/component_removal.h"
#include "lod/copy_with_parts.h"
#include "simplify/rest_of_model.h"
#include "support/run_together.h"
#include "simplify/simplify_impl.h"

#include <vcg/complex/append.h>

#include <algorithm>
#include <deque>
#include <functional>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

namespace cadlod {

// At most this many buckets: enough to keep a few cores busy when the components differ
// in size, few enough that each session has work worth a task.
inline constexpr std::size_t kMaxCollapseBuckets = 8;

template <class MeshType>
class CollapseBuckets
{
public:
    // `newMesh` returns an empty mesh with what cadlod::simplify needs (VF adjacency, marks)
    // and the optional components of `model`; the buckets live in them.
    explicit CollapseBuckets(const std::function<MeshType&()>& newMesh) : newMesh_(newMesh) {}
    CollapseBuckets(const CollapseBuckets&) = delete;
    CollapseBuckets& operator=(const CollapseBuckets&) = delete;
    ~CollapseBuckets() { release(); }

    // Deals the faces of `model` into buckets and prepares a session on each (side by
    // side, through `together`). `model` is left with its selection cleared. False (with
    // `error`) if the model has no extent.
    bool prepare(MeshType& model, const SimplifyParams& params, std::string& error,
                 const RunTogether& together = runInSequence)
    {
        const double diagonal = detail::finiteFaceDiagonal(model);
        if (!(diagonal > 0)) {
            error = "the mesh has no extent (all vertices coincide or are not finite)";
            return false;
        }
        vcg::tri::UpdateTopology<MeshType>::VertexFace(model);
        const std::vector<Component<MeshType>> components = connectedComponents(model);
        const std::vector<std::vector<std::size_t>> dealt = deal(model, components);
        // The largest component comes last; its bucket must keep it.
        const std::size_t largestFace =
            components.empty() ? 0 : std::size_t(components.back().faces.front() - &model.face[0]);
        // The gap a removal leaves is measured against the whole model, whose other pieces
        // a bucket does not hold (rest_of_model.h).
        wholeModel_.reset();
        if (components.size() >= 2)
            wholeModel_ = std::make_shared<ComponentSurfaces>(model, components);
        const std::shared_ptr<const ComponentSurfaces> wholeModel = wholeModel_;
        for (const std::vector<std::size_t>& faces : dealt) {
            Bucket& b = buckets_.emplace_back(newMesh_());
            copyFaces(model, faces, b.mesh);
            b.ctx.mayRemoveLargestComponent = !std::binary_search(faces.begin(), faces.end(), largestFace);
            b.ctx.modelComponents = wholeModel;
            if (wholeModel)
                for (std::size_t f : faces)  // the bucket's faces are the model's, in order
                    b.ctx.modelComponentOf.push_back(wholeModel->componentOfFace(f));
        }
        forEachBucket(0, buckets_.size(), together,
                      [&](Bucket& b) { b.ready = prepareCollapse(b.mesh, params, b.ctx, b.stats, diagonal); });
        return true;
    }

    // Every bucket collapsed until its collapses would exceed `maxErrorAbs`, or in the far
    // field (params.farFieldWithinBound) open more than `maxDistance`; before it too once
    // holdToDistanceBeforeFarField was called. A large bucket's halves (collapse_halves.h)
    // are held to `halvesMaxErrorAbs` (negative: maxErrorAbs) alone.
    void collapse(double maxErrorAbs, double maxDistance, const RunTogether& together, double halvesMaxErrorAbs = -1)
    {
        for (Bucket& b : buckets_) {
            b.ctx.maxErrorAbs = maxErrorAbs;
            b.ctx.maxDistance = maxDistance;
            b.stats.targetFaces = 0;
            b.stats.errorBound = maxErrorAbs;
        }
        // A bucket of a few hundred thousand faces starts as two halves side by side
        // (collapse_halves.h): a one-part model's first level is most of a chain's work.
        forEachBucket(0, buckets_.size(), together, [&](Bucket& b) {
            if (!b.ready)
                return;
            const int before = b.stats.halvesCollapses;
            b.ctx.maxErrorAbs = halvesMaxErrorAbs >= 0 ? halvesMaxErrorAbs : maxErrorAbs;
            collapseHalvesFirst(b.mesh, b.ctx, b.stats, together, nullptr);
            b.ctx.maxErrorAbs = maxErrorAbs;
            // The points go to the faces after the halves, which leave them where they were.
            const bool halvesRan = b.stats.halvesCollapses > before;
            if (holdBeforeFarField_ && b.ctx.farField && !b.ctx.farField->started() && b.mesh.fn > 0 &&
                (halvesRan || !b.ctx.farField->dealt()))
                b.ctx.farField->deal(b.mesh);
            if (halvesRan)
                b.stats.relaxed.push_back(std::to_string(b.stats.halvesCollapses - before) +
                                          " collapses made on two halves side by side first (a band of " +
                                          std::to_string(b.stats.halvesBandVertices) + " vertices between them)");
            collapseToTarget(b.mesh, b.ctx, b.stats, nullptr);
        });
        // What one piece removed is gone for every piece's removals from the next level on.
        for (Bucket& b : buckets_) {
            if (wholeModel_)
                for (const std::int32_t c : b.ctx.modelComponentsRemoved)
                    wholeModel_->markGone(c);
            b.ctx.modelComponentsRemoved.clear();
        }
    }

    int faces() const
    {
        int n = 0;
        for (const Bucket& b : buckets_)
            n += b.mesh.fn;
        return n;
    }

    double largestError() const { return largestOver(&CollapseContext<MeshType>::largestError); }
    double largestDistance() const { return largestOver(&CollapseContext<MeshType>::largestDistance); }

    // Takes every bucket into the far field (params.farFieldWithinBound), logged in its
    // statistics.
    void startFarField()
    {
        for (Bucket& b : buckets_)
            if (b.ready && b.ctx.farField && !b.ctx.farField->started() && b.mesh.fn > 0) {
                b.ctx.farField->start(b.mesh);
                b.stats.relaxed.push_back("far field from " + std::to_string(b.mesh.fn) +
                                          " faces: collapses and removals ranked by the largest distance they "
                                          "open, and held to the budget by it alone (the shape guard, the normal "
                                          "threshold and, unless tunnels are kept, the topology give way)");
            }
    }

    // From the next collapse on, collapses before the far field are held to the distance
    // bound too (CollapseContext::checksDistance): the input's points are dealt to each
    // bucket's faces when it next collapses. The quadric error of a collapse tells the
    // distance it opens only within a factor that varies from one collapse to the next (a
    // relay's levels measured 1.3 to 2.6 times their largest collapse error), so a bound on
    // it alone must allow for the worst, and holds most collapses far below the budget.
    void holdToDistanceBeforeFarField() { holdBeforeFarField_ = true; }

    // Whether every bucket that has faces left is in the far field.
    bool inFarField() const
    {
        return std::all_of(buckets_.begin(), buckets_.end(),
                           [](const Bucket& b) { return b.mesh.fn == 0 || b.ctx.inFarField(); });
    }

    // The buckets' statistics added up onto `total` (counts summed, largest values kept,
    // what gave way listed bucket by bucket); the buckets' lists start afresh.
    void addStatsTo(SimplifyStats& total)
    {
        for (Bucket& b : buckets_) {
            const SimplifyStats& s = b.stats;
            for (int SimplifyStats::*count : kSessionCounts)
                total.*count += s.*count - b.reported.*count;
            total.largestRemovedComponent = std::max(total.largestRemovedComponent, s.largestRemovedComponent);
            total.halvesBandVertices = std::max(total.halvesBandVertices, s.halvesBandVertices);
            total.widestTunnelCap = std::max(total.widestTunnelCap, s.widestTunnelCap);
            total.relaxed.insert(total.relaxed.end(), s.relaxed.begin(), s.relaxed.end());
            b.stats.relaxed.clear();
            b.reported = b.stats;
        }
    }

    // The buckets, in order, into the empty mesh `out` (parts kept).
    void appendTo(MeshType& out)
    {
        out.Clear();
        for (Bucket& b : buckets_) {
            if (&b == &buckets_.front())
                detail::copyWithParts(out, b.mesh);
            else
                vcg::tri::Append<MeshType, MeshType>::Mesh(out, b.mesh, false, false);
        }
        vcg::tri::Allocator<MeshType>::CompactEveryVector(out);
    }

    // Ends the sessions and gives back the bit flags (the meshes stay).
    void release()
    {
        for (Bucket& b : buckets_)
            if (b.ready) {
                releaseCollapse(b.mesh, b.ctx);
                b.ready = false;
            }
    }

private:
    struct Bucket {
        explicit Bucket(MeshType& m) : mesh(m) {}
        MeshType& mesh;
        CollapseContext<MeshType> ctx;
        SimplifyStats stats;
        SimplifyStats reported;  // what addStatsTo has counted already
        bool ready = false;
    };

    // The largest value of a session's `field` over the buckets.
    double largestOver(double CollapseContext<MeshType>::*field) const
    {
        double e = 0.0;
        for (const Bucket& b : buckets_)
            e = std::max(e, b.ctx.*field);
        return e;
    }

    template <class Work>
    void forEachBucket(std::size_t begin, std::size_t end, const RunTogether& together, const Work& work)
    {
        if (end - begin == 1) {
            work(buckets_[begin]);
            return;
        }
        if (end == begin)
            return;
        const std::size_t middle = begin + (end - begin) / 2;
        together([&] { forEachBucket(begin, middle, together, work); },
                 [&] { forEachBucket(middle, end, together, work); });
    }

    // Face indices of `model` per bucket: groups of touching components, largest first, each
    // to the bucket with the fewest faces so far (the first such on a tie).
    static std::vector<std::vector<std::size_t>> deal(MeshType& model, const std::vector<Component<MeshType>>& components)
    {
        const std::vector<int> group = touchGroups(model, components);
        const std::size_t groups = group.empty() ? 0 : std::size_t(*std::max_element(group.begin(), group.end())) + 1;
        std::vector<std::vector<std::size_t>> facesOfGroup(groups);
        for (std::size_t c = 0; c < components.size(); ++c)
            for (auto* f : components[c].faces)
                facesOfGroup[std::size_t(group[c])].push_back(std::size_t(f - &model.face[0]));
        std::vector<std::size_t> order(groups);
        std::iota(order.begin(), order.end(), std::size_t(0));
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return facesOfGroup[a].size() > facesOfGroup[b].size();
        });
        std::vector<std::vector<std::size_t>> buckets(std::min(kMaxCollapseBuckets, groups));
        for (std::size_t g : order) {
            auto lightest = std::min_element(buckets.begin(), buckets.end(),
                                             [](const auto& a, const auto& b) { return a.size() < b.size(); });
            lightest->insert(lightest->end(), facesOfGroup[g].begin(), facesOfGroup[g].end());
        }
        for (auto& faces : buckets)
            std::sort(faces.begin(), faces.end());  // the model's face order within a bucket
        return buckets;
    }

    // Copies the faces `faces` of `model` (and their vertices) into the empty mesh `out`.
    static void copyFaces(MeshType& model, const std::vector<std::size_t>& faces, MeshType& out)
    {
        vcg::tri::UpdateSelection<MeshType>::Clear(model);
        for (std::size_t f : faces)
            model.face[f].SetS();
        out.Clear();
        if (hasParts(model)) {
            facePartHandle(out);
            partTableHandle(out)() = partTableHandle(model)();
        }
        vcg::tri::Append<MeshType, MeshType>::Mesh(out, model, true, false);
        vcg::tri::UpdateSelection<MeshType>::Clear(model);
        vcg::tri::UpdateSelection<MeshType>::Clear(out);
        vcg::tri::Allocator<MeshType>::CompactEveryVector(out);
    }

    std::function<MeshType&()> newMesh_;
    std::deque<Bucket> buckets_;
    std::shared_ptr<ComponentSurfaces> wholeModel_;  // the model as dealt (rest_of_model.h)
    bool holdBeforeFarField_ = false;  // holdToDistanceBeforeFarField
};

}  // namespace cadlod
