// The CAD Quadric Edge Collapse: a vcglib local-optimization edge collapse (the
// TriEdgeCollapse framework, like vcglib's TriEdgeCollapseQuadric) whose vertex placement
// breaks quadric-cost ties by triangle compactness. Its parts:
//   - placement.h, the placement policy: the candidates of an edge (both endpoints, points
//     between them, the quadric's own placement: quadric_placement.h), each ranked at its
//     quadric cost, times featurePenalty where it breaks a feature, plus the price of the
//     shading it changes; among those tied with the cheapest (a relative tolerance, or the
//     rounding of float coordinates where every candidate costs nothing), the one whose new
//     faces are the most compact;
//   - new_face_checks.h: what the new faces at a placement would be (turned, below the shape
//     floor, folding a smooth join), collapse_ring.h: the faces around the edge now;
//   - collapse_cost.h, the cost model: the priority of the chosen placement, its quadric cost
//     (normalised by the bbox diagonal; the sum over the merged planes, as in Garland-Heckbert)
//     plus a floor of the rounding size that orders the free collapses of flat regions and
//     straight lines, smallest merged area and best shape first. Dividing the whole priority by
//     the shape, as vcglib's QualityThr does, would delay real error reductions for shape, and
//     a floor far above the rounding would order real, small errors by shape instead of error;
//   - far_field_placement.h: in the far field, placement and priority by the distance opened;
//   - this file: the heap entry, and IsFeasible's list of checks on the collapse about to run
//     (the topology, the distance bound, facing the input surface), each of which accepts,
//     refuses or prices it.
//
// Evaluation is lazy: an edge enters the heap with a cheap lower bound of its priority
// (collapse_cost.h, no look at the faces around it) and is evaluated in full only when it
// reaches the top. If its real priority is then above the next entry's, it goes back into
// the heap with that value. Most entries go stale before they reach the top, so most full
// evaluations (O(valence) per candidate) are never done. An evaluated entry whose faces
// changed since (a neighbour collapsed) is evaluated again when it reaches the top.
//
// vcglib pitfalls handled here: the base constructor would call the base ComputePriority,
// so this class sets its own fields; ComputePosition is not virtual in vcglib, so the
// position is computed and stored by ComputePriority; all per-run state lives in the
// CollapseContext passed as the BaseParameterClass, not in statics: the context's `mark`
// replaces vcglib's static GlobalMark(), and IsUpToDate is this class's own (vcglib's
// counts failures in a static), so sessions on different meshes may run at the same time.
#pragma once

#include "simplify/cad_quadrics.h"
#include "simplify/collapse_context.h"
#include "simplify/collapse_cost.h"
#include "simplify/collapse_ring.h"
#include "simplify/entry_pool.h"
#include "simplify/far_field_placement.h"
#include "simplify/new_face_checks.h"
#include "simplify/placement.h"
#include "simplify/collapse_edge.h"
#include "simplify/collapse_heap.h"
#include "measure/compactness.h"
#include "mesh/crease_fans.h"
#include "simplify/far_field.h"
#include "simplify/feature_edges.h"
#include "measure/input_surface.h"
#include "simplify/link_condition.h"
#include "simplify/removal_log.h"
#include "simplify/simplify_params.h"

#include <vcg/complex/algorithms/edge_collapse.h>
#include <vcg/complex/algorithms/local_optimization.h>
#include <vcg/complex/algorithms/local_optimization/tri_edge_collapse.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <memory_resource>
#include <utility>
#include <vector>

namespace cadlod {

template <class MeshType>
class TunnelCut;  // tunnel_cut.h: offered when a collapse fails the link condition

template <class MeshType>
class CadEdgeCollapse
    : public vcg::tri::TriEdgeCollapse<MeshType, vcg::tri::BasicVertexPair<typename MeshType::VertexType>,
                                       CadEdgeCollapse<MeshType>>
{
public:
    using VertexType = typename MeshType::VertexType;
    using FaceType = typename MeshType::FaceType;
    using VertexPair = vcg::tri::BasicVertexPair<VertexType>;
    using Base = vcg::tri::TriEdgeCollapse<MeshType, VertexPair, CadEdgeCollapse<MeshType>>;
    using HeapType = typename vcg::LocalOptimization<MeshType>::HeapType;
    using HeapElem = typename vcg::LocalOptimization<MeshType>::HeapElem;
    using ScalarType = typename MeshType::ScalarType;
    using Context = CollapseContext<MeshType>;
    using VFIterator = vcg::face::VFIterator<FaceType>;
    using Ring = CollapseRing<MeshType>;
    using Checks = NewFaceChecks<MeshType>;
    using Place = Placement<MeshType>;
    using Far = FarFieldPlacement<MeshType>;
    using Cost = CollapseCost<MeshType>;
    using Candidate = typename Place::Candidate;
    static constexpr int kMaxCandidates = Place::kMaxCandidates;

    static void* operator new(std::size_t size) { return EntryPool::allocate(size); }
    static void operator delete(void* p, std::size_t size) { EntryPool::deallocate(p, size); }

    CadEdgeCollapse(const VertexPair& p, int mark, vcg::BaseParameterClass* pp)
    {
        this->localMark = mark;
        this->pos = p;
        this->_priority = Cost::lowerBound(*static_cast<Context*>(pp), this->pos.V(0), this->pos.V(1));
    }

    ScalarType ComputePriority(vcg::BaseParameterClass* pp) override
    {
        evaluate(*static_cast<Context*>(pp));
        return this->_priority;
    }

    // Out of date when a vertex was deleted or changed after this entry was made.
    bool IsUpToDate() const override
    {
        const VertexType* v0 = this->pos.cV(0);
        const VertexType* v1 = this->pos.cV(1);
        return !v0->IsD() && !v1->IsD() && this->localMark >= v0->cIMark() && this->localMark >= v1->cIMark();
    }

    // The collapse evaluated (again, if its ring changed since), then the checks of the
    // collapse about to run, in order: each accepts it, refuses it (counted in the session's
    // stats), or prices it (it goes back into the heap when no longer the cheapest).
    bool IsFeasible(vcg::BaseParameterClass* pp) override
    {
        Context& ctx = *static_cast<Context*>(pp);
        if (!evaluated_ || ringChangedSinceEvaluation(ctx)) {
            evaluate(ctx);
            if (feasible_ && !stillFirst(ctx))
                return false;
        }
        if (!feasible_)
            return false;
        for (const Check check : {&CadEdgeCollapse::keepsTopology, &CadEdgeCollapse::staysWithinDistance,
                                  &CadEdgeCollapse::facesTheInput}) {
            const Verdict v = (this->*check)(ctx);
            switch (v.kind) {
            case Verdict::accept:
                continue;
            case Verdict::reject:
                ++(ctx.stats->*v.reason);
                return false;
            case Verdict::price:
                this->_priority *= ScalarType(v.factor);
                return stillFirst(ctx);
            case Verdict::retryOnTheEdge:
                return retryOnTheEdge(ctx);
            }
        }
        return true;
    }

    void Execute(MeshType&, vcg::BaseParameterClass* pp) override
    {
        Context& ctx = *static_cast<Context*>(pp);
        VertexType* v0 = this->pos.V(0);
        VertexType* v1 = this->pos.V(1);
        // Feature edges (v0,x) and (v1,x) of the faces about to vanish merge into (v1,x):
        // remember x so that the surviving edge keeps the feature mark.
        std::vector<VertexType*> featureApex;
        for (VFIterator vfi(v0); !vfi.End(); ++vfi) {
            FaceType* f = vfi.F();
            const int z = vfi.I();
            if (f->V((z + 1) % 3) != v1 && f->V((z + 2) % 3) != v1)
                continue;
            const int apexIndex = f->V((z + 1) % 3) == v1 ? (z + 2) % 3 : (z + 1) % 3;
            if (f->IsUserBit(ctx.bits.edge[apexIndex]) || f->IsUserBit(ctx.bits.edge[(apexIndex + 2) % 3]))
                featureApex.push_back(f->V(apexIndex));
        }
        if (v0->IsUserBit(ctx.bits.boundary))
            v1->SetUserBit(ctx.bits.boundary);
        ctx.quadrics.merge(v0, v1);
        const bool points = ctx.farField && ctx.farField->dealt();
        if (points)
            ctx.farField->takePointsAround(v0, v1);
        const CollapseCount deleted = collapseEdge(v0, v1, target_);
        if (points)
            ctx.farField->dealPointsAround(v1);
        *ctx.faceCounter -= deleted.faces;
        *ctx.vertexCounter -= deleted.vertices;
        for (VertexType* x : featureApex)
            markEdge(ctx, v1, x);
        ctx.recordError(error_, distance_);
        if (joinsBoundary_)
            ++ctx.stats->boundaryJoins;
        if (breaksFeature_) {
            ++ctx.stats->featureBreaks;
            ctx.largestFeatureBreak = std::max(ctx.largestFeatureBreak, double(error_));
        }
    }

    // The surviving vertex's edges are pushed again (its quadric changed), and so are the
    // edges among its neighbours, which an earlier refusal may have taken out of the heap.
    // The neighbours' other edges keep their entries (their quadrics did not change, so
    // their bounds still hold) but are marked for a new evaluation when they reach the
    // top: vcglib's quadric collapse marks them out of date instead, and they drop out of
    // the heap until it is rebuilt.
    void UpdateHeap(HeapType& heap, vcg::BaseParameterClass* pp) override
    {
        Context& ctx = *static_cast<Context*>(pp);
        const int mark = ++ctx.mark;
        VertexType* v1 = this->pos.V(1);
        v1->IMark() = mark;
        ctx.ringChanged(v1) = mark;
        for (VFIterator vfi(v1); !vfi.End(); ++vfi) {
            vfi.V1()->ClearV();
            vfi.V2()->ClearV();
            ctx.ringChanged(vfi.V1()) = mark;
            ctx.ringChanged(vfi.V2()) = mark;
        }
        for (VFIterator vfi(v1); !vfi.End(); ++vfi) {
            if (!vfi.V1()->IsV() && vfi.V1()->IsRW()) {
                vfi.V1()->SetV();
                push(heap, vfi.V0(), vfi.V1(), pp);
            }
            if (!vfi.V2()->IsV() && vfi.V2()->IsRW()) {
                vfi.V2()->SetV();
                push(heap, vfi.V2(), vfi.V0(), pp);
            }
            if (vfi.V1()->IsRW() && vfi.V2()->IsRW())
                push(heap, vfi.V1(), vfi.V2(), pp);
        }
    }

    // The edges of `v` whose other end is writable (after a tunnel cut).
    static void pushEdgesOf(HeapType& heap, VertexType* v, vcg::BaseParameterClass* pp)
    {
        if (!v->IsRW())
            return;
        for (VFIterator vfi(v); !vfi.End(); ++vfi) {
            vfi.V1()->ClearV();
            vfi.V2()->ClearV();
        }
        for (VFIterator vfi(v); !vfi.End(); ++vfi)
            for (VertexType* w : {vfi.V1(), vfi.V2()})
                if (!w->IsV() && w->IsRW()) {
                    w->SetV();
                    push(heap, v, w, pp);
                }
    }

    // Every edge once, both vertices writable.
    static void Init(MeshType& m, HeapType& heap, vcg::BaseParameterClass* pp)
    {
        for (HeapElem& e : heap)
            delete e.locModPtr;
        heap.clear();
        for (VertexType& v : m.vert)
            appendEdgesOf(&v, heap, pp);
    }

    // The edges from `v` to writable vertices after it in memory (so each edge once, when
    // this is done for every vertex), appended to `heap` unordered.
    static void appendEdgesOf(VertexType* v, HeapType& heap, vcg::BaseParameterClass* pp)
    {
        if (v->IsD() || !v->IsRW())
            return;
        for (VFIterator x(v); !x.End(); ++x) {
            x.V1()->ClearV();
            x.V2()->ClearV();
        }
        for (VFIterator x(v); !x.End(); ++x) {
            for (VertexType* w : {x.V1(), x.V2()}) {
                if (v < w && w->IsRW() && !w->IsV()) {
                    w->SetV();
                    heap.push_back(HeapElem(new CadEdgeCollapse(VertexPair(v, w), static_cast<Context*>(pp)->mark, pp)));
                }
            }
        }
    }

    static void Finalize(MeshType&, HeapType&, vcg::BaseParameterClass*) {}
    static float HeapSimplexRatio(vcg::BaseParameterClass*) { return 4.0f; }
    static bool IsSymmetric(vcg::BaseParameterClass*) { return true; }

    const vcg::Point3<ScalarType>& target() const { return target_; }
    float error() const { return error_; }

private:
    bool ringChangedSinceEvaluation(Context& ctx) const
    {
        return ctx.ringChanged(this->pos.cV(0)) > evaluatedAt_ || ctx.ringChanged(this->pos.cV(1)) > evaluatedAt_;
    }

    // The heap owns and deletes the popped entry: a copy, now evaluated, goes back in.
    void requeue(HeapType& heap) const
    {
        heapPush(heap, HeapElem(new CadEdgeCollapse(*this)));
    }

    static void push(HeapType& heap, VertexType* a, VertexType* b, vcg::BaseParameterClass* pp)
    {
        heapPush(heap, HeapElem(new CadEdgeCollapse(VertexPair(a, b), static_cast<Context*>(pp)->mark, pp)));
    }

    // In the far field of a session held to a distance (an LOD chain's level) the topology
    // gives way like the other locks, unless tunnels are to be kept: the distance alone judges
    // a collapse there. A thin part may flatten into a two-sided sheet (coincident faces of
    // opposite orientation), a hole close, two touching parts collapse into one another, where
    // the level's budget allows; an edge may then have more than two faces.
    static bool topologyGivesWay(const Context& ctx) { return ctx.heldToDistance() && ctx.params.closeTunnels; }

    // A quadric minimum off the edge would turn a face away from the input surface: on a
    // convex surface the minimum lies outside the chords, and where another part fits
    // closely (a pin in its bore) that is across its surface. The points of the segment
    // lie within the chords: the collapse is evaluated again with those alone (IsFeasible
    // evaluates it, and puts it back in the heap if it is no longer first).
    bool retryOnTheEdge(Context& ctx)
    {
        onTheEdgeOnly_ = true;
        evaluated_ = false;
        return IsFeasible(&ctx);
    }

    // Whether this entry, its priority raised since it was pushed, is still no dearer than
    // the heap's top; if not, it goes back into the heap to wait its turn.
    bool stillFirst(Context& ctx) const
    {
        if (ctx.heap && !ctx.heap->empty() && this->_priority > ctx.heap->front().pri) {
            requeue(*ctx.heap);
            return false;
        }
        return true;
    }

    // What a check says of the collapse about to run.
    struct Verdict {
        enum Kind { accept, reject, price, retryOnTheEdge } kind = accept;
        int SimplifyStats::*reason = nullptr;  // reject: the count it adds to
        double factor = 1.0;                   // price: what the priority is multiplied by
    };
    using Check = Verdict (CadEdgeCollapse::*)(Context&);
    static Verdict refused(int SimplifyStats::*reason) { return {Verdict::reject, reason}; }
    static Verdict priced(double factor) { return {Verdict::price, nullptr, factor}; }

    // The link condition, and no edge left with more than two faces (link_condition.h), unless
    // topology is not preserved, gives way here (topologyGivesWay), or the collapse was priced
    // for it already. A collapse that closes a hole or joins boundary runs changes the topology
    // where the viewer sees a surface closed a little early: toward a face target it is ranked
    // like a feature break, so that it runs when it is cheaper than what else is left. Any
    // other is refused, and a cut of the tunnel it would close is offered (tunnel_cut.h).
    Verdict keepsTopology(Context& ctx)
    {
        VertexType* v0 = this->pos.V(0);
        VertexType* v1 = this->pos.V(1);
        if (!ctx.params.preserveTopology || topologyGivesWay(ctx) || joinsBoundary_ ||
            (vcg::tri::EdgeCollapser<MeshType, VertexPair>::LinkConditions(this->pos) &&
             !makesNonManifoldEdge(v0, v1)) ||
            (ctx.inFarField() && foldsTetrahedron(v0, v1)))
            return {};
        if (ctx.joinBoundaries && joinsBoundaryOnly(v0, v1)) {
            joinsBoundary_ = true;
            return priced(std::max(1.0, ctx.params.featurePenalty));
        }
        TunnelCut<MeshType>::offer(ctx, v0, v1);
        return refused(&SimplifyStats::rejectedTopology);
    }

    // Before the far field, with the input's points dealt: the session's distance bound.
    Verdict staysWithinDistance(Context& ctx)
    {
        if (ctx.checksDistance() && !opensWithinBound(ctx))
            return refused(&SimplifyStats::rejectedError);
        return {};
    }

    // Whether the new faces face the input surface near them (input_surface.h), down to the
    // far field's floor, where the check gives way. A collapse that would turn one away is
    // tried again on the segment's points alone where its placement was off the edge, else
    // refused, or ranked at facingPenalty times its priority.
    Verdict facesTheInput(Context& ctx)
    {
        if (!ctx.surface || turnsAway_ || free_)
            return {};
        if (*ctx.faceCount <= ctx.farFieldFloor) {
            ctx.facingGaveWay = true;
            return {};
        }
        if (newFacesFaceTheInput(ctx))
            return {};
        if (offEdge_)
            return {Verdict::retryOnTheEdge};
        if (ctx.facingPenalty <= 0)
            return refused(&SimplifyStats::rejectedFlip);
        turnsAway_ = true;
        return priced(ctx.facingPenalty);
    }

    // Before the far field, with the input's points dealt: whether the collapse about to run
    // opens no more than the session's distance bound. Its priority is its quadric error,
    // which the distance does not change, so it is measured here, on the collapses that come
    // to run, and not at every evaluation: most entries are evaluated again, their ring
    // changed by a collapse nearby, before they come to the top.
    bool opensWithinBound(Context& ctx)
    {
        VertexType* v0 = this->pos.V(0);
        VertexType* v1 = this->pos.V(1);
        Ring::gatherRing(ctx, v0, v1);
        // Held to the bound and recorded into the session's largest distance only, a
        // distance need not be told apart below the largest the session has opened (or the
        // bound, where a level's bound is below an earlier one's).
        std::uint32_t farthest = FarFieldDistances<MeshType>::kNoPoint;
        distance_ = Far::farFieldDistance(ctx, v0, v1, vcg::Point3d::Construct(target_), ctx.maxDistance * (1 + 1e-9),
                                          farthest, std::min(ctx.largestDistance, ctx.maxDistance));
        return !ctx.exceedsBound(error_, distance_);
    }

    // Checked last, on the collapse about to run only: a closest-face search or two per new
    // face are too dear for every evaluation (input_surface.h). Free collapses (within the
    // flat floor) are not checked: they keep their faces on the input planes.
    bool newFacesFaceTheInput(Context& ctx) const
    {
        const vcg::Point3d p = vcg::Point3d::Construct(target_);
        for (const VertexType* v : {this->pos.cV(0), this->pos.cV(1)}) {
            const VertexType* other = v == this->pos.cV(0) ? this->pos.cV(1) : this->pos.cV(0);
            for (VFIterator vfi(const_cast<VertexType*>(v)); !vfi.End(); ++vfi) {
                const FaceType* f = vfi.F();
                const int z = vfi.I();
                const VertexType* a = f->cV((z + 1) % 3);
                const VertexType* b = f->cV((z + 2) % 3);
                if (a == other || b == other)
                    continue;  // vanishes with the edge
                const vcg::Point3d pa = vcg::Point3d::Construct(a->cP()), pb = vcg::Point3d::Construct(b->cP());
                const vcg::Point3d n = (pa - p) ^ (pb - p);
                const double len = n.Norm();
                if (!(len > 0) || !ctx.surface->facesAlong(std::size_t(f - ctx.faceBase), (p + pa + pb) / 3.0, n / len))
                    return false;
            }
        }
        return true;
    }

    static void markEdge(Context& ctx, VertexType* v, VertexType* x)
    {
        for (VFIterator vfi(v); !vfi.End(); ++vfi) {
            FaceType* f = vfi.F();
            const int z = vfi.I();
            if (f->V((z + 1) % 3) == x)
                f->SetUserBit(ctx.bits.edge[z]);
            if (f->V((z + 2) % 3) == x)
                f->SetUserBit(ctx.bits.edge[(z + 2) % 3]);
        }
    }

    void reject(int& reason)
    {
        ++reason;
        feasible_ = false;
        this->_priority = std::numeric_limits<ScalarType>::max();
    }

    void evaluate(Context& ctx)
    {
        evaluated_ = true;
        evaluatedAt_ = ctx.mark;
        turnsAway_ = false;
        joinsBoundary_ = false;
        feasible_ = true;
        breaksFeature_ = false;
        VertexType* v0 = this->pos.V(0);
        VertexType* v1 = this->pos.V(1);
        SimplifyStats& stats = *ctx.stats;
        if (v0->IsUserBit(ctx.bits.locked) || v1->IsUserBit(ctx.bits.locked))
            return reject(stats.rejectedFeature);
        const typename Ring::Neighbourhood n = Ring::gatherRing(ctx, v0, v1);
        if (ctx.ring.empty())
            return reject(stats.rejectedTopology);  // would delete a whole component

        const Quadric q = Cost::mergedQuadric(ctx, v0, v1);
        const double area = double(ctx.quadrics.area(v0)) + double(ctx.quadrics.area(v1));
        // A corner (a crease end, or where creases meet) keeps its place, and so does any
        // feature vertex when the edge leaves its feature: it is pinned. Along a crease the
        // new vertex may move (interior points, the optimum): the crease's constraint planes
        // hold it on the crease, and it can cut the chord error of a curved crease in half.
        // Along a boundary a vertex may only take the other endpoint's place. An edge between
        // two feature vertices that is no feature itself cuts across.
        const bool crosses = n.v0OnFeature && n.v1OnFeature && !n.edgeIsFeature;
        const bool v0Pinned = n.v0OnFeature && (!n.edgeIsFeature || n.v0Corner);
        const bool v1Pinned = n.v1OnFeature && (!n.edgeIsFeature || n.v1Corner);
        const bool onBoundaryLine =
            n.edgeIsFeature && (v0->IsUserBit(ctx.bits.boundary) || v1->IsUserBit(ctx.bits.boundary));
        const double flatFloor = area * ctx.flatError2;
        Candidate cand[kMaxCandidates];
        const int count =
            Place::rankedCandidates(ctx, q, vcg::Point3d::Construct(v0->cP()), vcg::Point3d::Construct(v1->cP()),
                                    v0Pinned, v1Pinned, onBoundaryLine, crosses, flatFloor, !onTheEdgeOnly_, cand);
        if (count == 0)
            return reject(stats.rejectedFeature);
        double minRanked = std::numeric_limits<double>::max();
        for (int i = 0; i < count; ++i)
            minRanked = std::min(minRanked, cand[i].ranked);
        const double tieLimit = minRanked * (1.0 + ctx.params.tieTolerance) + area * ctx.roundingError2;

        const typename Place::ShapeFloors floors = Place::shapeFloors(ctx, n, flatFloor);
        typename Place::Choice choice = Place::mostCompactOfTied(ctx, cand, count, tieLimit, floors);
        if (choice.best < 0)
            return reject(choice.anyFlip ? stats.rejectedFlip : stats.rejectedCompactness);
        int& best = choice.best;
        PlacementScore& bestScore = choice.score;
        const typename Far::FarFieldChoice farField =
            ctx.inFarField() ? Far::farFieldPlacement(ctx, v0, v1, cand, count, area, floors, best, bestScore, choice.failed)
                             : typename Far::FarFieldChoice();
        distance_ = farField.opened;

        const double cost = cand[best].cost;
        target_ = vcg::Point3<ScalarType>::Construct(cand[best].p);
        error_ = Cost::errorOf(cost, area);
        breaksFeature_ = cand[best].breaks;
        offEdge_ = cand[best].offEdge;
        free_ = cost <= flatFloor;
        if (ctx.exceedsBound(error_, distance_))
            return reject(stats.rejectedError);
        const double qualityThr = ctx.params.qualityThreshold;
        const double shape = qualityThr > 0 ? std::clamp(bestScore.meanCompactness / qualityThr, 0.02, 1.0) : 1.0;
        if (ctx.inFarField()) {
            this->_priority = ScalarType(ctx.farFieldPriority(std::sqrt(farField.ranked2)));
        } else {
            this->_priority = Cost::priorityOf(ctx, cand[best].ranked, ctx.quadrics.cappedArea(v0, v1), shape);
            if (n.removesSliver)
                this->_priority *= ScalarType(ctx.params.sliverFirstShare);
        }
    }

    vcg::Point3<ScalarType> target_;
    float error_ = 0.0f;
    double distance_ = 0.0;  // in the far field: the distance the collapse opens (not as ranked)
    bool feasible_ = true;
    bool breaksFeature_ = false;
    bool evaluated_ = false;
    bool turnsAway_ = false;  // a new face would turn away from the input surface: ranked at facingPenalty
    bool joinsBoundary_ = false;  // closes a hole or joins boundary runs: ranked like a feature break
    bool free_ = false;       // costs no more than the flat floor
    bool offEdge_ = false;    // target_ is a quadric minimum off the segment
    bool onTheEdgeOnly_ = false;  // a minimum off the segment turned a face away: the segment's points only
    int evaluatedAt_ = 0;  // ctx.mark when evaluated
};

}  // namespace cadlod
