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

#include "mesh/crease_fans.h"
#include "measure/hausdorff.h"
#include "measure/triangle_tree.h"

#include <vcg/complex/complex.h>

#include <cstddef>
#include <cstdint>
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

// A point on a mesh: its face (index into mesh.face) and the weights of the face's corners
// 1 and 2.
using SurfacePoint = SurfacePick;

// `count` area-uniform points on the live faces of m (areaUniformPicks), with their faces'
// indices into m.face.
template <class MeshType>
std::vector<SurfacePoint> surfacePoints(const MeshType& m, std::size_t count, unsigned seed)
{
    const auto faces = liveFaces(m);
    std::vector<SurfacePoint> points = areaUniformPicks(faces, count, seed);
    for (SurfacePoint& p : points)
        p.face = std::size_t(faces[p.face] - &m.face[0]);
    return points;
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

// The input's side of the measure, prepared once for every result measured against it:
// its smooth fans, its points, and `closest`, the index of its faces (a Hausdorff
// measure's, built once too).
template <class MeshA>
struct ShadingInput {
    ShadingInput(MeshA& m, const detail::ClosestFace<MeshA>& closest, std::size_t samplesPerSide, unsigned seed)
        : mesh(m), fans(m), closest(closest), points(detail::surfacePoints(m, samplesPerSide, seed)),
          samplesPerSide(samplesPerSide), resultSeed(seed + 1)
    {
    }
    MeshA& mesh;
    CreaseFans fans;
    const detail::ClosestFace<MeshA>& closest;
    std::vector<detail::SurfacePoint> points;
    std::size_t samplesPerSide;
    unsigned resultSeed;  // the seed of the points on a result
};

// The shading deviation between the input and `result` (`toResult` indexes its faces), a
// normal counting as visibly changed past `visibleChange`.
template <class MeshA, class MeshB>
ShadingDeviation shadingDeviation(const ShadingInput<MeshA>& input, MeshB& result,
                                  const detail::ClosestFace<MeshB>& toResult,
                                  double visibleChange = kVisibleNormalChange)
{
    const CreaseFans resultFans(result);
    const auto onResult = detail::surfacePoints(result, input.samplesPerSide, input.resultSeed);
    ShadingDeviation d;
    d.samples = input.points.size() + onResult.size();
    d.turned = detail::visiblyDifferent(input.mesh, input.fans, input.points, result, resultFans, toResult,
                                        visibleChange) +
               detail::visiblyDifferent(result, resultFans, onResult, input.mesh, input.fans, input.closest,
                                        visibleChange);
    return d;
}

}  // namespace cadlod
