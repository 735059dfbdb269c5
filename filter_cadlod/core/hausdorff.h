// Symmetric Hausdorff distance between two vcglib triangle meshes, sampled the way
// MeshLab's "Hausdorff Distance" filter does: every vertex of the sampled mesh plus
// area-uniform random points on its faces (fixed seed: same meshes, same numbers), each
// measured to the closest point of the other mesh through a uniform grid. Needs no
// normals, marks or adjacency; deleted elements are ignored.
#pragma once

#include <vcg/complex/algorithms/closest.h>
#include <vcg/complex/complex.h>
#include <vcg/space/index/grid_static_ptr.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <vector>

namespace cadlod {

struct HausdorffStats {
    double max = 0.0;   // model units
    double mean = 0.0;
    double rms = 0.0;
    std::size_t samples = 0;
};

struct SymmetricHausdorff {
    HausdorffStats forward;   // samples of A measured to B
    HausdorffStats backward;  // samples of B measured to A
    double diagonal = 0.0;    // bbox diagonal of A
    double max() const { return std::max(forward.max, backward.max); }
    double mean() const
    {
        const std::size_t n = forward.samples + backward.samples;
        return n ? (forward.mean * forward.samples + backward.mean * backward.samples) / n : 0.0;
    }
    double rms() const
    {
        const std::size_t n = forward.samples + backward.samples;
        return n ? std::sqrt((forward.rms * forward.rms * forward.samples +
                              backward.rms * backward.rms * backward.samples) / n)
                 : 0.0;
    }
    double maxFraction() const { return diagonal > 0 ? max() / diagonal : 0.0; }
    double meanFraction() const { return diagonal > 0 ? mean() / diagonal : 0.0; }
};

// Bounding box of the live vertices, in double (null when there are none).
template <class MeshType>
vcg::Box3d liveVertexBox(const MeshType& m)
{
    vcg::Box3d box;
    for (const auto& v : m.vert)
        if (!v.IsD())
            box.Add(vcg::Point3d::Construct(v.cP()));
    return box;
}

template <class MeshType>
double liveDiagonal(const MeshType& m)
{
    const vcg::Box3d box = liveVertexBox(m);
    return box.IsNull() ? 0.0 : box.Diag();
}

namespace detail {

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
inline vcg::Point3d closestOnTriangle(const vcg::Point3d& p, const vcg::Point3d& a, const vcg::Point3d& b,
                                      const vcg::Point3d& c)
{
    const vcg::Point3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab * ap, d2 = ac * ap;
    if (d1 <= 0 && d2 <= 0)
        return a;
    const vcg::Point3d bp = p - b;
    const double d3 = ab * bp, d4 = ac * bp;
    if (d3 >= 0 && d4 <= d3)
        return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return a + ab * (d1 / (d1 - d3));
    const vcg::Point3d cp = p - c;
    const double d5 = ab * cp, d6 = ac * cp;
    if (d6 >= 0 && d5 <= d6)
        return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return a + ac * (d2 / (d2 - d6));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
    const double denom = va + vb + vc;
    if (!(std::abs(denom) > 0))
        return a;
    return a + ab * (vb / denom) + ac * (vc / denom);
}

// A live face as the grid sees it (vcglib's grid would also index deleted faces).
template <class FaceType>
struct FaceRef {
    using ScalarType = typename FaceType::ScalarType;
    FaceType* face;
    typename FaceType::CoordType cP(int j) const { return face->cP(j); }
    bool IsD() const { return false; }
    template <class Box>
    void GetBBox(Box& b) const
    {
        b.Set(cP(0));
        b.Add(cP(1));
        b.Add(cP(2));
    }
};

struct NoMarks {
    void UnMarkAll() const {}
    template <class T> bool IsMarked(T) const { return false; }
    template <class T> void Mark(T) const {}
};

// Grid functor: distance from a point to a face, no face normal needed.
template <class Scalar>
struct TriangleDistance {
    using QueryType = vcg::Point3<Scalar>;
    static const QueryType& Pos(const QueryType& q) { return q; }
    template <class Face>
    bool operator()(const Face& f, const vcg::Point3<Scalar>& p, Scalar& minDist, vcg::Point3<Scalar>& q) const
    {
        const vcg::Point3d pd = vcg::Point3d::Construct(p);
        const vcg::Point3d c = closestOnTriangle(pd, vcg::Point3d::Construct(f.cP(0)),
                                                 vcg::Point3d::Construct(f.cP(1)),
                                                 vcg::Point3d::Construct(f.cP(2)));
        const double d = vcg::Distance(pd, c);
        if (d >= double(minDist))
            return false;
        minDist = Scalar(d);
        q = vcg::Point3<Scalar>::Construct(c);
        return true;
    }
};

template <class MeshType>
std::vector<typename MeshType::FaceType*> liveFaces(MeshType& m)
{
    std::vector<typename MeshType::FaceType*> faces;
    faces.reserve(m.fn);
    for (auto& f : m.face)
        if (!f.IsD())
            faces.push_back(&f);
    return faces;
}

// Closest live face of a mesh to query points.
template <class MeshType>
class ClosestFace
{
public:
    using FaceType = typename MeshType::FaceType;
    using Scalar = typename MeshType::ScalarType;

    // `queries`: where the points to look up lie (empty: near m); the grid's box holds
    // them with a 1 % margin, so that lookups take the grid's fast inside path.
    explicit ClosestFace(MeshType& m, const vcg::Box3d& queries = vcg::Box3d())
    {
        for (auto& f : m.face)
            if (!f.IsD())
                refs_.push_back({&f});
        vcg::Box3d box = queries;
        for (const auto& r : refs_)
            for (int j = 0; j < 3; ++j)
                box.Add(vcg::Point3d::Construct(r.cP(j)));
        const double diag = box.IsNull() ? 1.0 : box.Diag();
        maxDist_ = Scalar(diag * 4 + 1);
        if (refs_.empty())
            return;
        const double margin = 0.01 * diag + 1e-6 * (box.max.Norm() + box.min.Norm()) + 1e-30;
        box.Offset(margin);
        grid_.Set(refs_.begin(), refs_.end(), vcg::Box3<Scalar>::Construct(box));
    }
    bool empty() const { return refs_.empty(); }

    // Closest face (null if none) and the distance to it; points farther than a few
    // diagonals away are reported at that cap.
    FaceType* find(const vcg::Point3d& p, double& distance)
    {
        return find(p, distance, [](const FaceType&) { return true; });
    }

    // The closest of the faces `accept` takes.
    template <class Accept>
    FaceType* find(const vcg::Point3d& p, double& distance, Accept accept)
    {
        distance = maxDist_;
        if (refs_.empty())
            return nullptr;
        Scalar d = maxDist_;
        vcg::Point3<Scalar> q;
        NoMarks marks;
        AcceptedTriangleDistance<Accept> fn{accept};
        FaceRef<FaceType>* r = grid_.GetClosest(fn, marks, offTheFarEdge(vcg::Point3<Scalar>::Construct(p)), maxDist_, d, q);
        distance = d;
        return r ? r->face : nullptr;
    }

    const vcg::Box3<Scalar>& gridBox() const { return grid_.bbox; }

private:
    // vcglib's grid turns a point inside its box into a cell index without clamping it,
    // and float rounding maps a point a few steps below the box's far side one cell past
    // the end (an assertion; a read out of bounds with NDEBUG). Such a point is moved onto
    // the side, i.e. outside, by those few float steps.
    vcg::Point3<Scalar> offTheFarEdge(vcg::Point3<Scalar> p) const
    {
        const vcg::Box3<Scalar>& box = grid_.bbox;
        for (int j = 0; j < 3; ++j) {
            const Scalar band = 8 * std::numeric_limits<Scalar>::epsilon() * (std::abs(box.max[j]) + std::abs(box.min[j]));
            if (p[j] < box.max[j] && p[j] >= box.max[j] - band)
                p[j] = box.max[j];
        }
        return p;
    }

    // TriangleDistance over the faces `accept` takes.
    template <class Accept>
    struct AcceptedTriangleDistance {
        using QueryType = vcg::Point3<Scalar>;
        static const QueryType& Pos(const QueryType& q) { return q; }
        Accept& accept;
        bool operator()(const FaceRef<FaceType>& f, const QueryType& p, Scalar& minDist, QueryType& q) const
        {
            return accept(*f.face) && TriangleDistance<Scalar>()(f, p, minDist, q);
        }
    };

    std::vector<FaceRef<FaceType>> refs_;
    vcg::GridStaticPtr<FaceRef<FaceType>, Scalar> grid_;
    Scalar maxDist_ = 1;
};

}  // namespace detail

// Distances from `faceSamples` area-uniform points on `from` (plus its vertices) to `to`.
// `vertexDistances`, when given, receives the distance of every vertex of `from` (indexed
// like from.vert; deleted vertices get 0).
template <class MeshFrom, class MeshTo>
HausdorffStats oneSidedHausdorff(MeshFrom& from, MeshTo& to, std::size_t faceSamples, unsigned seed = 1,
                                 std::vector<double>* vertexDistances = nullptr)
{
    HausdorffStats s;
    const auto sources = detail::liveFaces(from);
    detail::ClosestFace<MeshTo> closest(to, liveVertexBox(from));
    if (closest.empty() || sources.empty())
        return s;

    double sum = 0.0, sumSquares = 0.0;
    auto measure = [&](const vcg::Point3d& p) {
        double d = 0;
        closest.find(p, d);
        s.max = std::max(s.max, d);
        sum += d;
        sumSquares += d * d;
        ++s.samples;
        return d;
    };

    if (vertexDistances)
        vertexDistances->assign(from.vert.size(), 0.0);
    for (std::size_t i = 0; i < from.vert.size(); ++i)
        if (!from.vert[i].IsD()) {
            const double d = measure(vcg::Point3d::Construct(from.vert[i].cP()));
            if (vertexDistances)
                (*vertexDistances)[i] = d;
        }

    std::vector<double> cumulativeArea;
    cumulativeArea.reserve(sources.size());
    double total = 0.0;
    for (auto* f : sources) {
        const vcg::Point3d a = vcg::Point3d::Construct(f->cP(0));
        total += 0.5 * ((vcg::Point3d::Construct(f->cP(1)) - a) ^ (vcg::Point3d::Construct(f->cP(2)) - a)).Norm();
        cumulativeArea.push_back(total);
    }
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::size_t i = 0; i < faceSamples && total > 0; ++i) {
        const double pick = unit(rng) * total;
        const std::size_t k = std::min(sources.size() - 1,
                                       std::size_t(std::lower_bound(cumulativeArea.begin(), cumulativeArea.end(), pick) -
                                                   cumulativeArea.begin()));
        double u = unit(rng), v = unit(rng);
        if (u + v > 1) {
            u = 1 - u;
            v = 1 - v;
        }
        const vcg::Point3d a = vcg::Point3d::Construct(sources[k]->cP(0));
        const vcg::Point3d b = vcg::Point3d::Construct(sources[k]->cP(1));
        const vcg::Point3d c = vcg::Point3d::Construct(sources[k]->cP(2));
        measure(a + (b - a) * u + (c - a) * v);
    }
    s.mean = s.samples ? sum / double(s.samples) : 0.0;
    s.rms = s.samples ? std::sqrt(sumSquares / double(s.samples)) : 0.0;
    return s;
}

// Both directions; fractions are of A's bounding-box diagonal.
template <class MeshA, class MeshB>
SymmetricHausdorff symmetricHausdorff(MeshA& a, MeshB& b, std::size_t faceSamplesPerSide)
{
    SymmetricHausdorff h;
    h.forward = oneSidedHausdorff(a, b, faceSamplesPerSide, 1);
    h.backward = oneSidedHausdorff(b, a, faceSamplesPerSide, 2);
    h.diagonal = liveDiagonal(a);
    return h;
}

}  // namespace cadlod
