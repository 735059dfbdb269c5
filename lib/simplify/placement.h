// The placement policy: the points an edge may collapse to (its endpoints, points between
// them, the quadric's own placement), each with its quadric cost, and the cost each is ranked
// at once features and shading are priced.
#pragma once

#include "simplify/new_face_checks.h"
#include "simplify/quadric_placement.h"

#include <algorithm>
#include <limits>

namespace cadlod {

template <class MeshType>
struct Placement {
    using VertexType = typename MeshType::VertexType;
    using FaceType = typename MeshType::FaceType;
    using VFIterator = vcg::face::VFIterator<FaceType>;
    using Context = CollapseContext<MeshType>;

    struct Candidate {
        vcg::Point3d p;
        double cost;      // quadric cost: the geometric error the placement makes
        bool breaks;      // moves a feature point off its feature (see evaluate)
        double ranked;    // the cost it is ordered by: cost, times the feature penalty if it breaks
        bool offEdge;     // a quadric minimum, not a point of the segment
    };
    static constexpr int kMaxCandidates = 32;
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

    // The candidates a collapse may use, ranked. Features are not locks but prices: a
    // placement that breaks one (cuts across a crease, moves a corner or a boundary vertex
    // off its place) is ranked at featurePenalty times its quadric cost, which already holds
    // the feature's constraint planes. So a feature gives way only where every collapse that
    // keeps the features costs that many times more error: a board keeps its corners while
    // any small part can still lose a chamfer. featurePenalty 0 makes features hard locks.
    static int rankedCandidates(const Context& ctx, const Quadric& q, const vcg::Point3d& p0, const vcg::Point3d& p1,
                                bool v0Pinned, bool v1Pinned, bool onBoundaryLine, bool crossesFeature, double flatFloor,
                                bool offEdgeMinima, Candidate* cand)
    {
        const double penalty = ctx.params.featurePenalty;
        int count = candidates(ctx, q, p0, p1, v0Pinned, v1Pinned, onBoundaryLine, offEdgeMinima, cand);
        int kept = 0;
        for (int i = 0; i < count; ++i) {
            Candidate c = cand[i];
            c.breaks = crossesFeature || (c.breaks && c.cost > flatFloor);
            if (c.breaks && penalty <= 0)
                continue;
            c.ranked = c.breaks ? c.cost * std::max(1.0, penalty) : c.cost;
            if (ctx.shadingScale > 0 && c.cost > flatFloor)
                c.ranked += ctx.shadingScale * NewFaceChecks<MeshType>::shadedArea(ctx, c.p);
            cand[kept++] = c;
        }
        return kept;
    }

    // The shape floors of one collapse's new faces. No new face below minCompactness, unless
    // it is still better than the worst now. A collapse that costs nothing (within the flat
    // floor) must not make a sliver either: any later collapse can do its work, and a sliver
    // made for free is shape lost for nothing. Both guards give way when the simplifier
    // relaxes its shape limits (simplify.h), and in the far field of a session held to a
    // distance (an LOD chain's level, drawn where the model is a few dozen pixels high): its
    // distance alone judges it there, and a thin wall around a cavity (a jack's socket) keeps
    // its opening with long faces across the rim. Near a face target (ctx.countsSlivers) a
    // collapse among slivers may not add to their number either: the floor alone lets it make
    // new ones as long as each beats the worst.
    struct ShapeFloors {
        double floor = 0.0;      // for a collapse that costs something
        double freeFloor = 0.0;  // for a free one
        double flatFloor = 0.0;  // the cost up to which a collapse is free
        int maxSlivers = std::numeric_limits<int>::max();
        bool keepJoins = false;  // the smooth-join guard is in force
        double operator()(const Candidate& c) const { return c.cost <= flatFloor ? freeFloor : floor; }
    };
    static ShapeFloors shapeFloors(const Context& ctx, const typename CollapseRing<MeshType>::Neighbourhood& n,
                                   double flatFloor)
    {
        const double minCompactness = ctx.shapeGuards && !ctx.heldToDistance() ? ctx.params.minCompactness : 0.0;
        const double minFree = minCompactness > 0 ? std::max(CollapseRing<MeshType>::kSliver, minCompactness) : 0.0;
        ShapeFloors f;
        f.floor = std::min(minCompactness, n.worstCompactness);
        f.freeFloor = std::min(minFree, n.worstCompactness);
        f.flatFloor = flatFloor;
        if (minCompactness > 0 && ctx.countsSlivers)
            f.maxSlivers = n.slivers;
        f.keepJoins = ctx.keepsSmoothJoins();
        return f;
    }

    struct Choice {
        int best = -1;  // the candidate chosen; -1: none is acceptable
        PlacementScore score;
        bool anyFlip = false;  // a candidate was refused for a face turned too far
        int failed = -1;       // the ring face that refused the last candidate (NewFaceChecks::score)
    };

    // Compactness breaks the ties of cost: among the candidates ranked within `tieLimit`, the
    // one whose new faces are the most compact on average (the cheaper of equals). Where no
    // tied candidate is acceptable, the cheapest acceptable other.
    static Choice mostCompactOfTied(const Context& ctx, const Candidate* cand, int count, double tieLimit,
                                    const ShapeFloors& floors)
    {
        Choice c;
        auto scoreOf = [&](int i) {
            const PlacementScore s = NewFaceChecks<MeshType>::score(ctx, cand[i].p, floors(cand[i]), c.failed,
                                                                    floors.keepJoins, floors.maxSlivers);
            c.anyFlip |= s.flipped;
            return s;
        };
        for (int i = 0; i < count; ++i) {
            if (cand[i].ranked > tieLimit)
                continue;
            const PlacementScore s = scoreOf(i);
            if (s.valid && (c.best < 0 || s.meanCompactness > c.score.meanCompactness ||
                            (s.meanCompactness == c.score.meanCompactness && cand[i].ranked < cand[c.best].ranked))) {
                c.best = i;
                c.score = s;
            }
        }
        if (c.best >= 0)
            return c;
        for (int i = 0; i < count; ++i) {
            if (cand[i].ranked <= tieLimit || (c.best >= 0 && cand[i].ranked >= cand[c.best].ranked))
                continue;
            const PlacementScore s = scoreOf(i);
            if (s.valid) {
                c.best = i;
                c.score = s;
            }
        }
        return c;
    }
};

}  // namespace cadlod
