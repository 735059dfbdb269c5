// The far field: below kFacingFarField of its input faces (toward a face target),
// or in an LOD chain's levels where the model is a few dozen pixels high, a mesh has a few
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
//   and from its new vertex to the input surface, with its quadric error and the volume
//   it sweeps beside (kFarFieldMeanShare, kFarFieldSweptShare);
// - a component's removal, by the gap it leaves (component_removal.h).
// An LOD chain's sessions are also held to their budget by that distance
// (CollapseContext::maxDistance): the distance a collapse opens, without the terms beside;
// and the swept volume, an outline term for a face target, is left out of their ranking.
// The placement of a collapse is then the candidate that opens the least, and a
// tetrahedron may fold into a fin (foldsTetrahedron).
// After a collapse its points go to the nearest of the faces around the new vertex; a
// removed component's points go with it (its gap is the distance they were ranked at).
#pragma once

#include "measure/hausdorff.h"
#include "measure/triangle_tree.h"

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
// least. Chosen on the far-field bench (docs/benchmarks.md).
inline constexpr double kFarFieldMeanShare = 0.5;

// A distance misses what a viewer of a solid sees at that size: its outline. Flattening a
// plate's corner opens half the plate's thickness but takes a wedge out of its outline in
// every side view, while folding a boss into a fin opens its radius and takes less. So the
// volume a collapse sweeps counts beside, as the edge of a cube of that volume, squared,
// at this share. Chosen on the far-field bench (docs/benchmarks.md).
inline constexpr double kFarFieldSweptShare = 0.18;

// A fin is seen edge-on from the directions in its plane, where the part's whole width
// across it vanishes, about twice the distance the fold opens (the fin runs through the
// middle): so a fold is ranked at this many times that distance (chosen on the far-field
// bench, docs/benchmarks.md).
inline constexpr double kFoldWidth = 2.0;

// Whether v0 and v1 are an edge of a tetrahedron, a closed component of four faces: its
// collapse fails the link condition (the other two vertices are neighbours of both and
// joined by an edge), yet in the far field it is the cheapest step a small tall part can
// take. It folds the part into a fin, two faces back to back, which keeps the part's
// height and outline from the side where removing it opens its whole height (a board's
// capacitors, seen from far: meshoptimizer keeps them so). A fin's own edges stay refused, and
// the fin is removed whole like any component.
template <class VertexType>
bool foldsTetrahedron(VertexType* v0, VertexType* v1)
{
    using FaceType = typename VertexType::FaceType;
    VertexType* seen[4] = {v0, v1, nullptr, nullptr};
    int faces = 0;
    for (VertexType* v : {v0, v1})
        for (vcg::face::VFIterator<FaceType> vfi(v); !vfi.End(); ++vfi) {
            if (++faces > 6)
                return false;
            for (int k = 0; k < 3; ++k) {
                VertexType* x = vfi.F()->V(k);
                if (std::find(seen, seen + 4, x) != seen + 4)
                    continue;
                if (seen[3])
                    return false;  // a fifth vertex
                *std::find(seen, seen + 4, nullptr) = x;
            }
        }
    return faces == 6 && seen[3];
}

template <class MeshType>
class FarFieldDistances
{
public:
    using FaceType = typename MeshType::FaceType;
    using VertexType = typename MeshType::VertexType;

    // Keeps the input's points: every live vertex and face centroid of `m` as it is now,
    // and with `edgeSpacing` > 0, points along every edge no farther apart than that; or,
    // with `maxPoints` > 0 and more of them, every k-th so that at most that many are kept
    // (in the far field a face stands for thousands of input faces, and each collapse
    // measures every point of the faces it changes).
    explicit FarFieldDistances(const MeshType& m, std::size_t maxPoints = 0, double edgeSpacing = 0.0)
    {
        std::size_t all = 0;
        forEachInputPoint(m, edgeSpacing, [&](const vcg::Point3d&) { ++all; });
        const std::size_t step = maxPoints > 0 && all > maxPoints ? (all + maxPoints - 1) / maxPoints : 1;
        points_.reserve(all / step + 1);
        std::size_t i = 0;
        forEachInputPoint(m, edgeSpacing, [&](const vcg::Point3d& p) {
            if (i++ % step == 0)
                points_.push_back(p);
            if (i == std::size_t(m.vn) + std::size_t(m.fn))
                cornersAndCentroids_ = points_.size();
        });
    }

    // The input's points kept (the far field's own, once started).
    const std::vector<vcg::Point3d>& points() const { return points_; }

    bool started() const { return started_; }
    bool dealt() const { return dealt_; }

    // Deals the points to the nearest live face of `m` and ranks by distance from here on.
    void start(MeshType& m)
    {
        // Here a face stands for hundreds of input faces and every placement of a
        // collapse is ranked by its distance: the points along the edges would make that
        // several times dearer, and the chain's measure of each level against level 0
        // steers the far field's budgets (lod_chain.h).
        points_.resize(std::min(points_.size(), cornersAndCentroids_));
        deal(m);
        started_ = true;
    }

    // Deals the points to the nearest live face of `m` (faces keep their index from here on).
    void deal(MeshType& m)
    {
        faceBase_ = m.face.empty() ? nullptr : &m.face[0];
        pointsOf_.assign(m.face.size(), {});
        dealt_ = true;
        const detail::ClosestFace<MeshType> closest(m);
        if (closest.empty())
            return;
        for (std::uint32_t i = 0; i < points_.size(); ++i) {
            double d = 0;
            if (const FaceType* f = closest.find(points_[i], d))
                pointsOf_[index(f)].push_back(i);
        }
    }

    static constexpr std::uint32_t kNoPoint = std::numeric_limits<std::uint32_t>::max();

    // The largest distance from the points of the faces around v0 and v1 to the triangles
    // (p, a, b) of `ring` (the faces a collapse of the edge to p makes); once it reaches
    // `enough`, the rest of the points are skipped. `farthest` names the point found
    // farthest, and a point it names already is measured first: the placements of one
    // collapse mostly share their farthest point, and with the largest distance known
    // early most points stop at the first face within it. That face is tried first for the
    // next point: a face's points come in a row and mostly lie under the same new face.
    // Distances below `atLeast` are not told apart: the least returned is that.
    template <class Ring>
    double collapseError(VertexType* v0, VertexType* v1, const vcg::Point3d& p, const Ring& ring, double enough,
                         std::uint32_t& farthest, double atLeast = 0.0) const
    {
        const double enough2 = enough < std::sqrt(std::numeric_limits<double>::max()) ? enough * enough
                                                                                      : std::numeric_limits<double>::max();
        double largest2 = atLeast * atLeast;
        const std::size_t faces = ring.size();
        std::size_t within = 0;  // the ring face the point before stopped at
        auto measure = [&](std::uint32_t i) {
            double nearest2 = std::numeric_limits<double>::max();
            for (std::size_t k = 0; k < faces; ++k) {
                const std::size_t j = within + k < faces ? within + k : within + k - faces;
                nearest2 = std::min(nearest2, TriangleTree::triangleDistance2({p, ring[j].a, ring[j].b}, points_[i]));
                if (nearest2 <= largest2) {
                    within = j;
                    return;  // cannot raise the largest
                }
            }
            if (nearest2 < std::numeric_limits<double>::max()) {
                largest2 = nearest2;
                farthest = i;
            }
        };
        if (farthest != kNoPoint)
            measure(farthest);
        const std::uint32_t first = farthest;
        forEachPointAround(v0, v1, [&](std::uint32_t i) {
            if (largest2 < enough2 && i != first)
                measure(i);
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
        if (dealt_)
            pointsOf_[index(f)].clear();
    }

private:
    std::size_t index(const FaceType* f) const { return std::size_t(f - faceBase_); }

    // The vertices, the face centroids, and with `edgeSpacing` > 0 the points that split
    // each edge into pieces no longer than that. An LOD level's distance from the input is
    // measured all over the input's surface, and along a long edge (a housing's side, a
    // strip of a cylinder) it can grow well beyond what its ends and the face's centroid
    // say: a chain level measured 1.4 times the largest distance its collapses were held
    // to (docs/benchmarks.md). An edge between two faces is taken once, from the face that
    // has its first vertex first in memory, or from its one face on a border.
    template <class Visit>
    static void forEachInputPoint(const MeshType& m, double edgeSpacing, const Visit& visit)
    {
        for (const VertexType& v : m.vert)
            if (!v.IsD())
                visit(vcg::Point3d::Construct(v.cP()));
        for (const FaceType& f : m.face)
            if (!f.IsD())
                visit((vcg::Point3d::Construct(f.cP(0)) + vcg::Point3d::Construct(f.cP(1)) +
                       vcg::Point3d::Construct(f.cP(2))) / 3.0);
        if (!(edgeSpacing > 0))
            return;
        for (const FaceType& f : m.face) {
            if (f.IsD())
                continue;
            for (int j = 0; j < 3; ++j) {
                const VertexType* a = f.cV(j);
                const VertexType* b = f.cV((j + 1) % 3);
                if (a > b && !isBorder(f, j))
                    continue;
                const vcg::Point3d pa = vcg::Point3d::Construct(a->cP()), pb = vcg::Point3d::Construct(b->cP());
                const double pieces = std::ceil((pb - pa).Norm() / edgeSpacing);
                const int n = pieces < 1 ? 1 : (pieces > 1024 ? 1024 : int(pieces));
                for (int k = 1; k < n; ++k)
                    visit(pa + (pb - pa) * (double(k) / n));
            }
        }
    }

    // Whether edge j of f has no other face: none of the faces around its first vertex
    // holds its second vertex before the first (the other face's direction).
    static bool isBorder(const FaceType& f, int j)
    {
        const VertexType* a = f.cV(j);
        const VertexType* b = f.cV((j + 1) % 3);
        for (vcg::face::VFIterator<FaceType> vfi(const_cast<VertexType*>(a)); !vfi.End(); ++vfi) {
            const FaceType* g = vfi.F();
            if (g != &f && g->cV((vfi.I() + 2) % 3) == b)
                return false;
        }
        return true;
    }

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
    std::size_t cornersAndCentroids_ = 0;                // the points before those along the edges
    const FaceType* faceBase_ = nullptr;
    bool started_ = false;
    bool dealt_ = false;
};

}  // namespace cadlod
