// What a simplification session shares with every collapse it runs: the parameters and the
// bounds derived from them, the per-vertex quadrics, the input's normals and surface, the
// far field's distances, the counters, and the scratch of the edge being evaluated.
#pragma once

#include "simplify/cad_quadrics.h"
#include "simplify/far_field.h"
#include "simplify/feature_edges.h"
#include "measure/input_surface.h"
#include "simplify/removal_log.h"
#include "simplify/simplify_params.h"

#include <vcg/complex/algorithms/local_optimization.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace cadlod {

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

// What float coordinates resolve, as a share of their magnitude (a few units in the last
// place): quadric costs below this distance are rounding, not error.
inline constexpr double kRoundingOfFloat = 2.5 * std::numeric_limits<float>::epsilon();

template <class MeshType>
struct CollapseContext : public vcg::BaseParameterClass {
    using VertexType = typename MeshType::VertexType;

    SimplifyParams params;
    FeatureBits bits;
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
    // Where the session is. Near the input, operations are ranked by their quadric error and
    // bounded by maxErrorAbs; `nearWithinDistance` bounds them by the distance they open too
    // (the input's points dealt for a far field ahead, with a distance bound). In the far field
    // (far_field.h, once started) they are ranked by the largest distance they open;
    // `farHeldToDistance` is an LOD chain's level there, judged by that distance alone.
    enum class Regime { near, nearWithinDistance, far, farHeldToDistance };
    Regime regime() const
    {
        if (farField && farField->started())
            return maxDistance > 0 ? Regime::farHeldToDistance : Regime::far;
        if (farField && farField->dealt() && maxDistance > 0)
            return Regime::nearWithinDistance;
        return Regime::near;
    }
    bool inFarField() const { return regime() == Regime::far || regime() == Regime::farHeldToDistance; }
    bool heldToDistance() const { return regime() == Regime::farHeldToDistance; }
    bool checksDistance() const { return regime() == Regime::nearWithinDistance; }
    // The priority of an operation in the far field: the distance it opens, squared, in
    // diagonals.
    double farFieldPriority(double distance) const { return distance * distance / (diagonal * diagonal); }
    // The smooth-join guard (keepSmoothJoins) is one of the shape guards: in force while they
    // are, and only where the compactness guard is.
    bool keepsSmoothJoins() const
    {
        return cosSmoothJoin >= -1.0 && shapeGuards && !heldToDistance() && params.minCompactness > 0;
    }
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

}  // namespace cadlod
