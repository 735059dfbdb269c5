// In the far field a collapse is placed and ranked by the largest distance it opens from the
// input (far_field.h), not by the quadrics and compactness alone.
#pragma once

#include "simplify/link_condition.h"
#include "simplify/placement.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace cadlod {

template <class MeshType>
struct FarFieldPlacement {
    using VertexType = typename MeshType::VertexType;
    using FaceType = typename MeshType::FaceType;
    using VFIterator = vcg::face::VFIterator<FaceType>;
    using Context = CollapseContext<MeshType>;
    using Candidate = typename Placement<MeshType>::Candidate;
    using ShapeFloors = typename Placement<MeshType>::ShapeFloors;

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
    static FarFieldChoice farFieldPlacement(Context& ctx, VertexType* v0, VertexType* v1, const Candidate* cand,
                                            int count, double area, const ShapeFloors& floors, int& best,
                                            PlacementScore& bestScore, int& failed)
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
            const PlacementScore s = NewFaceChecks<MeshType>::score(ctx, cand[i].p, floors(cand[i]), failed, false);
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
    // makes a far reduction much slower (docs/benchmarks.md).
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
    // corners lie on it: p alone says nothing of that, and a chain level would measure more
    // than the distance its collapses were held to.
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

};

}  // namespace cadlod
