// Shading deviation: the share of a simplified surface a viewer sees lit differently from
// its input, measured without rendering. A renderer lights a point from the normal its
// triangle interpolates between its corners' smooth-fan normals (crease_fans.h: split at
// creases above 30°, as VRML's creaseAngle, the OpenFlight export and the bench's shading
// measure do). Points spread evenly over each surface are matched to the closest point of
// the other one, and a point counts when the two interpolated normals differ by more than
// kVisibleNormalChange: for a unit light, the change in diffuse intensity is at most the
// length of the normals' difference, and a key light at 0.75 changes the 0..255 intensity
// by more than 8 (what the bench calls visible) once that length passes about 0.04 with the
// light square to it. Both directions count, so a facet missing from either side does.
// The Hausdorff distance says how far a result strays; this says how much of it looks it.
#pragma once

#include "crease_fans.h"
#include "hausdorff.h"
#include "triangle_tree.h"

#include <vcg/complex/complex.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace cadlod {

// Length of the difference of two unit normals (about the angle between them, in radians)
// above which their shading counts as visibly different.
inline constexpr double kVisibleNormalChange = 0.06;

struct ShadingDeviation {
    std::size_t samples = 0;  // points measured, both directions
    std::size_t turned = 0;   // of which lit visibly differently
    double share() const { return samples ? double(turned) / double(samples) : 0.0; }
};

namespace detail {

// A point on a mesh: its face and the weights of the face's corners 1 and 2.
struct SurfacePoint {
    std::size_t face = 0;  // index into mesh.face
    double u = 0, v = 0;
    std::uint32_t order = 0;  // along the face (groupedByFace)
};

// `count` area-uniform points on the live faces of m, face by face (lookups in a row near
// each other are fast); a fixed seed gives the same points for the same mesh.
template <class MeshType>
std::vector<SurfacePoint> surfacePoints(const MeshType& m, std::size_t count, unsigned seed)
{
    std::vector<std::size_t> faces;
    std::vector<double> cumulativeArea;
    double total = 0.0;
    for (std::size_t i = 0; i < m.face.size(); ++i) {
        if (m.face[i].IsD())
            continue;
        total += 0.5 * vcg::Point3d::Construct(vcg::TriangleNormal(m.face[i])).Norm();
        faces.push_back(i);
        cumulativeArea.push_back(total);
    }
    std::vector<SurfacePoint> picks;
    if (!(total > 0))
        return picks;
    const AreaGuide faceAt(cumulativeArea);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    picks.reserve(count);
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t k = std::min(faces.size() - 1, faceAt(unit(rng) * total));
        double u = unit(rng), v = unit(rng);
        if (u + v > 1) {
            u = 1 - u;
            v = 1 - v;
        }
        picks.push_back({k, u, v, mortonOrder(u, v)});
    }
    picks = groupedByFace(picks, faces.size());
    for (SurfacePoint& p : picks)
        p.face = faces[p.face];
    return picks;
}

template <class FaceType>
TriangleTree::Triangle triangleOf(const FaceType& f)
{
    return {vcg::Point3d::Construct(f.cP(0)), vcg::Point3d::Construct(f.cP(1)), vcg::Point3d::Construct(f.cP(2))};
}

// The normal a renderer lights the point with weights w (of corners 0, 1, 2) of `face` with.
inline vcg::Point3d smoothNormalAt(const CreaseFans& fans, std::size_t face, const vcg::Point3d& w)
{
    vcg::Point3d n(0, 0, 0);
    for (int k = 0; k < 3; ++k)
        n += vcg::Point3d::Construct(fans.normal(fans.fanOf(face, k))) * w[k];
    const double length = n.Norm();
    return length > 0 ? n / length : n;
}

// How many of `points` on `from` are lit visibly differently from the closest point of the
// mesh `closest` indexes (`to`).
template <class MeshFrom, class MeshTo>
std::size_t visiblyDifferent(const MeshFrom& from, const CreaseFans& fromFans, const std::vector<SurfacePoint>& points,
                             const MeshTo& to, const CreaseFans& toFans, const ClosestFace<MeshTo>& closest,
                             double visibleChange)
{
    std::size_t count = 0;
    std::int64_t hint = -1;
    for (const SurfacePoint& s : points) {
        const vcg::Point3d w(1 - s.u - s.v, s.u, s.v);
        const TriangleTree::Triangle t = triangleOf(from.face[s.face]);
        const vcg::Point3d p = t[0] * w[0] + t[1] * w[1] + t[2] * w[2];
        double distance = 0.0;
        const auto* g = closest.find(p, distance, hint);
        if (!g)
            continue;
        const std::size_t gi = std::size_t(g - &to.face[0]);
        const vcg::Point3d wg = TriangleTree::closestWeights(triangleOf(*g), p);
        const vcg::Point3d change = smoothNormalAt(fromFans, s.face, w) - smoothNormalAt(toFans, gi, wg);
        count += change.Norm() > visibleChange;
    }
    return count;
}

}  // namespace detail

// The shading deviation between `input` and `result`, `samplesPerSide` points on each, a
// normal counting as visibly changed past `visibleChange`. `toInput` indexes `input` (built
// once when several results are measured against it).
template <class MeshA, class MeshB>
ShadingDeviation shadingDeviation(MeshA& input, const detail::ClosestFace<MeshA>& toInput, MeshB& result,
                                  std::size_t samplesPerSide, unsigned seed,
                                  double visibleChange = kVisibleNormalChange)
{
    const CreaseFans inputFans(input), resultFans(result);
    const detail::ClosestFace<MeshB> toResult(result);
    const auto onInput = detail::surfacePoints(input, samplesPerSide, seed);
    const auto onResult = detail::surfacePoints(result, samplesPerSide, seed + 1);
    ShadingDeviation d;
    d.samples = onInput.size() + onResult.size();
    d.turned = detail::visiblyDifferent(input, inputFans, onInput, result, resultFans, toResult, visibleChange) +
               detail::visiblyDifferent(result, resultFans, onResult, input, inputFans, toInput, visibleChange);
    return d;
}

}  // namespace cadlod
