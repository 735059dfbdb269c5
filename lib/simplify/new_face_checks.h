// What the faces around the new vertex would be at a candidate placement: whether one turns
// too far or away from the input surface, falls below the shape floor, or folds a smooth join
// into a crease, their mean compactness, and how much of them changes shade.
#pragma once

#include "simplify/collapse_ring.h"
#include "measure/compactness.h"

#include <limits>

namespace cadlod {

struct PlacementScore {
    bool valid = false;
    bool flipped = false;
    double meanCompactness = 0.0;
};

template <class MeshType>
struct NewFaceChecks {
    using VertexType = typename MeshType::VertexType;
    using FaceType = typename MeshType::FaceType;
    using VFIterator = vcg::face::VFIterator<FaceType>;
    using Context = CollapseContext<MeshType>;
    static constexpr double kSliver = CollapseRing<MeshType>::kSliver;

    // How much of the ring changes shade with the new vertex at p: the sum, over the faces
    // turned more than the shading angle from the face they were in the input, of area ×
    // (1 − cos of the turn). Turns below the angle (a crease sliding along a fillet, a facet
    // of a fine cylinder) are not counted: pricing those costs distance and slivers
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
    static PlacementScore score(const Context& ctx, const vcg::Point3d& p, double floor, int& failed,
                                bool keepsSmoothJoins, int maxSlivers = std::numeric_limits<int>::max())
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
};

}  // namespace cadlod
