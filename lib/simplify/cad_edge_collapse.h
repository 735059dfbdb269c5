// The CAD Quadric Edge Collapse: a vcglib local-optimization edge collapse (the
// TriEdgeCollapse framework, like vcglib's TriEdgeCollapseQuadric) whose vertex placement
// breaks quadric-cost ties by triangle compactness.
//
// For an edge (v0, v1) the candidates are v0, v1, evenly spaced points between them and the
// quadric's optimum near the edge (where the planes meet in a line and there is none, the
// point of that line nearest the edge's middle: quadricPlacement). Candidates within a
// relative tolerance of the cheapest cost, or within the rounding of float coordinates
// (flat regions, where every candidate costs nothing but rounding), are tied; the tied
// candidate whose surrounding triangles have the highest mean compactness wins.
// Priority = quadric cost of the chosen position (normalised by the bbox diagonal; the
// sum over the merged planes, as in Garland–Heckbert), plus a floor of the same rounding
// size that orders the free collapses of flat regions and straight lines: smallest merged
// area and best shape first (the floor is divided by the mean compactness of the new
// triangles over qualityThreshold, capped at 1). Dividing the whole priority by the
// shape, as vcglib's QualityThr does, delays real error reductions for shape: on the
// bench shaft at 90 % that cost Hausdorff and gained no compactness. So does a floor far
// above the rounding: it ties and orders real, small errors by shape instead of by error,
// and the largest of them grows (docs/benchmarks.md).
//
// Evaluation is lazy: an edge enters the heap with a cheap lower bound of its priority
// (the quadric cost of its cheapest candidate, no look at the faces around it) and is
// evaluated in full only when it reaches the top. If its real priority is then above the
// next entry's, it goes back into the heap with that value. Most entries go stale before
// they reach the top, so most full evaluations (O(valence) per candidate) are never done.
// An evaluated entry whose faces changed since (a neighbour collapsed) is evaluated again
// when it reaches the top.
//
// Shape guards: no collapse may create a face below minCompactness unless the faces around
// the edge were already worse, and a free collapse (cost within the flat floor) none below
// 0.1 (a sliver): free collapses can wait for a shape-keeping one.
//
// vcglib pitfalls handled here: the base constructor would call the base ComputePriority,
// so this class sets its own fields; ComputePosition is not virtual in vcglib, so the
// position is computed and stored by ComputePriority; all per-run state lives in the
// CollapseContext passed as the BaseParameterClass, not in statics: the context's `mark`
// replaces vcglib's static GlobalMark(), and IsUpToDate is this class's own (vcglib's
// counts failures in a static), so sessions on different meshes may run at the same time.
#pragma once

#include "simplify/cad_quadrics.h"
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
class ComponentSurfaces;  // rest_of_model.h: how far a component stands off the others

// A face around the collapsing edge that survives it: (new vertex, a, b). What does not
// depend on the new vertex is computed once per edge, not once per candidate.
struct RingFace {
    vcg::Point3d a, b;
    vcg::Point3d normal;    // before the collapse, not normalised (zero for zero-area faces)
    double normalLength;    // |normal|
    vcg::Point3d original;  // unit normal the face had in the input (zero if none)
    double abSquared;       // |b - a|²
    // With keepSmoothJoins: the unit normal of the face beyond the outer edge a-b (zero
    // where there is none), and the endpoint the face is around (0: v0, 1: v1).
    vcg::Point3d beyond{0, 0, 0};
    int side = 0;
};

struct PlacementScore {
    bool valid = false;
    bool flipped = false;
    double meanCompactness = 0.0;
};

// Heap entries are made and deleted by the million (every push and every re-queue): they
// come from a pool, which takes memory from malloc a chunk of entries at a time, and gives
// it all back when its last entry is deleted (a session's end). Each thread has a pool of
// its own; a session whose heap outlives one task (a half of collapse_halves.h, whose
// rounds may each run on another thread) brings its own and puts it in use (EntryPool::Use)
// wherever its entries are made or deleted.
class EntryPool
{
public:
    EntryPool() = default;
    EntryPool(const EntryPool&) = delete;
    EntryPool& operator=(const EntryPool&) = delete;

    // The pool entries come from on this thread while it lives.
    class Use
    {
    public:
        explicit Use(EntryPool& pool) : previous_(current()) { current() = &pool; }
        ~Use() { current() = previous_; }
        Use(const Use&) = delete;
        Use& operator=(const Use&) = delete;

    private:
        EntryPool* previous_;
    };

    static void* allocate(std::size_t size)
    {
        EntryPool& p = inUse();
        ++p.live_;
        return p.pool_.allocate(size);
    }
    static void deallocate(void* ptr, std::size_t size)
    {
        EntryPool& p = inUse();
        p.pool_.deallocate(ptr, size);
        if (--p.live_ == 0)
            p.pool_.release();
    }

private:
    static EntryPool*& current()
    {
        thread_local EntryPool* pool = nullptr;
        return pool;
    }
    static EntryPool& inUse()
    {
        thread_local EntryPool own;
        EntryPool* p = current();
        return p ? *p : own;
    }

    std::pmr::unsynchronized_pool_resource pool_;
    std::size_t live_ = 0;
};

// What float coordinates resolve, as a share of their magnitude (a few units in the last
// place): quadric costs below this distance are rounding, not error.
inline constexpr double kRoundingOfFloat = 2.5 * std::numeric_limits<float>::epsilon();

template <class MeshType>
struct CollapseContext : public vcg::BaseParameterClass {
    using VertexType = typename MeshType::VertexType;

    SimplifyParams params;
    FeatureBits bits;
    bool ownsBits = true;         // bits taken by this session (not shared with others)
    // The per-vertex and per-face arrays of the mesh, one set for every session on it: a
    // copy of a context is a second session on the same mesh (collapse_halves.h), and the
    // two write the entries of different vertices and faces only.
    struct MeshArrays {
        VertexQuadrics<VertexType> quadrics;
        std::vector<int> ringChangedAt;         // per vertex: `mark` when a face around it last changed
        std::vector<vcg::Point3f> inputNormal;  // per face index: unit normal in the input
    };
    std::shared_ptr<MeshArrays> arrays = std::make_shared<MeshArrays>();
    VertexQuadrics<VertexType>& quadrics = arrays->quadrics;
    std::vector<int>& ringChangedAt = arrays->ringChangedAt;
    std::vector<vcg::Point3f>& inputNormal = arrays->inputNormal;
    SimplifyStats* stats = nullptr;
    double diagonal = 1.0;
    double flatError2 = 0.0;      // (flatTolerance * diagonal)²: collapses within it are free
    double roundingError2 = 0.0;  // (kRoundingOfFloat * the coordinates' magnitude)²
    double maxErrorAbs = 0.0;     // 0: unbounded
    // In the far field, when > 0: the largest distance an operation may open, in place of
    // maxErrorAbs (an LOD chain's budget, params.farFieldWithinBound).
    double maxDistance = 0.0;
    double cosNormalLimit = -1.0;
    double cosShadingAngle = 1.0;  // faces turned further from their input face change shade
    double cosSmoothJoin = -2.0;   // keepSmoothJoins: cosine of the crease angle; below -1: off
    double shadingScale = 0.0;     // shadingWeight × diagonal²: the price of a unit of turned area
    double largestError = 0.0;    // over executed collapses
    double largestDistance = 0.0; // over operations held to maxDistance (far field)
    double largestFeatureBreak = 0.0;  // largest error of an executed collapse that broke a feature
    bool shapeGuards = true;      // minCompactness and the free-sliver guard apply (relaxed last)
    bool countsSlivers = false;   // with the shape guards: no collapse adds to the slivers around it
    // Toward a face target: collapses that close a hole or join boundary runs are offered,
    // priced (link_condition.h). A session held to an error ends where they would begin.
    bool joinBoundaries = false;
    RemovalLog removals;          // the log's lines of components removed whole, one per name
    typename vcg::LocalOptimization<MeshType>::HeapType* heap = nullptr;  // for re-queued entries
    std::vector<RingFace> ring;   // scratch of the edge being evaluated
    int mark = 0;                 // this session's clock: ticks at every collapse (vcglib's GlobalMark)
    bool mayRemoveLargestComponent = false;  // the mesh is a piece of a model whose largest component is elsewhere
    // A piece of a model (collapse_buckets.h): the whole model's components as it was dealt,
    // and per face of the piece the model's component it came from, for the gap a removal
    // leaves (component_removal.h). Null: the session's mesh is the whole model.
    std::shared_ptr<const ComponentSurfaces> modelComponents;
    std::vector<std::int32_t> modelComponentOf;
    // The model's component face f came from; -1: none (no model index, or a face made since,
    // a tunnel's cap).
    std::int32_t modelComponentOfFace(const typename MeshType::FaceType* f) const
    {
        const std::size_t i = std::size_t(f - faceBase);
        return i < modelComponentOf.size() ? modelComponentOf[i] : -1;
    }
    // The model's components this session removed whole: gone for its own later removals at
    // once, for every piece's from the next level on (CollapseBuckets::collapse), so that
    // the pieces' sessions do not depend on the order they run in.
    std::vector<std::int32_t> modelComponentsRemoved;
    int& ringChanged(const VertexType* v) { return ringChangedAt[v - vertexBase]; }
    const VertexType* vertexBase = nullptr;
    // Collapses about to run are checked against the input surface (input_surface.h): one
    // that turns a face away from it is ranked at facingPenalty times its error, as a feature
    // break is (0: refused). Null: no check. It gives way in the far field, once the mesh is
    // down to farFieldFloor faces.
    std::shared_ptr<InputSurface> surface;
    int farFieldFloor = 0;  // the live faces where the far field starts
    // Once started (far_field.h), every operation is ranked by the largest distance it opens
    // (farFieldPriority). Null: the session never reaches the far field.
    std::shared_ptr<FarFieldDistances<MeshType>> farField;
    // A session held to a distance (an LOD chain's level, drawn on the strength of it)
    // measures the faces a collapse makes back to this input surface (farFieldDistance).
    // Null: toward a face target, where only the new vertex is measured back, to `surface`.
    std::shared_ptr<InputSurface> farFieldSurface;
    bool inFarField() const { return farField && farField->started(); }
    // The priority of an operation in the far field: the distance it opens, squared, in
    // diagonals.
    double farFieldPriority(double distance) const { return distance * distance / (diagonal * diagonal); }
    bool heldToDistance() const { return inFarField() && maxDistance > 0; }
    // The smooth-join guard (keepSmoothJoins) is one of the shape guards: in force while they
    // are, and only where the compactness guard is.
    bool keepsSmoothJoins() const
    {
        return cosSmoothJoin >= -1.0 && shapeGuards && !heldToDistance() && params.minCompactness > 0;
    }
    // Before the far field, with the input's points dealt: ranked by the quadrics, but held
    // to maxDistance by the distance each collapse opens too.
    bool checksDistance() const { return farField && farField->dealt() && !farField->started() && maxDistance > 0; }
    // Whether an operation of this error, opening this distance, is beyond the session's
    // bound: the distance where it is held to one, else the error.
    bool exceedsBound(double error, double distance) const
    {
        if (heldToDistance())
            return distance > maxDistance;
        if (checksDistance() && distance > maxDistance)
            return true;
        return maxErrorAbs > 0 && error > maxErrorAbs;
    }
    // An executed operation's error, or its distance where it is held to one (the bound it
    // was checked against, which an LOD chain learns from).
    void recordError(double error, double distance)
    {
        if (heldToDistance())
            largestDistance = std::max(largestDistance, distance);
        else
            largestError = std::max(largestError, error);
        if (checksDistance())
            largestDistance = std::max(largestDistance, distance);
    }
    double facingPenalty = 0.0;
    bool facingGaveWay = false;      // a collapse ran unchecked below farFieldFloor
    const int* faceCount = nullptr;  // the mesh's live faces (m.fn)
    // Where executed collapses count what they delete: the mesh's own counts (m.fn, m.vn),
    // or a session's own when two sessions collapse the halves of one mesh at once.
    int* faceCounter = nullptr;
    int* vertexCounter = nullptr;
    const typename MeshType::FaceType* faceBase = nullptr;
    // Deleted elements reserved for tunnel cuts (tunnel_cut.h); empty: no cuts.
    std::vector<VertexType*> spareVertices;
    std::vector<typename MeshType::FaceType*> spareFaces;
    // Per face index, the mark of the last walk that reached the face (a tunnel cut's walk
    // over both sides of its loop, tunnel_cut.h), sized on the first walk.
    std::vector<std::uint32_t> walkMark;
    std::uint32_t walkClock = 0;
    // Two marks no face holds yet, one for each side of a walk.
    std::pair<std::uint32_t, std::uint32_t> newWalkMarks()
    {
        if (walkMark.size() != inputNormal.size() || walkClock > std::numeric_limits<std::uint32_t>::max() - 2) {
            walkMark.assign(inputNormal.size(), 0);
            walkClock = 0;
        }
        walkClock += 2;
        return {walkClock - 1, walkClock};
    }

    // Faces keep their identity through collapses (only a vertex is replaced), so the input
    // normal bounds the rotation a face accumulates over many collapses.
    void storeInputNormals(MeshType& m)
    {
        faceBase = m.face.empty() ? nullptr : &m.face[0];
        inputNormal.assign(m.face.size(), vcg::Point3f(0, 0, 0));
        for (std::size_t i = 0; i < m.face.size(); ++i) {
            const auto& f = m.face[i];
            if (f.IsD())
                continue;
            vcg::Point3d n = (vcg::Point3d::Construct(f.cP(1)) - vcg::Point3d::Construct(f.cP(0))) ^
                             (vcg::Point3d::Construct(f.cP(2)) - vcg::Point3d::Construct(f.cP(0)));
            const double len = n.Norm();
            if (len > 0 && std::isfinite(len))
                inputNormal[i] = vcg::Point3f::Construct(n / len);
        }
    }

    // Priority of an operation: its quadric cost (the weighted sum of squared distances to
    // the merged planes, not their mean: a vertex that stands for many planes weighs more),
    // plus a rounding floor that keeps collapses costing nothing ordered (smallest merged
    // weight, best shape first) instead of tied at ~0. `shape` in (0, 1]: 1 for well-shaped
    // results. Both terms are normalised by the bbox diagonal, so the order is scale-free.
    double priority(double cost, double area, double shape) const
    {
        const double diag2 = diagonal * diagonal;
        return (cost / diag2 + roundingError2 * area / (diag2 * shape)) / diag2;
    }

    // No face has changed yet.
    void clearRingChanges(MeshType& m)
    {
        vertexBase = m.vert.empty() ? nullptr : &m.vert[0];
        ringChangedAt.assign(m.vert.size(), std::numeric_limits<int>::min());
    }
};

// Cheapest point of a quadric, when its matrix is well conditioned (scale-free test).
inline bool quadricMinimum(const Quadric& q, vcg::Point3d& x)
{
    const double a = q.a[0], b = q.a[1], c = q.a[2], d = q.a[3], e = q.a[4], f = q.a[5];
    const double c00 = d * f - e * e, c01 = c * e - b * f, c02 = b * e - c * d;
    const double det = a * c00 + b * c01 + c * c02;
    const double norm = std::sqrt(a * a + d * d + f * f + 2 * (b * b + c * c + e * e));
    if (!(norm > 0) || std::abs(det) < 1e-6 * norm * norm * norm)
        return false;
    const double c11 = a * f - c * c, c12 = b * c - a * e, c22 = a * d - b * b;
    const double rx = -0.5 * q.b[0], ry = -0.5 * q.b[1], rz = -0.5 * q.b[2];
    x = vcg::Point3d(c00 * rx + c01 * ry + c02 * rz, c01 * rx + c11 * ry + c12 * rz,
                     c02 * rx + c12 * ry + c22 * rz) / det;
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

// The minimum of q(x) + eps |x - m|^2, eps a small share of q's trace: the quadric's
// optimum where it is well determined, and the point nearest m along the directions where
// it is flat. On a cylinder's strips or along a crease the planes meet in a line, so the
// plain optimum does not exist (quadricMinimum refuses it), but the best placement near
// the edge still lies off the edge, on that line.
inline bool nearestMinimum(const Quadric& q, const vcg::Point3d& m, vcg::Point3d& x)
{
    constexpr double kPullToM = 1e-3;
    const double eps = kPullToM * (q.a[0] + q.a[3] + q.a[5]);
    if (!(eps > 0))
        return false;
    Quadric pulled = q;
    pulled.a[0] += eps;
    pulled.a[3] += eps;
    pulled.a[5] += eps;
    for (int i = 0; i < 3; ++i)
        pulled.b[i] -= 2.0 * eps * m[i];
    return quadricMinimum(pulled, x);
}

// Whether x lies beside the segment p0 -> p1: between its ends, off it by at most a tenth
// of its length (a chord's sag is a few hundredths of it). A minimum along a line could
// otherwise slide far along a crease or an axis, where the quadric sees no cost but the
// faces around stretch past the end of the crease.
inline bool besideTheEdge(const vcg::Point3d& x, const vcg::Point3d& p0, const vcg::Point3d& p1)
{
    const vcg::Point3d e = p1 - p0;
    const double length2 = e.SquaredNorm();
    if (!(length2 > 0))
        return false;
    const double t = ((x - p0) * e) / length2;
    const double off2 = (x - (p0 + e * t)).SquaredNorm();
    return t >= 0.0 && t <= 1.0 && off2 <= length2 / 100.0;
}

// The quadric's own placement for the edge p0 -> p1: its optimum where the planes meet in a
// point, near the edge; where they meet in a line (a cylinder's strips, a crease), the
// point of that line nearest the edge's middle, beside the edge.
inline bool quadricPlacement(const Quadric& q, const vcg::Point3d& p0, const vcg::Point3d& p1, vcg::Point3d& x)
{
    const vcg::Point3d middle = (p0 + p1) * 0.5;
    if (quadricMinimum(q, x))
        return vcg::Distance(x, middle) <= vcg::Distance(p0, p1);
    return nearestMinimum(q, middle, x) && besideTheEdge(x, p0, p1);
}

inline double applyQuadric(const Quadric& q, const vcg::Point3d& p)
{
    return std::max(0.0, q.Apply(p));
}

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

    static void* operator new(std::size_t size) { return EntryPool::allocate(size); }
    static void operator delete(void* p, std::size_t size) { EntryPool::deallocate(p, size); }

    CadEdgeCollapse(const VertexPair& p, int mark, vcg::BaseParameterClass* pp)
    {
        this->localMark = mark;
        this->pos = p;
        this->_priority = lowerBound(*static_cast<Context*>(pp));
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
        if (ctx.params.preserveTopology && !topologyGivesWay(ctx) && !joinsBoundary_ &&
            !(vcg::tri::EdgeCollapser<MeshType, VertexPair>::LinkConditions(this->pos) &&
              !makesNonManifoldEdge(this->pos.V(0), this->pos.V(1))) &&
            !(ctx.inFarField() && foldsTetrahedron(this->pos.V(0), this->pos.V(1)))) {
            if (ctx.joinBoundaries && joinsBoundaryOnly(this->pos.V(0), this->pos.V(1)))
                return priceJoiningBoundary(ctx);
            ++ctx.stats->rejectedTopology;
            TunnelCut<MeshType>::offer(ctx, this->pos.V(0), this->pos.V(1));
            return false;
        }
        if (ctx.checksDistance() && !opensWithinBound(ctx)) {
            ++ctx.stats->rejectedError;
            return false;
        }
        if (ctx.surface && !turnsAway_ && !free_) {
            if (*ctx.faceCount <= ctx.farFieldFloor)
                ctx.facingGaveWay = true;
            else if (!newFacesFaceTheInput(ctx))
                return offEdge_ ? retryOnTheEdge(ctx) : priceTurningAway(ctx);
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

    // A collapse that closes a hole or joins boundary runs (link_condition.h) changes the
    // topology where the viewer sees a surface closed a little early: ranked like a feature
    // break, so that it runs when it is cheaper than what else is left.
    bool priceJoiningBoundary(Context& ctx)
    {
        joinsBoundary_ = true;
        this->_priority *= ScalarType(std::max(1.0, ctx.params.featurePenalty));
        return stillFirst(ctx);
    }

    // The collapse would turn a face away from the input surface: refused, or ranked at
    // facingPenalty times its priority (back into the heap when that is no longer the top).
    bool priceTurningAway(Context& ctx)
    {
        if (ctx.facingPenalty <= 0) {
            ++ctx.stats->rejectedFlip;
            return false;
        }
        turnsAway_ = true;
        this->_priority *= ScalarType(ctx.facingPenalty);
        return stillFirst(ctx);
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
        gatherRing(ctx, v0, v1);
        // Held to the bound and recorded into the session's largest distance only, a
        // distance need not be told apart below the largest the session has opened (or the
        // bound, where a level's bound is below an earlier one's).
        std::uint32_t farthest = FarFieldDistances<MeshType>::kNoPoint;
        distance_ = farFieldDistance(ctx, v0, v1, vcg::Point3d::Construct(target_), ctx.maxDistance * (1 + 1e-9),
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

    // What the faces around the edge say: surviving faces into ctx.ring, whether the
    // endpoints and the edge lie on features, the worst compactness of all of them.
    struct Neighbourhood {
        bool v0OnFeature = false, v1OnFeature = false, edgeIsFeature = false;
        bool v0Corner = false, v1Corner = false;  // on other than exactly two feature edges
        double worstCompactness = 1.0;
        int slivers = 0;  // faces below kSliver, the two the collapse removes included
        bool removesSliver = false;  // a face it removes is a sliver and the edge is its shortest
    };

    Neighbourhood gatherRing(Context& ctx, VertexType* v0, VertexType* v1)
    {
        Neighbourhood n;
        ctx.ring.clear();
        for (int side = 0; side < 2; ++side) {
            VertexType* v = side == 0 ? v0 : v1;
            VertexType* other = side == 0 ? v1 : v0;
            bool onFeature = false;
            VertexType* featureEnds[2] = {nullptr, nullptr};
            bool corner = false;
            auto addFeatureEnd = [&](VertexType* x) {
                if (x == featureEnds[0] || x == featureEnds[1])
                    return;
                if (!featureEnds[0])
                    featureEnds[0] = x;
                else if (!featureEnds[1])
                    featureEnds[1] = x;
                else
                    corner = true;  // a third feature edge
            };
            for (VFIterator vfi(v); !vfi.End(); ++vfi) {
                FaceType* f = vfi.F();
                const int z = vfi.I();
                VertexType* a = f->V((z + 1) % 3);
                VertexType* b = f->V((z + 2) % 3);
                const bool featureA = f->IsUserBit(ctx.bits.edge[z]);
                const bool featureB = f->IsUserBit(ctx.bits.edge[(z + 2) % 3]);
                onFeature |= featureA || featureB;
                if (featureA)
                    addFeatureEnd(a);
                if (featureB)
                    addFeatureEnd(b);
                if (a == other || b == other) {
                    n.edgeIsFeature |= a == other ? featureA : featureB;
                    if (side == 0) {  // shared faces are seen from both sides
                        const double c = compactness(f->cP(0), f->cP(1), f->cP(2));
                        n.worstCompactness = std::min(n.worstCompactness, c);
                        n.slivers += c < kSliver;
                        n.removesSliver |= c < kSliver && isShortestEdge(*f, z, a == other ? (z + 1) % 3 : (z + 2) % 3);
                    }
                } else {
                    const vcg::Point3d pa = vcg::Point3d::Construct(a->cP());
                    const vcg::Point3d pb = vcg::Point3d::Construct(b->cP());
                    const vcg::Point3d pv = vcg::Point3d::Construct(v->cP());
                    const vcg::Point3d normal = (pa - pv) ^ (pb - pv);
                    RingFace face{pa, pb, normal, normal.Norm(),
                                  vcg::Point3d::Construct(ctx.inputNormal[f - ctx.faceBase]),
                                  (pb - pa).SquaredNorm()};
                    if (ctx.keepsSmoothJoins()) {
                        faceBeyond(f, a, b, v0, v1, face);
                        face.side = side;
                    }
                    const double edges = (pa - pv).SquaredNorm() + (pb - pv).SquaredNorm() + face.abSquared;
                    const double c = compactnessFrom(face.normalLength, edges);
                    n.worstCompactness = std::min(n.worstCompactness, c);
                    n.slivers += c < kSliver;
                    ctx.ring.push_back(face);
                }
            }
            (side == 0 ? n.v0OnFeature : n.v1OnFeature) = onFeature;
            (side == 0 ? n.v0Corner : n.v1Corner) = onFeature && (corner || !featureEnds[1]);
        }
        return n;
    }

    // How much of the ring changes shade with the new vertex at p: the sum, over the faces
    // turned more than the shading angle from the face they were in the input, of area ×
    // (1 − cos of the turn). Turns below the angle (a crease sliding along a fillet, a facet
    // of a fine cylinder) are not counted: pricing those costs Hausdorff and slivers at 50 %
    // for no shading a viewer sees.
    static double shadedArea(const Context& ctx, const vcg::Point3d& p)
    {
        double sum = 0.0;
        for (const RingFace& f : ctx.ring) {
            const vcg::Point3d n = (f.a - p) ^ (f.b - p);  // twice the area, along the normal
            const double doubleArea = n.Norm();
            const double along = n * f.original;
            if (doubleArea > 0 && along < ctx.cosShadingAngle * doubleArea)
                sum += 0.5 * (doubleArea - along);
        }
        return sum;
    }

    // The compactness face f of the ring takes with the new vertex at p, or kTurned if the
    // normal checks refuse it (it turns too far, or away from the input surface). Too far is
    // the normal threshold, but a quarter turn in the far field of a session held to a
    // distance: there the distance alone judges a collapse, and closing a thin wall's rim
    // turns its faces further than the threshold lets a near level's do.
    static constexpr double kTurned = -1.0;
    static double faceAt(const Context& ctx, const RingFace& f, const vcg::Point3d& p)
    {
        const vcg::Point3d ua = f.a - p, ub = f.b - p;
        const vcg::Point3d n = ua ^ ub;
        const double doubleArea = n.Norm();
        if (ctx.params.normalCheck) {
            const double len = doubleArea * f.normalLength;
            const double cosLimit = ctx.heldToDistance() ? 0.0 : ctx.cosNormalLimit;
            if (f.normalLength > 0 && !(len > 0 && (n * f.normal) >= cosLimit * len))
                return kTurned;
            if (n * f.original < 0)
                return kTurned;  // turned away from the input surface
        }
        return compactnessFrom(doubleArea, ua.SquaredNorm() + ub.SquaredNorm() + f.abSquared);
    }

    // Mean compactness of the faces around the new vertex at p; invalid if one of them would
    // fall below `floor` or more than `maxSlivers` of them below kSliver, flipped if one turns
    // too far. `failed` is the ring face that made
    // the last candidate invalid (-1: none): most refused edges are refused by one face for
    // every candidate, so it is tried first. It is set to the face that fails this one.
    PlacementScore score(const Context& ctx, const vcg::Point3d& p, double floor, int& failed,
                         bool keepsSmoothJoins, int maxSlivers = std::numeric_limits<int>::max()) const
    {
        PlacementScore s;
        if (failed >= 0) {
            const double c = faceAt(ctx, ctx.ring[std::size_t(failed)], p);
            s.flipped = c == kTurned;
            if (c < floor)
                return s;
        }
        double sum = 0.0;
        int slivers = 0;
        for (std::size_t i = 0; i < ctx.ring.size(); ++i) {
            const double c = faceAt(ctx, ctx.ring[i], p);
            if (c < floor) {
                s.flipped = c == kTurned;
                failed = int(i);
                return s;
            }
            sum += c;
            slivers += c < kSliver;
        }
        if (slivers > maxSlivers)
            return s;
        if (keepsSmoothJoins && foldsSmoothJoin(ctx, p))
            return s;
        s.meanCompactness = sum / double(ctx.ring.size());
        s.valid = true;
        return s;
    }

    // The face across the outer edge a-b of ring face f, for the smooth-join guard.
    static void faceBeyond(const FaceType* f, VertexType* a, const VertexType* b,
                           const VertexType* v0, const VertexType* v1, RingFace& face)
    {
        for (VFIterator vfi(a); !vfi.End(); ++vfi) {
            const FaceType* g = vfi.F();
            if (g == f)
                continue;
            bool hasB = false, inRing = false;
            for (int k = 0; k < 3; ++k) {
                hasB |= g->cV(k) == b;
                inRing |= g->cV(k) == v0 || g->cV(k) == v1;
            }
            if (!hasB || inRing)
                continue;
            vcg::Point3d n = vcg::Point3d::Construct(vcg::TriangleNormal(*g));
            const double length = n.Norm();
            if (!(length > 0))
                return;
            face.beyond = n / length;
            return;
        }
    }

    // Whether a face around the new vertex at p folds past the crease angle
    // (ctx.cosSmoothJoin) against a neighbour, across a spoke or its outer edge, where the two
    // met below it before the collapse (or did not meet): the join would be drawn as a crease,
    // each side flat-shaded, where it was smooth. (Not the faces' input normals: a face that
    // has been through many collapses may lie far from where it was.)
    static bool foldsSmoothJoin(const Context& ctx, const vcg::Point3d& p)
    {
        const double limit = ctx.cosSmoothJoin;
        for (std::size_t i = 0; i < ctx.ring.size(); ++i) {
            const RingFace& f = ctx.ring[i];
            const vcg::Point3d nf = (f.a - p) ^ (f.b - p);
            const double lf = nf.Norm();
            if (!(lf > 0) || !(f.normalLength > 0))
                continue;
            const bool hasBeyond = f.beyond * f.beyond > 0;
            if (hasBeyond && (nf * f.beyond) < limit * lf && (f.normal * f.beyond) >= limit * f.normalLength)
                return true;  // folds against the face beyond its outer edge
            for (std::size_t j = i + 1; j < ctx.ring.size(); ++j) {
                const RingFace& g = ctx.ring[j];
                const bool shareSpoke = f.a == g.a || f.a == g.b || f.b == g.a || f.b == g.b;
                if (!shareSpoke || !(g.normalLength > 0))
                    continue;
                const vcg::Point3d ng = (g.a - p) ^ (g.b - p);
                const double lg = ng.Norm();
                const bool foldsNow = lg > 0 && (nf * ng) < limit * lf * lg;
                // Faces around different endpoints meet for the first time (across a removed
                // face): any fold between them is new.
                const bool smoothBefore =
                    f.side != g.side || (f.normal * g.normal) >= limit * f.normalLength * g.normalLength;
                if (foldsNow && smoothBefore)
                    return true;
            }
        }
        return false;
    }

    struct Candidate {
        vcg::Point3d p;
        double cost;      // quadric cost: the geometric error the placement makes
        bool breaks;      // moves a feature point off its feature (see evaluate)
        double ranked;    // the cost it is ordered by: cost, times the feature penalty if it breaks
        bool offEdge;     // a quadric minimum, not a point of the segment
    };
    static constexpr int kMaxCandidates = 32;
    static constexpr double kSliver = 0.1;  // compactness below which a face counts as a sliver

    // Both endpoints, evenly spaced interior points and, with `offEdgeMinima`, the quadric's
    // own placement (quadricPlacement), with their costs. A placement breaks a feature when
    // it moves a pinned endpoint, or puts a vertex that must stay on a boundary polyline (it
    // may take the other endpoint's place) between the two; evaluate() lets it off when it
    // costs no more than the flat floor (it lies on the feature already).
    static int candidates(const Context& ctx, const Quadric& q, const vcg::Point3d& p0, const vcg::Point3d& p1,
                          bool v0Pinned, bool v1Pinned, bool onBoundaryLine, bool offEdgeMinima, Candidate* cand)
    {
        int count = 0;
        const int interior = std::clamp(ctx.params.candidatesPerEdge, 0, kMaxCandidates - 4);
        const bool between = v0Pinned || v1Pinned || onBoundaryLine;
        cand[count++] = {p0, 0.0, v1Pinned, 0.0, false};
        cand[count++] = {p1, 0.0, v0Pinned, 0.0, false};
        for (int i = 1; i <= interior; ++i)
            cand[count++] = {p0 + (p1 - p0) * (double(i) / (interior + 1)), 0.0, between, 0.0, false};
        vcg::Point3d optimum(0, 0, 0);
        if (offEdgeMinima && ctx.params.optimalPlacement && quadricPlacement(q, p0, p1, optimum))
            cand[count++] = {optimum, 0.0, between, 0.0, true};
        for (int i = 0; i < count; ++i)
            cand[i].cost = applyQuadric(q, cand[i].p);
        return count;
    }

    static ScalarType priorityOf(const Context& ctx, double cost, double area, double shape)
    {
        return ScalarType(ctx.priority(cost, area, shape));
    }

    Quadric mergedQuadric(const Context& ctx) const
    {
        Quadric q = ctx.quadrics.quadric(this->pos.cV(0));
        q += ctx.quadrics.quadric(this->pos.cV(1));
        return q;
    }

    // Never above the priority evaluate() finds: the cheapest of all candidates (evaluate
    // may refuse some or rank them higher, never lower) and the best shape.
    ScalarType lowerBound(const Context& ctx)
    {
        VertexType* v0 = this->pos.V(0);
        VertexType* v1 = this->pos.V(1);
        if (v0->IsUserBit(ctx.bits.locked) || v1->IsUserBit(ctx.bits.locked))
            return std::numeric_limits<ScalarType>::max();
        if (ctx.inFarField())
            return 0;  // the distance it opens is found when it is evaluated
        const Quadric q = mergedQuadric(ctx);
        Candidate cand[kMaxCandidates];
        const int count = candidates(ctx, q, vcg::Point3d::Construct(v0->cP()), vcg::Point3d::Construct(v1->cP()),
                                     false, false, false, true, cand);
        double minCost = std::numeric_limits<double>::max();
        for (int i = 0; i < count; ++i)
            minCost = std::min(minCost, cand[i].cost);
        return priorityOf(ctx, minCost, ctx.quadrics.cappedArea(v0, v1), 1.0) *
               ScalarType(std::min(1.0, ctx.params.sliverFirstShare));
    }

    // The candidates a collapse may use, ranked. Features are not locks but prices: a
    // placement that breaks one (cuts across a crease, moves a corner or a boundary vertex
    // off its place) is ranked at featurePenalty times its quadric cost, which already holds
    // the feature's constraint planes. So a feature gives way only where every collapse that
    // keeps the features costs that many times more error: a board keeps its corners while
    // any small part can still lose a chamfer. featurePenalty 0 makes features hard locks.
    int rankedCandidates(const Context& ctx, const Quadric& q, const vcg::Point3d& p0, const vcg::Point3d& p1,
                         bool v0Pinned, bool v1Pinned, bool onBoundaryLine, bool crossesFeature, double flatFloor,
                         Candidate* cand) const
    {
        const double penalty = ctx.params.featurePenalty;
        int count = candidates(ctx, q, p0, p1, v0Pinned, v1Pinned, onBoundaryLine, !onTheEdgeOnly_, cand);
        int kept = 0;
        for (int i = 0; i < count; ++i) {
            Candidate c = cand[i];
            c.breaks = crossesFeature || (c.breaks && c.cost > flatFloor);
            if (c.breaks && penalty <= 0)
                continue;
            c.ranked = c.breaks ? c.cost * std::max(1.0, penalty) : c.cost;
            if (ctx.shadingScale > 0 && c.cost > flatFloor)
                c.ranked += ctx.shadingScale * shadedArea(ctx, c.p);
            cand[kept++] = c;
        }
        return kept;
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
        const Neighbourhood n = gatherRing(ctx, v0, v1);
        if (ctx.ring.empty())
            return reject(stats.rejectedTopology);  // would delete a whole component

        const Quadric q = mergedQuadric(ctx);
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
        const int count = rankedCandidates(ctx, q, vcg::Point3d::Construct(v0->cP()), vcg::Point3d::Construct(v1->cP()),
                                           v0Pinned, v1Pinned, onBoundaryLine, crosses, flatFloor, cand);
        if (count == 0)
            return reject(stats.rejectedFeature);
        double minRanked = std::numeric_limits<double>::max();
        for (int i = 0; i < count; ++i)
            minRanked = std::min(minRanked, cand[i].ranked);
        const double tieLimit = minRanked * (1.0 + ctx.params.tieTolerance) + area * ctx.roundingError2;

        // No new face below minCompactness, unless it is still better than the worst now.
        // A collapse that costs nothing must not make a sliver either: any later collapse
        // can do its work, and a sliver made for free is shape lost for nothing (the rings
        // shaft at half: 61 % -> 30 % slivers, stock 57 %). Both guards give way when the
        // simplifier relaxes its shape limits (simplify.h), and in the far field of a session
        // held to a distance (an LOD chain's level, drawn where the model is a few dozen pixels
        // high): its distance alone judges it there, and a thin wall around a cavity (a jack's
        // socket) keeps its opening with long faces across the rim. Near a face target
        // (ctx.countsSlivers) a collapse among slivers may not add to their number either: the
        // floor alone lets it make new ones as long as each beats the worst.
        const double minCompactness = ctx.shapeGuards && !ctx.heldToDistance() ? ctx.params.minCompactness : 0.0;
        const double floor = std::min(minCompactness, n.worstCompactness);
        const double minFree = minCompactness > 0 ? std::max(kSliver, minCompactness) : 0.0;
        const double freeFloor = std::min(minFree, n.worstCompactness);
        auto floorFor = [&](const Candidate& c) { return c.cost <= flatFloor ? freeFloor : floor; };
        const int maxSlivers =
            minCompactness > 0 && ctx.countsSlivers ? n.slivers : std::numeric_limits<int>::max();
        const bool keepJoins = ctx.keepsSmoothJoins();
        int best = -1;
        PlacementScore bestScore;
        bool anyFlip = false;
        int failed = -1;
        for (int i = 0; i < count; ++i) {
            if (cand[i].ranked > tieLimit)
                continue;
            const PlacementScore s = score(ctx, cand[i].p, floorFor(cand[i]), failed, keepJoins, maxSlivers);
            anyFlip |= s.flipped;
            if (s.valid && (best < 0 || s.meanCompactness > bestScore.meanCompactness ||
                            (s.meanCompactness == bestScore.meanCompactness && cand[i].ranked < cand[best].ranked))) {
                best = i;
                bestScore = s;
            }
        }
        if (best < 0)  // no tied candidate is acceptable: the cheapest acceptable one
            for (int i = 0; i < count; ++i) {
                if (cand[i].ranked <= tieLimit || (best >= 0 && cand[i].ranked >= cand[best].ranked))
                    continue;
                const PlacementScore s = score(ctx, cand[i].p, floorFor(cand[i]), failed, keepJoins, maxSlivers);
                anyFlip |= s.flipped;
                if (s.valid) {
                    best = i;
                    bestScore = s;
                }
            }
        if (best < 0)
            return reject(anyFlip ? stats.rejectedFlip : stats.rejectedCompactness);
        const FarFieldChoice farField =
            ctx.inFarField() ? farFieldPlacement(ctx, v0, v1, cand, count, area, floorFor, best, bestScore, failed)
                             : FarFieldChoice();
        distance_ = farField.opened;

        const double cost = cand[best].cost;
        target_ = vcg::Point3<ScalarType>::Construct(cand[best].p);
        error_ = float(area > 0 ? std::sqrt(cost / area) : std::sqrt(cost));
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
            this->_priority = priorityOf(ctx, cand[best].ranked, ctx.quadrics.cappedArea(v0, v1), shape);
            if (n.removesSliver)
                this->_priority *= ScalarType(ctx.params.sliverFirstShare);
        }
    }

    // Whether the edge of f from corner i to corner j is no longer than its other two.
    static bool isShortestEdge(const FaceType& f, int i, int j)
    {
        const int k = 3 - i - j;
        const double edge = (f.cP(i) - f.cP(j)).SquaredNorm();
        return edge <= (f.cP(i) - f.cP(k)).SquaredNorm() && edge <= (f.cP(j) - f.cP(k)).SquaredNorm();
    }

    // In the far field the placement is the valid candidate that opens the smallest distance
    // (far_field.h), its quadric error and, toward a face target, its swept volume beside
    // (kFarFieldMeanShare, kFarFieldSweptShare), not the one the quadrics and compactness
    // chose: with a few hundred faces left, a placement a few planes cheaper may still stand
    // off the input where another does not. A fold of a tetrahedron counts kFoldWidth times
    // the distance. `best` and `bestScore` follow the choice.
    struct FarFieldChoice {
        double ranked2 = 0.0;  // the squared distance it is ranked at, the terms beside included
        double opened = 0.0;   // the distance it opens
    };
    template <class FloorFor>
    FarFieldChoice farFieldPlacement(Context& ctx, VertexType* v0, VertexType* v1, const Candidate* cand, int count,
                             double area, const FloorFor& floorFor, int& best, PlacementScore& bestScore, int& failed)
    {
        const double fold = foldsTetrahedron(v0, v1) ? kFoldWidth : 1.0;
        // A session held to a distance (an LOD chain's level) is judged by that distance
        // alone, not by the outline the swept volume stands for (docs/benchmarks.md).
        const double sweptShare = ctx.heldToDistance() ? 0.0 : kFarFieldSweptShare;
        auto beside2 = [&](int i) {  // the terms beside the distance opened, squared
            const double swept = sweptShare > 0 ? sweptLength(ctx, cand[i].p) : 0.0;
            return kFarFieldMeanShare * (area > 0 ? cand[i].cost / area : cand[i].cost) + sweptShare * swept * swept;
        };
        std::uint32_t farthest = FarFieldDistances<MeshType>::kNoPoint;
        auto opened = [&](int i, double enough) {
            return fold * farFieldDistance(ctx, v0, v1, cand[i].p, enough / fold, farthest);
        };
        const double first = opened(best, std::numeric_limits<double>::max());
        double best2 = first * first + beside2(best);
        double bestOpened = first / fold;
        for (int i = 0; i < count; ++i) {
            const double m2 = beside2(i);
            if (i == best || m2 >= best2)
                continue;  // the terms beside the distance alone rank it no better
            const double d = opened(i, std::sqrt(best2 - m2));
            const double d2 = d * d + m2;
            if (d2 >= best2)
                continue;
            // The far field's distance alone ranks its shapes: no join is kept there.
            const PlacementScore s = score(ctx, cand[i].p, floorFor(cand[i]), failed, false);
            if (!s.valid)
                continue;
            best = i;
            bestScore = s;
            best2 = d2;
            bestOpened = d / fold;
        }
        return {best2, bestOpened};
    }

    // The edge of a cube of the volume the collapse to p sweeps: between each face of the
    // ring before the collapse and after it, the tetrahedron of the old face and p.
    static double sweptLength(const Context& ctx, const vcg::Point3d& p)
    {
        double sixVolumes = 0;
        for (const RingFace& f : ctx.ring)
            sixVolumes += std::abs(f.normal.dot(p - f.a));
        return std::cbrt(sixVolumes / 6.0);
    }

    // The largest distance the collapse to p opens (far_field.h): from the input's points
    // of the faces it changes to the faces it makes, and back to the input surface from the
    // faces it makes where the session is held to a distance (farFieldSurface), else from p;
    // once it reaches `enough`, the rest is not looked at (`farthest`: collapseError's);
    // below `atLeast` distances are not told apart, and that is the least returned.
    // Toward a face target, measuring the faces' points too ranks a little better but
    // makes a 99 % run much slower (docs/benchmarks.md).
    static double farFieldDistance(const Context& ctx, VertexType* v0, VertexType* v1, const vcg::Point3d& p,
                                   double enough, std::uint32_t& farthest, double atLeast = 0.0)
    {
        const double forward = ctx.farField->collapseError(v0, v1, p, ctx.ring, enough, farthest, atLeast);
        if (forward >= enough)
            return forward;
        if (ctx.farFieldSurface)
            return backFromNewFaces(*ctx.farFieldSurface, ctx.ring, p, forward, enough);
        return ctx.surface ? std::max(forward, ctx.surface->distance(p)) : forward;
    }

    // The largest distance from p and the faces (p, a, b) of `ring` to the input surface, as
    // far as p, the faces' centroids and the midpoints of their edges from p tell, or `known`
    // where that is larger; from `enough` on, the rest is not looked at. A face that bridges
    // a gap (a socket's mouth, a groove) stands off the input in its middle, though its
    // corners lie on it: p alone said nothing of that, and a chain level measured twice the
    // distance its collapses had been held to (docs/benchmarks.md).
    static double backFromNewFaces(const InputSurface& surface, const std::vector<RingFace>& ring,
                                   const vcg::Point3d& p, double known, double enough)
    {
        InputSurface::RecentFaces recent;
        double largest = std::max(known, surface.distanceBeyond(p, known, recent));
        for (const RingFace& f : ring) {
            for (const vcg::Point3d& q : {(p + f.a + f.b) / 3.0, (p + f.a) / 2.0, (p + f.b) / 2.0}) {
                if (largest >= enough)
                    return largest;
                largest = std::max(largest, surface.distanceBeyond(q, largest, recent));
            }
        }
        return largest;
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
