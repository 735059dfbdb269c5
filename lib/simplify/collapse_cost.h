// The cost model of an edge collapse: the quadric error of its placement, and the priority
// it is ranked at in the heap (CollapseContext::priority: the cost plus a rounding floor that
// orders the free collapses of flat regions by merged area and shape, both scale-free).
#pragma once

#include "simplify/collapse_context.h"
#include "simplify/placement.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cadlod {

template <class MeshType>
struct CollapseCost {
    using VertexType = typename MeshType::VertexType;
    using ScalarType = typename MeshType::ScalarType;
    using Context = CollapseContext<MeshType>;
    using Place = Placement<MeshType>;

    static ScalarType priorityOf(const Context& ctx, double cost, double area, double shape)
    {
        return ScalarType(ctx.priority(cost, area, shape));
    }

    static Quadric mergedQuadric(const Context& ctx, const VertexType* v0, const VertexType* v1)
    {
        Quadric q = ctx.quadrics.quadric(v0);
        q += ctx.quadrics.quadric(v1);
        return q;
    }

    // The error a placement of quadric cost `cost` makes: the root of its mean squared
    // distance to the merged planes (`area`, their weight), or of the cost where they weigh
    // nothing.
    static float errorOf(double cost, double area) { return float(area > 0 ? std::sqrt(cost / area) : std::sqrt(cost)); }

    // Never above the priority evaluate() finds: the cheapest of all candidates (evaluate
    // may refuse some or rank them higher, never lower) and the best shape. In the far field
    // 0: the distance an operation opens is found when it is evaluated.
    static ScalarType lowerBound(const Context& ctx, VertexType* v0, VertexType* v1)
    {
        if (v0->IsUserBit(ctx.bits.locked) || v1->IsUserBit(ctx.bits.locked))
            return std::numeric_limits<ScalarType>::max();
        if (ctx.inFarField())
            return 0;
        const Quadric q = mergedQuadric(ctx, v0, v1);
        typename Place::Candidate cand[Place::kMaxCandidates];
        const int count = Place::candidates(ctx, q, vcg::Point3d::Construct(v0->cP()), vcg::Point3d::Construct(v1->cP()),
                                            false, false, false, true, cand);
        double minCost = std::numeric_limits<double>::max();
        for (int i = 0; i < count; ++i)
            minCost = std::min(minCost, cand[i].cost);
        return priorityOf(ctx, minCost, ctx.quadrics.cappedArea(v0, v1), 1.0) *
               ScalarType(std::min(1.0, ctx.params.sliverFirstShare));
    }
};

}  // namespace cadlod
