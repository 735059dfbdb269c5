// Per-vertex error quadrics for the CAD edge collapse (Garland–Heckbert):
//  - every face adds its plane to its three vertices, all with about the same weight (one
//    area cap, plus the face's area up to one more, see kAreaCapOfMean), plus a share of
//    their area (QuadricWeights::areaShare);
//  - every feature edge (boundary, crease, part border) adds, for each face along it, the
//    plane through the edge perpendicular to that face, weighted by boundaryWeight × the
//    face's weight, so that moving the edge sideways by d costs what moving that face off
//    its plane by d costs. (A weight of |e|² would make the long thin faces CAD exporters
//    put along features nearly free to slide, and holes close up at far reductions.)
//  - planarQuadric adds the same edge planes with a tiny weight on all other edges.
// The accumulated weight (the face weights, called area below) is kept beside each
// quadric, so sqrt(cost / area) is an RMS distance in model units: the collapse error
// reported and bounded by maxError.
#pragma once

#include "simplify/feature_edges.h"

#include <vcg/math/quadric.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cadlod {

using Quadric = vcg::math::Quadric<double>;

// Quadric of the squared distance to the plane n·x = d (n of unit length), times weight.
inline Quadric planeQuadric(const vcg::Point3d& n, double d, double weight)
{
    Quadric q;
    q.a[0] = weight * n[0] * n[0];
    q.a[1] = weight * n[0] * n[1];
    q.a[2] = weight * n[0] * n[2];
    q.a[3] = weight * n[1] * n[1];
    q.a[4] = weight * n[1] * n[2];
    q.a[5] = weight * n[2] * n[2];
    q.b[0] = -2.0 * weight * d * n[0];
    q.b[1] = -2.0 * weight * d * n[1];
    q.b[2] = -2.0 * weight * d * n[2];
    q.c = weight * d * d;
    return q;
}

struct QuadricWeights {
    double feature = 1.0;   // constraint planes of feature edges
    double planar = 0.0;    // constraint planes of the other edges (0: none)
    double areaShare = 0.0; // a face weighs its capped area plus this share of its full area
};

template <class VertexType>
class VertexQuadrics
{
public:
    template <class MeshType, class IsFeatureEdge>
    void init(MeshType& m, const QuadricWeights& w, IsFeatureEdge isFeatureEdge)
    {
        base_ = m.vert.empty() ? nullptr : &m.vert[0];
        Quadric zero;
        zero.SetZero();
        quadric_.assign(m.vert.size(), zero);
        area_.assign(m.vert.size(), 0.0f);
        cappedArea_.assign(m.vert.size(), 0.0f);
        areaCap_ = kAreaCapOfMean * meanFaceArea(m);
        for (auto& f : m.face)
            if (!f.IsD())
                addFace(f, w, isFeatureEdge);
    }

    Quadric& quadric(const VertexType* v) { return quadric_[v - base_]; }
    float& area(const VertexType* v) { return area_[v - base_]; }
    const Quadric& quadric(const VertexType* v) const { return quadric_[v - base_]; }
    double area(const VertexType* v) const { return area_[v - base_]; }
    // The capped weights alone (about one per face merged into v): what orders free
    // collapses, which move no plane, so that a large face's share does not hold them back.
    float& cappedArea(const VertexType* v) { return cappedArea_[v - base_]; }
    double cappedArea(const VertexType* v) const { return cappedArea_[v - base_]; }
    // The capped weights of an edge's ends, the same sum wherever it is taken (the lazy
    // bound and the full evaluation must agree to the last bit).
    double cappedArea(const VertexType* v0, const VertexType* v1) const
    {
        return double(cappedArea_[v0 - base_]) + double(cappedArea_[v1 - base_]);
    }

    // v1 survives a collapse of v0 into it.
    void merge(const VertexType* v0, const VertexType* v1)
    {
        quadric(v1) += quadric(v0);
        area(v1) += area(v0);
        cappedArea(v1) += cappedArea(v0);
    }

    // One more plane through v (a tunnel's cap), weighted by `area` as a face's plane is.
    void addPlane(const VertexType* v, const vcg::Point3d& unitNormal, double offset, double area)
    {
        const double capped = std::min(area, areaCap_);
        const double weight = areaCap_ + capped;
        quadric(v) += planeQuadric(unitNormal, offset, weight);
        this->area(v) += weight;
        cappedArea(v) += capped;
    }

    std::size_t bytes() const
    {
        return quadric_.capacity() * sizeof(Quadric) + (area_.capacity() + cappedArea_.capacity()) * sizeof(float);
    }

private:
    // A face's plane weighs one cap (1 % of the mean face area) plus its area up to one
    // more cap, so nearly every plane weighs the same, as in Garland and Heckbert's paper
    // and CGAL. Area weights let the big faces CAD exporters make of flat regions and long
    // strips outweigh the small ones beside them and hide a deviation concentrated there;
    // a cap at a quarter of the mean still does. Without the floor of one cap, the faces of
    // a small fillet or a rounded corner, a hundredth of the mean and less, would weigh next
    // to nothing, and the simplifier would keep the long strips' vertices beside them and
    // coarsen the corner (docs/benchmarks.md).
    static constexpr double kAreaCapOfMean = 0.01;

    template <class MeshType>
    static double meanFaceArea(MeshType& m)
    {
        double total = 0.0;
        int faces = 0;
        for (auto& f : m.face) {
            if (f.IsD())
                continue;
            const double a = detail::faceNormal(f).Norm();  // twice the area
            if (a > 0 && std::isfinite(a)) {
                total += 0.5 * a;
                ++faces;
            }
        }
        return faces ? total / faces : 0.0;
    }

    template <class FaceType, class IsFeatureEdge>
    void addFace(FaceType& f, const QuadricWeights& w, IsFeatureEdge isFeatureEdge)
    {
        vcg::Point3d p[3];
        for (int j = 0; j < 3; ++j)
            p[j] = vcg::Point3d::Construct(f.cP(j));
        vcg::Point3d n = (p[1] - p[0]) ^ (p[2] - p[0]);
        const double doubleArea = n.Norm();
        if (!(doubleArea > 0) || !std::isfinite(doubleArea))
            return;
        n /= doubleArea;
        const double capped = std::min(0.5 * doubleArea, areaCap_);
        const double area = areaCap_ + capped + w.areaShare * 0.5 * doubleArea;
        const Quadric q = planeQuadric(n, n * p[0], area);
        for (int j = 0; j < 3; ++j) {
            quadric(f.V(j)) += q;
            area_[f.V(j) - base_] += area;
            cappedArea_[f.V(j) - base_] += capped;
        }
        for (int j = 0; j < 3; ++j) {
            const double weight = isFeatureEdge(f, j) ? w.feature : w.planar;
            if (weight > 0)
                addEdgePlane(f, p[j], p[(j + 1) % 3], n, weight * std::max(area, 0.0), j);
        }
    }

    template <class FaceType>
    void addEdgePlane(FaceType& f, const vcg::Point3d& a, const vcg::Point3d& b,
                      const vcg::Point3d& faceNormal, double weight, int j)
    {
        const vcg::Point3d e = b - a;
        const double len2 = e.SquaredNorm();
        if (!(len2 > 0))
            return;
        vcg::Point3d n = faceNormal ^ e;
        n.Normalize();
        const Quadric q = planeQuadric(n, n * a, weight);
        quadric(f.V(j)) += q;
        quadric(f.V((j + 1) % 3)) += q;
    }

    const VertexType* base_ = nullptr;
    double areaCap_ = 0.0;
    std::vector<Quadric> quadric_;
    // Sums of weights, in float: 8 bytes a vertex, where the quadrics take 80.
    std::vector<float> cappedArea_;
    std::vector<float> area_;
};

}  // namespace cadlod
