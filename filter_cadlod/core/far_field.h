// The far field (issue 13): below kFacingFarField of its input faces a mesh has a few
// hundred faces left for what had thousands, and what a viewer sees of a collapse there is
// how far it moves the surface, the Hausdorff distance, which the quadrics' sum of squared
// plane distances ranks differently. A quadric sums over the planes a vertex stands for:
// squeezing a tall part into a tetrahedron moves a few of its planes by its whole height
// and costs little, while removing a small part moves all of its planes by its small height
// and costs a lot, so the tall part went first where the Hausdorff distance says the other.
//
// So when the far field starts, the input's points (its vertices and face centroids) are
// dealt to the live face nearest to each, and from then on every operation is ranked by the
// largest distance it opens:
// - a collapse, by the largest distance from the points of the faces it changes to the
//   faces it makes (the points may lie nearer another face: never less than the truth),
//   and from its new vertex to the input surface, with its quadric error beside
//   (kFarFieldMeanShare);
// - a component's removal, by the gap it leaves (component_removal.h).
// After a collapse its points go to the nearest of the faces around the new vertex; a
// removed component's points go with it (its gap is the distance they were ranked at).
#pragma once

#include "hausdorff.h"
#include "triangle_tree.h"

#include <vcg/space/point3.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace cadlod {

// Beside the largest distance a collapse opens, its quadric error (the mean distance of its
// new vertex to the planes it stands for) counts, squared, at this share: most collapses of
// a flat region open none, and among those the quadric still tells which moves the surface
// least. Tried at 0, 0.5, 1, 2, 4 and 16 on the far-field bench (docs/benchmarks.md).
inline constexpr double kFarFieldMeanShare = 0.5;

template <class MeshType>
class FarFieldDistances
{
public:
    using FaceType = typename MeshType::FaceType;
    using VertexType = typename MeshType::VertexType;

    // Keeps the input's points: every live vertex and face centroid of `m` as it is now.
    explicit FarFieldDistances(const MeshType& m)
    {
        for (const VertexType& v : m.vert)
            if (!v.IsD())
                points_.push_back(vcg::Point3d::Construct(v.cP()));
        for (const FaceType& f : m.face)
            if (!f.IsD())
                points_.push_back((vcg::Point3d::Construct(f.cP(0)) + vcg::Point3d::Construct(f.cP(1)) +
                                   vcg::Point3d::Construct(f.cP(2))) / 3.0);
    }

    bool started() const { return started_; }

    // Deals the points to the nearest live face of `m` (faces keep their index from here on).
    void start(MeshType& m)
    {
        faceBase_ = m.face.empty() ? nullptr : &m.face[0];
        pointsOf_.assign(m.face.size(), {});
        started_ = true;
        const detail::ClosestFace<MeshType> closest(m);
        if (closest.empty())
            return;
        for (std::uint32_t i = 0; i < points_.size(); ++i) {
            double d = 0;
            if (const FaceType* f = closest.find(points_[i], d))
                pointsOf_[index(f)].push_back(i);
        }
    }

    // The largest distance from the points of the faces around v0 and v1 to the triangles
    // (p, a, b) of `ring` (the faces a collapse of the edge to p makes).
    template <class Ring>
    double collapseError(VertexType* v0, VertexType* v1, const vcg::Point3d& p, const Ring& ring) const
    {
        double largest2 = 0;
        forEachPointAround(v0, v1, [&](std::uint32_t i) {
            double nearest2 = std::numeric_limits<double>::max();
            for (const auto& face : ring) {
                nearest2 = std::min(nearest2, TriangleTree::triangleDistance2({p, face.a, face.b}, points_[i]));
                if (nearest2 <= largest2)
                    break;  // cannot raise the largest
            }
            if (nearest2 < std::numeric_limits<double>::max())
                largest2 = std::max(largest2, nearest2);
        });
        return std::sqrt(largest2);
    }

    // Before the collapse of v0 into v1: takes the points of the faces around both.
    void takePointsAround(VertexType* v0, VertexType* v1)
    {
        moving_.clear();
        forEachFaceAround(v0, v1, [&](std::size_t f) {
            moving_.insert(moving_.end(), pointsOf_[f].begin(), pointsOf_[f].end());
            pointsOf_[f].clear();
        });
    }

    // After it: deals them to the nearest of the faces around v1.
    void dealPointsAround(VertexType* v1)
    {
        std::vector<FaceType*> around;
        for (vcg::face::VFIterator<FaceType> vfi(v1); !vfi.End(); ++vfi)
            around.push_back(vfi.F());
        if (around.empty())
            return;
        for (const std::uint32_t i : moving_) {
            std::size_t best = 0;
            double best2 = std::numeric_limits<double>::max();
            for (std::size_t k = 0; k < around.size(); ++k) {
                const FaceType& f = *around[k];
                const double d2 = TriangleTree::triangleDistance2(
                    {vcg::Point3d::Construct(f.cP(0)), vcg::Point3d::Construct(f.cP(1)), vcg::Point3d::Construct(f.cP(2))},
                    points_[i]);
                if (d2 < best2) {
                    best2 = d2;
                    best = k;
                }
            }
            pointsOf_[index(around[best])].push_back(i);
        }
    }

    // A removed face's points go with it.
    void dropPointsOf(const FaceType* f)
    {
        if (started_)
            pointsOf_[index(f)].clear();
    }

private:
    std::size_t index(const FaceType* f) const { return std::size_t(f - faceBase_); }

    template <class Visit>
    void forEachFaceAround(VertexType* v0, VertexType* v1, const Visit& visit) const
    {
        for (vcg::face::VFIterator<FaceType> vfi(v0); !vfi.End(); ++vfi)
            visit(index(vfi.F()));
        for (vcg::face::VFIterator<FaceType> vfi(v1); !vfi.End(); ++vfi) {
            const FaceType* f = vfi.F();
            if (f->cV(0) != v0 && f->cV(1) != v0 && f->cV(2) != v0)  // the edge's faces came with v0
                visit(index(f));
        }
    }

    template <class Visit>
    void forEachPointAround(VertexType* v0, VertexType* v1, const Visit& visit) const
    {
        forEachFaceAround(v0, v1, [&](std::size_t f) {
            for (const std::uint32_t i : pointsOf_[f])
                visit(i);
        });
    }

    std::vector<vcg::Point3d> points_;
    std::vector<std::vector<std::uint32_t>> pointsOf_;  // per face index: the points dealt to it
    std::vector<std::uint32_t> moving_;                  // taken before a collapse
    const FaceType* faceBase_ = nullptr;
    bool started_ = false;
};

}  // namespace cadlod
