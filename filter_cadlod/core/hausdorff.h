// Symmetric Hausdorff distance between two vcglib triangle meshes, sampled the way
// MeshLab's "Hausdorff Distance" filter does: every vertex of the sampled mesh plus
// area-uniform random points on its faces (fixed seed: same meshes, same numbers), each
// measured to the closest point of the other mesh through a uniform grid. Needs no
// normals, marks or adjacency; deleted elements are ignored.
#pragma once

#include "triangle_tree.h"

#include <vcg/complex/complex.h>

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

// Closest live face of a mesh to query points (a TriangleTree over its faces).
template <class MeshType>
class ClosestFace
{
public:
    using FaceType = typename MeshType::FaceType;

    explicit ClosestFace(MeshType& m) : faces_(liveFaces(m)), tree_(triangles(faces_))
    {
        for (const FaceType* f : faces_)
            for (int j = 0; j < 3; ++j)
                bounds_.Add(vcg::Point3d::Construct(f->cP(j)));
        maxDist_ = bounds_.IsNull() ? 1.0 : 4.0 * bounds_.Diag() + 1.0;
    }
    bool empty() const { return faces_.empty(); }
    // The box of the indexed faces.
    const vcg::Box3d& bounds() const { return bounds_; }

    // Closest face (null if none) and the distance to it; points farther than a few
    // diagonals away are reported at that cap.
    FaceType* find(const vcg::Point3d& p, double& distance) const
    {
        const std::int64_t i = tree_.closest(p, maxDist_, distance);
        return i >= 0 ? faces_[std::size_t(i)] : nullptr;
    }

    // The same, searching only for faces closer than `hint` (a face near p, e.g. the one
    // found for the point before): nearby lookups in a row prune most of the tree.
    FaceType* find(const vcg::Point3d& p, double& distance, std::int64_t& hint) const
    {
        if (hint < 0 || std::size_t(hint) >= faces_.size()) {
            hint = tree_.closest(p, maxDist_, distance);
        } else {
            const double bound = tree_.distance(std::size_t(hint), p);
            const std::int64_t i = tree_.closest(p, bound * (1 + 1e-12) + 1e-300, distance);
            if (i >= 0)
                hint = i;
            else
                distance = bound;
        }
        return hint >= 0 ? faces_[std::size_t(hint)] : nullptr;
    }

    // The closest of the faces `accept` takes.
    template <class Accept>
    FaceType* find(const vcg::Point3d& p, double& distance, Accept accept) const
    {
        const std::int64_t i =
            tree_.closest(p, maxDist_, distance, [&](std::size_t k) { return accept(*faces_[k]); });
        return i >= 0 ? faces_[std::size_t(i)] : nullptr;
    }

private:
    static std::vector<TriangleTree::Triangle> triangles(const std::vector<FaceType*>& faces)
    {
        std::vector<TriangleTree::Triangle> t(faces.size());
        for (std::size_t i = 0; i < faces.size(); ++i)
            for (int j = 0; j < 3; ++j)
                t[i][std::size_t(j)] = vcg::Point3d::Construct(faces[i]->cP(j));
        return t;
    }

    std::vector<FaceType*> faces_;
    TriangleTree tree_;
    vcg::Box3d bounds_;
    double maxDist_ = 1.0;
};

}  // namespace detail

// Distances from `faceSamples` area-uniform points on `from` (plus its vertices) to `to`.
// `vertexDistances`, when given, receives the distance of every vertex of `from` (indexed
// like from.vert; deleted vertices get 0).
// `closest` is an index of `to` (detail::ClosestFace), built once when many meshes are
// measured against the same one.
template <class MeshFrom, class MeshTo>
HausdorffStats oneSidedHausdorff(MeshFrom& from, detail::ClosestFace<MeshTo>& closest, std::size_t faceSamples,
                                 unsigned seed = 1, std::vector<double>* vertexDistances = nullptr)
{
    HausdorffStats s;
    const auto sources = detail::liveFaces(from);
    if (closest.empty() || sources.empty())
        return s;

    double sum = 0.0, sumSquares = 0.0;
    std::int64_t hint = -1;
    auto measure = [&](const vcg::Point3d& p) {
        double d = 0;
        closest.find(p, d, hint);
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
    // Random points, measured face by face: neighbouring lookups in a row are fast.
    struct Sample {
        std::size_t face;
        double u, v;
    };
    std::vector<Sample> picks;
    picks.reserve(total > 0 ? faceSamples : 0);
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
        picks.push_back({k, u, v});
    }
    std::stable_sort(picks.begin(), picks.end(), [](const Sample& x, const Sample& y) { return x.face < y.face; });
    for (const Sample& sample : picks) {
        const auto* f = sources[sample.face];
        const vcg::Point3d a = vcg::Point3d::Construct(f->cP(0));
        const vcg::Point3d b = vcg::Point3d::Construct(f->cP(1));
        const vcg::Point3d c = vcg::Point3d::Construct(f->cP(2));
        measure(a + (b - a) * sample.u + (c - a) * sample.v);
    }
    s.mean = s.samples ? sum / double(s.samples) : 0.0;
    s.rms = s.samples ? std::sqrt(sumSquares / double(s.samples)) : 0.0;
    return s;
}

template <class MeshFrom, class MeshTo>
HausdorffStats oneSidedHausdorff(MeshFrom& from, MeshTo& to, std::size_t faceSamples, unsigned seed = 1,
                                 std::vector<double>* vertexDistances = nullptr)
{
    detail::ClosestFace<MeshTo> closest(to);
    return oneSidedHausdorff(from, closest, faceSamples, seed, vertexDistances);
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
