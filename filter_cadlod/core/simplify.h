// cadlod::simplify: runs the CAD Quadric Edge Collapse on any vcglib triangle mesh with
// VF adjacency and per-vertex marks (CMeshO with MM_VERTFACETOPO | MM_VERTMARK, or a
// test mesh type). Deleted elements are left in place (m.fn/m.vn are right); compact
// the containers afterwards if needed.
#pragma once

#include "cad_edge_collapse.h"
#include "layer_metadata.h"
#include "simplify_params.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <chrono>
#include <cmath>
#include <string>

namespace cadlod {

namespace detail {

inline bool validateParams(const SimplifyParams& p, std::string& why)
{
    if (p.targetFaces <= 0 && p.reductionPerc <= 0 && p.maxError <= 0)
        why = "no stop criterion: set a target face count, a reduction percentage or a maximum error";
    else if (p.reductionPerc > 100 || p.targetFaces < 0 || p.maxError < 0)
        why = "reduction must be 0..100 %, target faces and max error not negative";
    else if (!(p.featureAngle >= 0 && p.featureAngle <= 180) || !(p.normalThreshold > 0 && p.normalThreshold <= 180))
        why = "feature angle must be 0..180 degrees, normal threshold 0..180 degrees";
    else if (p.tieTolerance < 0 || p.flatTolerance < 0 || p.boundaryWeight < 0 || p.minCompactness < 0)
        why = "tolerances, boundary weight and minimum compactness must not be negative";
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

}  // namespace detail

template <class MeshType>
bool simplifierRequirementsMet(const MeshType& m)
{
    return vcg::tri::HasPerVertexVFAdjacency(m) && vcg::tri::HasPerFaceVFAdjacency(m) &&
           vcg::tri::HasPerVertexMark(m);
}

// Sets up a simplification of `m`: feature and boundary marks, quadrics, input normals,
// the bit flags they need. False if the mesh has no extent (stats.diagonal 0). Every
// prepareCollapse needs a releaseCollapse, which frees the bit flags.
template <class MeshType>
bool prepareCollapse(MeshType& m, const SimplifyParams& params, CollapseContext<MeshType>& ctx, SimplifyStats& stats)
{
    using FaceType = typename MeshType::FaceType;
    using VertexType = typename MeshType::VertexType;
    ctx.params = params;
    ctx.stats = &stats;
    for (int j = 0; j < 3; ++j)
        ctx.bits.edge[j] = FaceType::NewBitFlag();
    ctx.bits.locked = VertexType::NewBitFlag();
    ctx.bits.boundary = VertexType::NewBitFlag();
    for (VertexType& v : m.vert) {
        v.ClearUserBit(ctx.bits.locked);
        v.ClearUserBit(ctx.bits.boundary);
    }

    stats.diagonal = detail::usedDiagonal(m, ctx.bits.locked);
    if (!(stats.diagonal > 0))
        return false;
    ctx.diagonal = stats.diagonal;
    ctx.flatError2 = std::pow(params.flatTolerance * ctx.diagonal, 2);
    ctx.maxErrorAbs = params.maxError * ctx.diagonal;
    ctx.cosNormalLimit = std::cos(params.normalThreshold * M_PI / 180.0);

    vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    const bool parts = params.keepPartBorders && vcg::tri::HasPerFaceAttribute(m, kPartAttribute);
    typename MeshType::template PerFaceAttributeHandle<int> partHandle;
    if (parts)
        partHandle = facePartHandle(m);
    const FeatureEdgeCounts features = markFeatureEdges(
        m, ctx.bits, params.featureAngle, params.preserveBoundary,
        [&](FaceType& f) { return parts ? partHandle[f] : 0; });
    stats.featureEdges = features.feature;
    stats.boundaryEdges = features.boundary;
    stats.nonManifoldEdges = features.nonManifold;
    stats.degenerateFaces = features.degenerateFaces;

    QuadricWeights weights;
    weights.feature = params.boundaryWeight;
    weights.planar = params.planarQuadric ? 1e-3 : 0.0;
    ctx.quadrics.init(m, weights, [&](FaceType& f, int j) { return f.IsUserBit(ctx.bits.edge[j]); });
    ctx.storeInputNormals(m);
    ctx.clearRingChanges(m);
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
    VertexType::DeleteBitFlag(ctx.bits.boundary);
    VertexType::DeleteBitFlag(ctx.bits.locked);
    for (int j = 2; j >= 0; --j)
        FaceType::DeleteBitFlag(ctx.bits.edge[j]);
}

// The collapses themselves, on a prepared context, until stats.targetFaces or until no
// collapse is left.
template <class MeshType>
void collapseToTarget(MeshType& m, CollapseContext<MeshType>& ctx, SimplifyStats& stats, vcg::CallBackPos* progress)
{
    using Collapse = CadEdgeCollapse<MeshType>;
    vcg::LocalOptimization<MeshType> session(m, &ctx);
    ctx.heap = &session.h;
    session.template Init<Collapse>();
    if (stats.targetFaces > 0)
        session.SetTargetSimplices(stats.targetFaces);
    const int toRemove = std::max(1, m.fn - stats.targetFaces);
    // Return now and then to report progress: after a number of collapses, not a time
    // budget (vcglib reads the process CPU clock, a system call, on every heap pop).
    session.SetTargetOperations(std::max(1000, toRemove / 100));
    int collapsesSinceInit = 0;
    while (m.fn > stats.targetFaces) {
        const bool heapLeft = session.DoOptimization();
        stats.collapses += session.nPerformedOps;
        collapsesSinceInit += session.nPerformedOps;
        if (progress)
            progress(std::clamp(100 - 100 * (m.fn - stats.targetFaces) / toRemove, 0, 99), "CAD edge collapse");
        if (!heapLeft) {
            // Refused edges left the heap, and an edge whose neighbourhood has changed
            // since may be acceptable now: rebuild it while that still helps.
            if (collapsesSinceInit == 0)
                break;
            collapsesSinceInit = 0;
            session.template Init<Collapse>();
        }
    }
    ctx.heap = nullptr;
}

// Simplifies `m` in place. `progress` may be null.
template <class MeshType>
SimplifyStats simplify(MeshType& m, const SimplifyParams& params, vcg::CallBackPos* progress = nullptr)
{
    using VertexType = typename MeshType::VertexType;
    const auto start = std::chrono::steady_clock::now();

    SimplifyStats stats;
    stats.facesBefore = stats.facesAfter = m.fn;
    stats.verticesBefore = stats.verticesAfter = m.vn;
    if (!detail::validateParams(params, stats.message))
        return stats;
    if (!simplifierRequirementsMet(m)) {
        stats.message = "the mesh lacks VF adjacency or per-vertex marks";
        return stats;
    }
    if (m.fn == 0) {
        stats.message = "empty mesh: no faces to simplify";
        return stats;
    }
    stats.targetFaces = targetFaceCount(params, m.fn);
    stats.ok = true;
    if (stats.targetFaces >= m.fn && params.maxError <= 0) {
        stats.message = "target of " + std::to_string(stats.targetFaces) + " faces is not below the " +
                        std::to_string(m.fn) + " faces of the mesh: nothing to do";
        return stats;
    }

    CollapseContext<MeshType> ctx;
    if (prepareCollapse(m, params, ctx, stats)) {
        std::vector<VertexType*> frozen;
        if (params.selectedOnly)
            frozen = detail::freezeUnselected(m);

        collapseToTarget(m, ctx, stats, progress);
        for (VertexType* v : frozen)
            v->SetW();
        if (params.selectedOnly)
            vcg::tri::UpdateSelection<MeshType>::VertexClear(m);
        stats.largestError = ctx.largestError;
    } else {
        stats.ok = false;
        stats.message = "the mesh has no extent (all vertices coincide or are not finite)";
    }

    releaseCollapse(m, ctx);

    stats.facesAfter = m.fn;
    stats.verticesAfter = m.vn;
    const bool faceTarget = params.targetFaces > 0 || params.reductionPerc > 0;  // 100 % asks for 0 faces
    if (stats.ok && faceTarget && m.fn > stats.targetFaces && stats.message.empty())
        stats.message = "stopped at " + std::to_string(m.fn) + " faces, above the target of " +
                        std::to_string(stats.targetFaces) +
                        ": the remaining collapses would break a feature, the topology, the error bound or the "
                        "face shape limits";
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace cadlod
