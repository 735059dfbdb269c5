// The simplification session behind simplify() (simplify.h): it prepares the mesh (features,
// quadrics, the input's normals and surface), runs the collapses to the target with the
// relaxation ladder, and gives the mesh back. Included where simplify() is compiled for a mesh
// type, and by tests of the session's internals.
#pragma once

#include "simplify/simplify.h"

#include "simplify/cad_edge_collapse.h"
#include "simplify/collapse_halves.h"
#include "simplify/collapse_heap.h"
#include "simplify/component_removal.h"
#include "mesh/layer_metadata.h"
#include "simplify/non_manifold_split.h"
#include "simplify/simplify_params.h"
#include "simplify/tunnel_cut.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>
#include <string>

namespace cadlod {

// The input points an error-bounded session keeps for the far field (an LOD chain's
// piece): its levels are measured against level 0 independently, and the ratio of that
// measure to the distances opened steers the budgets (lod_chain.h), so a sample serves.
inline constexpr std::size_t kBoundFarFieldPoints = 100000;

// ...and the spacing of the points it adds along the input's edges, in diagonals
// (far_field.h's forEachInputPoint).
inline constexpr double kBoundFarFieldEdgeSpacing = 0.005;

namespace detail {

inline bool validateParams(const SimplifyParams& p, std::string& why)
{
    if (p.targetFaces <= 0 && p.reductionPerc <= 0 && p.maxError <= 0)
        why = "no stop criterion: set a target face count, a reduction percentage or a maximum error";
    else if (p.reductionPerc > 100 || p.targetFaces < 0 || p.maxError < 0)
        why = "reduction must be 0..100 %, target faces and max error not negative";
    else if (!(p.featureAngle >= 0 && p.featureAngle <= 180) || !(p.normalThreshold > 0 && p.normalThreshold <= 180))
        why = "feature angle must be 0..180 degrees, normal threshold 0..180 degrees";
    else if (p.tieTolerance < 0 || p.flatTolerance < 0 || p.boundaryWeight < 0 || p.minCompactness < 0 ||
             p.largeFaceWeight < 0 || p.shadingWeight < 0)
        why = "tolerances, boundary weight, minimum compactness, large-face and shading weights must not be negative";
    else if (!(p.shadingAngle >= 0 && p.shadingAngle <= 180))
        why = "shading angle must be 0..180 degrees";
    else
        return true;
    return false;
}

// Bbox diagonal of the vertices used by live faces; vertices with non-finite coordinates
// are locked and left out.
template <class MeshType>
double usedDiagonal(MeshType& m, int lockedBit)
{
    vcg::Box3d box;
    for (auto& f : m.face) {
        if (f.IsD())
            continue;
        for (int j = 0; j < 3; ++j) {
            const auto& p = f.cP(j);
            if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))
                box.Add(vcg::Point3d::Construct(p));
            else
                f.V(j)->SetUserBit(lockedBit);
        }
    }
    return box.IsNull() ? 0.0 : box.Diag();
}

// The distance from the origin to the farthest finite vertex of a face: float coordinates
// resolve about FLT_EPSILON of it, whatever the size of the part.
template <class MeshType>
double coordinateReach(const MeshType& m)
{
    double reach2 = 0.0;
    for (const auto& f : m.face)
        for (int j = 0; j < 3 && !f.IsD(); ++j) {
            const vcg::Point3d p = vcg::Point3d::Construct(f.cP(j));
            if (std::isfinite(p.SquaredNorm()))
                reach2 = std::max(reach2, p.SquaredNorm());
        }
    return std::sqrt(reach2);
}

// The same diagonal, leaving the mesh as it is.
template <class MeshType>
double finiteFaceDiagonal(const MeshType& m)
{
    vcg::Box3d box;
    for (const auto& f : m.face)
        for (int j = 0; j < 3 && !f.IsD(); ++j) {
            const auto& p = f.cP(j);
            if (std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]))
                box.Add(vcg::Point3d::Construct(p));
        }
    return box.IsNull() ? 0.0 : box.Diag();
}

// vcglib's way to restrict a collapse to a selection: vertices not surrounded by selected
// faces are made read-only. Returns them, to make them writable again afterwards.
template <class MeshType>
std::vector<typename MeshType::VertexType*> freezeUnselected(MeshType& m)
{
    std::vector<typename MeshType::VertexType*> frozen;
    vcg::tri::UpdateSelection<MeshType>::VertexFromFaceStrict(m);
    for (auto& v : m.vert)
        if (!v.IsD() && !v.IsS() && v.IsW()) {
            v.ClearW();
            frozen.push_back(&v);
        }
    return frozen;
}

// Faces that repeat a vertex (welding rounded coordinates makes them) have no area and no
// edge of their own: deleting them closes nothing and opens nothing, whereas keeping them
// would lock their vertices. Returns how many were deleted.
template <class MeshType>
int deleteFacesRepeatingAVertex(MeshType& m)
{
    int deleted = 0;
    for (auto& f : m.face)
        if (!f.IsD() && repeatsVertex(f)) {
            vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
            ++deleted;
        }
    return deleted;
}

// Face colours mark materials when there are few of them (an import's part and face
// colours); a mesh painted with a measure has thousands, and its colour borders mean nothing.
constexpr std::size_t kMaxMaterialColors = 256;

template <class MeshType>
bool faceColorsAreMaterials(const MeshType& m)
{
    if (!vcg::tri::HasPerFaceColor(m))
        return false;
    std::set<std::uint32_t> colors;
    for (const auto& f : m.face) {
        if (f.IsD())
            continue;
        const vcg::Color4b c = f.cC();
        colors.insert(std::uint32_t(c[0]) << 24 | std::uint32_t(c[1]) << 16 | std::uint32_t(c[2]) << 8 | c[3]);
        if (colors.size() > kMaxMaterialColors)
            return false;
    }
    return colors.size() > 1;
}

}  // namespace detail

template <class MeshType>
bool simplifierRequirementsMet(const MeshType& m)
{
    return vcg::tri::HasPerVertexVFAdjacency(m) && vcg::tri::HasPerFaceVFAdjacency(m) &&
           vcg::tri::HasPerVertexMark(m);
}

// The bit flags a simplification needs, taken from vcglib's per-type pool once for the
// process and kept: that pool is a stack, to be taken from and given back in order by one
// thread, and simplifications run at once on several threads (an assembly's parts). Each
// marks only its own mesh, so all share the one set.
template <class MeshType>
const FeatureBits& featureBits()
{
    static const FeatureBits bits = [] {
        FeatureBits taken;
        for (int j = 0; j < 3; ++j)
            taken.edge[j] = MeshType::FaceType::NewBitFlag();
        taken.locked = MeshType::VertexType::NewBitFlag();
        taken.boundary = MeshType::VertexType::NewBitFlag();
        return taken;
    }();
    return bits;
}

// Sets up a simplification of `m`: feature and boundary marks, quadrics, input normals,
// the bit flags they need (featureBits). False if the mesh has no
// extent (stats.diagonal 0). `modelDiagonal` > 0: `m` is a piece of a model that size,
// whose priorities and logged sizes it must share. Every prepareCollapse needs a
// releaseCollapse, which gives back bit flags of its own.
template <class MeshType>
bool prepareCollapse(MeshType& m, const SimplifyParams& params, CollapseContext<MeshType>& ctx, SimplifyStats& stats,
                     double modelDiagonal = 0.0)
{
    using FaceType = typename MeshType::FaceType;
    using VertexType = typename MeshType::VertexType;
    ctx.params = params;
    ctx.stats = &stats;
    ctx.bits = featureBits<MeshType>();
    ctx.mark = 0;
    for (VertexType& v : m.vert) {
        v.ClearUserBit(ctx.bits.locked);
        v.ClearUserBit(ctx.bits.boundary);
        ctx.mark = std::max(ctx.mark, v.cIMark());  // marks of an earlier session on `m` stay in the past
    }

    stats.diagonal = detail::usedDiagonal(m, ctx.bits.locked);
    if (modelDiagonal > 0)
        stats.diagonal = modelDiagonal;
    if (!(stats.diagonal > 0))
        return false;
    ctx.diagonal = stats.diagonal;
    ctx.flatError2 = std::pow(params.flatTolerance * ctx.diagonal, 2);
    ctx.roundingError2 = std::pow(kRoundingOfFloat * std::max(ctx.diagonal, detail::coordinateReach(m)), 2);
    ctx.maxErrorAbs = params.maxError * ctx.diagonal;
    ctx.cosNormalLimit = std::cos(params.normalThreshold * M_PI / 180.0);
    ctx.cosShadingAngle = std::cos(params.shadingAngle * M_PI / 180.0);
    ctx.cosSmoothJoin = params.keepSmoothJoins ? std::cos(CreaseFans::kCreaseDegrees * M_PI / 180.0) : -2.0;
    ctx.shadingScale = params.shadingWeight * ctx.diagonal * ctx.diagonal;

    stats.degenerateFaces = detail::deleteFacesRepeatingAVertex(m);
    vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    if (params.closeTunnels && params.preserveTopology)
        reserveTunnelCuts(m, ctx);  // adds elements: before any pointer into m is kept
    // Part and material (colour) borders are features: a face's surface key is its part id
    // and its colour.
    const bool parts = params.keepPartBorders && vcg::tri::HasPerFaceAttribute(m, kPartAttribute);
    const bool colors = params.keepColorBorders && detail::faceColorsAreMaterials(m);
    typename MeshType::template PerFaceAttributeHandle<int> partHandle;
    if (parts)
        partHandle = facePartHandle(m);
    auto surfaceOf = [&](FaceType& f) -> std::uint64_t {
        std::uint64_t key = parts ? std::uint32_t(partHandle[f]) : 0u;
        if (colors) {
            const vcg::Color4b c = f.cC();
            key = key << 32 | (std::uint32_t(c[0]) << 24 | std::uint32_t(c[1]) << 16 | std::uint32_t(c[2]) << 8 | c[3]);
        }
        return key;
    };
    const FeatureEdgeCounts features =
        markFeatureEdges(m, ctx.bits, params.featureAngle, params.preserveBoundary, surfaceOf);
    stats.featureEdges = features.feature;
    stats.boundaryEdges = features.boundary;
    stats.nonManifoldEdges = features.nonManifold;

    QuadricWeights weights;
    weights.feature = params.boundaryWeight;
    weights.planar = params.planarQuadric ? 1e-3 : 0.0;
    weights.areaShare = params.largeFaceWeight;
    ctx.quadrics.init(m, weights, [&](FaceType& f, int j) { return f.IsUserBit(ctx.bits.edge[j]); });
    ctx.storeInputNormals(m);
    ctx.farFieldFloor = farFieldFloor(m.fn);
    ctx.countsSlivers = stats.targetFaces > 0 && stats.targetFaces >= params.sliverCountShare * m.fn;
    if (params.normalCheck && params.facingCheck) {
        ctx.surface = std::make_shared<InputSurface>(m, ctx.diagonal);
        ctx.facingPenalty = facingPenaltyOf(params);
        ctx.faceCount = &m.fn;
    }
    // A face target in the far field, or a bounded session its caller takes into it
    // (params.farFieldWithinBound): the input's points are kept for it (far_field.h).
    if ((stats.targetFaces > 0 && stats.targetFaces < ctx.farFieldFloor) || params.farFieldWithinBound)
        ctx.farField = std::make_shared<FarFieldDistances<MeshType>>(
            m, params.farFieldWithinBound ? kBoundFarFieldPoints : std::size_t(0),
            params.farFieldWithinBound ? kBoundFarFieldEdgeSpacing * ctx.diagonal : 0.0);
    if (params.farFieldWithinBound)
        ctx.farFieldSurface = ctx.surface ? ctx.surface : std::make_shared<InputSurface>(m, ctx.diagonal);
    ctx.clearRingChanges(m);
    ctx.faceCounter = &m.fn;
    ctx.vertexCounter = &m.vn;
    return true;
}

template <class MeshType>
void releaseCollapse(MeshType& m, CollapseContext<MeshType>& ctx)
{
    using FaceType = typename MeshType::FaceType;
    using VertexType = typename MeshType::VertexType;
    for (FaceType& f : m.face)
        for (int j = 0; j < 3; ++j)
            f.ClearUserBit(ctx.bits.edge[j]);
    for (VertexType& v : m.vert) {
        v.ClearUserBit(ctx.bits.locked);
        v.ClearUserBit(ctx.bits.boundary);
    }
}

namespace detail {

// The relaxation ladder's second step (collapseToTarget); false when it was taken already.
template <class MeshType>
bool relaxShapeGuards(MeshType& m, CollapseContext<MeshType>& ctx, SimplifyStats& stats)
{
    if (ctx.shapeGuards && ctx.params.minCompactness > 0) {
        ctx.shapeGuards = false;
        stats.relaxed.push_back("shape guards relaxed at " + std::to_string(m.fn) +
                                " faces: triangles less compact than " + std::to_string(ctx.params.minCompactness) +
                                " allowed");
        return true;
    }
    return false;
}

// One run of the heap until the session's goal, as vcglib's DoOptimization does it (the
// same pops, the same dropping of stale entries once the heap outgrows the mesh), but
// ending where that dropping leaves the heap empty: vcglib then pops from the empty heap
// (read before its start), which a far-field session whose last entries were all stale
// reached (the LOD chain of a KUKA robot). Returns whether entries are left.
template <class MeshType>
bool runHeap(vcg::LocalOptimization<MeshType>& session)
{
    session.nPerformedOps = 0;
    return heapRun(
        session.h, session.m, session.pp, session.nPerformedOps, [&] { return !session.GoalReached(); },
        [&] { return std::size_t(session.m.SimplexNumber() * session.HeapSimplexRatio); });
}

}  // namespace detail

// The collapses themselves, on a prepared context, until stats.targetFaces or until no
// collapse is left. When the face target is not met with the limits of the first pass,
// they give way in this order (relaxToReachTarget), each step logged in stats.relaxed:
//   1. features are never locks in the first place: collapses that break one are ranked
//      at featurePenalty times their error (cad_edge_collapse.h), and so is removing a
//      small component whole (component_removal.h): they run when they are cheaper;
//      so is a collapse that turns a face away from the input surface near it
//      (input_surface.h), which a viewer sees lit as the wrong side, at facingPenalty
//      (by default kFacingOverFeature times that penalty); in the far field (the mesh
//      down to kFacingFarField of its faces) that check gives way, and toward a face target every operation is ranked by
//      the largest distance it opens instead (far_field.h), both logged; and so is
//      cutting a tunnel whose rim has shrunk to three edges, where the link condition
//      refuses every collapse (tunnel_cut.h), logged; and so is a collapse the link
//      condition refuses that keeps every edge manifold: it closes a hole or joins
//      boundary runs (link_condition.h), logged;
//   2. the shape guards (minCompactness, no free slivers).
// Flips of a face against itself (cad_edge_collapse.h's normal checks), the link condition
// where a collapse would leave an edge with more than two faces (only a priced cut does,
// and in the far field the fold of a tetrahedron into a fin, far_field.h) and locked
// (non-manifold) vertices never give way.
template <class MeshType>
void collapseToTarget(MeshType& m, CollapseContext<MeshType>& ctx, SimplifyStats& stats, vcg::CallBackPos* progress)
{
    using Collapse = CadEdgeCollapse<MeshType>;
    vcg::LocalOptimization<MeshType> session(m, &ctx);
    ctx.heap = &session.h;
    // Components are removed whole when that is cheaper, toward a face target or within a
    // maximum error; the shape guards relax only toward a face target.
    const bool faceTarget = ctx.params.relaxToReachTarget && stats.targetFaces > 0;
    const bool removals = ctx.params.relaxToReachTarget && (stats.targetFaces > 0 || ctx.maxErrorAbs > 0);
    ctx.joinBoundaries = faceTarget;
    auto fillHeap = [&] {
        session.template Init<Collapse>();
        if (removals)
            ComponentRemoval<MeshType>::push(m, ctx, session.h);
        heapMake(session.h);
    };
    fillHeap();
    // A session bound for the far field first runs down to where it starts (far_field.h).
    const bool farFieldAhead = ctx.farField && !ctx.farField->started() && stats.targetFaces > 0;
    if (stats.targetFaces > 0)
        session.SetTargetSimplices(farFieldAhead ? std::max(stats.targetFaces, ctx.farFieldFloor) : stats.targetFaces);
    // Progress counts from the faces the simplification started with (a first phase,
    // collapse_halves.h, may have made part of the removal).
    const int toRemove = std::max(1, std::max(m.fn, stats.facesBefore) - stats.targetFaces);
    // Return now and then to report progress: after a number of collapses, not a time
    // budget (vcglib reads the process CPU clock, a system call, on every heap pop).
    session.SetTargetOperations(std::max(1000, toRemove / 100));
    int collapsesSinceInit = 0;
    const int tunnelsBefore = stats.closedTunnels;
    while (m.fn > stats.targetFaces) {
        if (farFieldAhead && !ctx.farField->started() && m.fn <= ctx.farFieldFloor) {
            ctx.farField->start(m);
            stats.relaxed.push_back("far field from " + std::to_string(m.fn) +
                                    " faces: collapses and removals ranked by the largest distance they open");
            session.SetTargetSimplices(stats.targetFaces);
            collapsesSinceInit = 0;
            fillHeap();
            continue;
        }
        const bool heapLeft = detail::runHeap(session);
        stats.collapses += session.nPerformedOps;
        collapsesSinceInit += session.nPerformedOps;
        if (progress)
            progress(std::clamp(100 - 100 * (m.fn - stats.targetFaces) / toRemove, 0, 99), "CAD edge collapse");
        if (heapLeft)
            continue;
        // Refused edges left the heap, and an edge whose neighbourhood has changed since
        // may be acceptable now: rebuild it while that still helps, then relax.
        if (collapsesSinceInit == 0 && !(faceTarget && detail::relaxShapeGuards(m, ctx, stats)))
            break;
        collapsesSinceInit = 0;
        fillHeap();
    }
    ctx.heap = nullptr;
    if (const int closed = stats.closedTunnels - tunnelsBefore; closed > 0) {
        char line[200];
        std::snprintf(line, sizeof line,
                      "closed %d tunnel%s (cut where the rim had shrunk to three edges, and capped), the widest cap "
                      "%.4g %% of the diagonal",
                      closed, closed == 1 ? "" : "s", ctx.diagonal > 0 ? 100 * stats.widestTunnelCap / ctx.diagonal : 0.0);
        stats.relaxed.push_back(line);
    }
    if (stats.boundaryJoins > 0)
        stats.relaxed.push_back(std::to_string(stats.boundaryJoins) +
                                " collapses closed a hole or joined boundary runs where the link condition refused them "
                                "(no edge got more than two faces; ranked like a feature break)");
    if (ctx.facingGaveWay)
        stats.relaxed.push_back("faces may turn away from the input surface below " + std::to_string(ctx.farFieldFloor) +
                                " faces (the far field: under 5 % of the input)");
}

template <class MeshType>
SimplifyStats simplifyWith(MeshType& m, const SimplifyParams& params, SimplifyStats stats,
                           std::chrono::steady_clock::time_point start, vcg::CallBackPos* progress,
                           const RunTogether& together);

namespace detail {

// Whether `m` and `params` ask for a simplification, with stats.message telling why not (bad
// parameters, an unfit or empty mesh, a target not below the mesh). Fills the "before" counts
// and the face target either way.
template <class MeshType>
bool readyToSimplify(const MeshType& m, const SimplifyParams& params, SimplifyStats& stats)
{
    stats.facesBefore = stats.facesAfter = m.fn;
    stats.verticesBefore = stats.verticesAfter = m.vn;
    if (!detail::validateParams(params, stats.message))
        return false;
    if (!simplifierRequirementsMet(m)) {
        stats.message = "the mesh lacks VF adjacency or per-vertex marks";
        return false;
    }
    if (m.fn == 0) {
        stats.message = "empty mesh: no faces to simplify";
        return false;
    }
    stats.targetFaces = targetFaceCount(params, m.fn);
    stats.ok = true;
    if (stats.targetFaces >= m.fn && params.maxError <= 0) {
        stats.message = "target of " + std::to_string(stats.targetFaces) + " faces is not below the " +
                        std::to_string(m.fn) + " faces of the mesh: nothing to do";
        return false;
    }
    return true;
}

}  // namespace detail

template <class MeshType>
SimplifyStats simplify(MeshType& m, const SimplifyParams& params, vcg::CallBackPos* progress,
                       const RunTogether& together)
{
    const auto start = std::chrono::steady_clock::now();
    SimplifyStats stats;
    if (!detail::readyToSimplify(m, params, stats))
        return stats;
    return simplifyWith(m, params, stats, start, progress, together);
}

// simplify() once the plane weight is chosen.
template <class MeshType>
SimplifyStats simplifyWith(MeshType& m, const SimplifyParams& params, SimplifyStats stats,
                           std::chrono::steady_clock::time_point start, vcg::CallBackPos* progress,
                           const RunTogether& together)
{
    using VertexType = typename MeshType::VertexType;
    // An edge of three faces or more would hold its vertices for good (feature_edges.h), and
    // a target would be reached by removing whole parts instead: it is cut apart first.
    cutNonManifoldEdges(m, params, stats);
    CollapseContext<MeshType> ctx;
    if (prepareCollapse(m, params, ctx, stats)) {
        std::vector<VertexType*> frozen;
        if (params.selectedOnly)
            frozen = detail::freezeUnselected(m);

        collapseHalvesFirst(m, ctx, stats, together, progress);
        collapseToTarget(m, ctx, stats, progress);
        for (VertexType* v : frozen)
            v->SetW();
        if (params.selectedOnly)
            vcg::tri::UpdateSelection<MeshType>::VertexClear(m);
        stats.largestError = ctx.largestError;
        stats.errorBound = ctx.maxErrorAbs;
    } else {
        stats.ok = false;
        stats.message = "the mesh has no extent (all vertices coincide or are not finite)";
    }

    releaseCollapse(m, ctx);

    stats.facesAfter = m.fn;
    stats.verticesAfter = m.vn;
    const bool faceTarget = params.targetFaces > 0 || params.reductionPerc > 0;  // 100 % asks for 0 faces
    if (stats.ok && faceTarget && m.fn <= stats.targetFaces)
        stats.stoppedBy = params.reductionPerc > 0 ? "reduction percentage" : "target face count";
    else if (stats.ok && params.maxError > 0 && stats.rejectedError > 0)
        stats.stoppedBy = "max error";
    else if (stats.ok)
        stats.stoppedBy = "no collapse left";
    if (stats.ok && faceTarget && m.fn > stats.targetFaces && stats.message.empty())
        stats.message = "stopped at " + std::to_string(m.fn) + " faces, above the target of " +
                        std::to_string(stats.targetFaces) +
                        (params.maxError > 0 && stats.rejectedError > 0
                             ? ": the remaining collapses would exceed the maximum error"
                             : ": the remaining collapses would flip faces, change the topology or touch "
                               "non-manifold edges");
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace cadlod
