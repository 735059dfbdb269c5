// Measures of a simplified mesh against its original, shared by the simplifier's tests
// and benchmarks: folded faces, non-manifold edges, boundary edges.
#pragma once

#include "measure/hausdorff.h"

#include <vcg/complex/complex.h>
#include <vcg/space/index/grid_static_ptr.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

namespace cadlod::test {

// Edges (as sorted vertex-index pairs) of live faces, with how many faces use each.
template <class MeshType>
std::vector<std::pair<std::pair<int, int>, int>> edgeUse(const MeshType& m)
{
    std::vector<std::pair<int, int>> edges;
    for (const auto& f : m.face)
        if (!f.IsD())
            for (int j = 0; j < 3; ++j) {
                int a = int(f.cV(j) - &m.vert[0]), b = int(f.cV((j + 1) % 3) - &m.vert[0]);
                edges.push_back({std::min(a, b), std::max(a, b)});
            }
    std::sort(edges.begin(), edges.end());
    std::vector<std::pair<std::pair<int, int>, int>> use;
    for (const auto& e : edges) {
        if (!use.empty() && use.back().first == e)
            ++use.back().second;
        else
            use.push_back({e, 1});
    }
    return use;
}

template <class MeshType>
int nonManifoldEdges(const MeshType& m)
{
    int n = 0;
    for (const auto& e : edgeUse(m))
        n += e.second > 2;
    return n;
}

template <class MeshType>
int boundaryEdgeCount(const MeshType& m)
{
    int n = 0;
    for (const auto& e : edgeUse(m))
        n += e.second == 1;
    return n;
}

template <class FaceType>
vcg::Point3d unitNormal(const FaceType& f)
{
    const vcg::Point3d a = vcg::Point3d::Construct(f.cP(0));
    vcg::Point3d n = (vcg::Point3d::Construct(f.cP(1)) - a) ^ (vcg::Point3d::Construct(f.cP(2)) - a);
    const double len = n.Norm();
    return len > 0 ? n / len : vcg::Point3d(0, 0, 0);
}

// Faces of `result` whose normal turns more than `limitDeg` away from the original face
// closest to their centroid (degenerate faces count as folded). Where input surfaces touch
// (a chip standing on a board: two faces at the same distance, facing opposite ways), the
// nearest face is the best-aligned of those within a 1e-5 diagonal tie: a face lying on
// both is not turned away from the surface it follows. A face turned exactly `limitDeg`
// (a chip lead's top beside its side wall, both axis-aligned: a dot product of exactly 0)
// is not turned more: the cosine gets a rounding margin, as cos(pi/2) is 6e-17, not 0.
template <class MeshResult, class MeshOriginal>
int foldedFaces(MeshResult& result, MeshOriginal& original, double limitDeg = 90.0)
{
    cadlod::detail::ClosestFace<MeshOriginal> closest(original);
    if (closest.empty())
        return 0;
    const double cosLimit = std::cos(limitDeg * M_PI / 180.0) - 1e-12;
    const double tie = 1e-5 * cadlod::liveDiagonal(original);
    int folded = 0;
    for (auto& f : result.face) {
        if (f.IsD())
            continue;
        const vcg::Point3d n = unitNormal(f);
        if (n.SquaredNorm() == 0) {
            ++folded;
            continue;
        }
        const vcg::Point3d centroid = vcg::Point3d::Construct((f.cP(0) + f.cP(1) + f.cP(2)) / 3);
        double nearest = 0, aligned = 0;
        closest.find(centroid, nearest);
        const auto* match = closest.find(centroid, aligned,
                                         [&](const auto& g) { return n * unitNormal(g) >= cosLimit; });
        if (!match || aligned > nearest + tie)
            ++folded;
    }
    return folded;
}

// The mesh as vertex positions and faces by vertex index, live elements only.
struct Snapshot {
    std::vector<vcg::Point3f> points;
    std::vector<std::array<int, 3>> faces;
    bool operator==(const Snapshot& o) const { return points == o.points && faces == o.faces; }
};

template <class MeshType>
Snapshot snapshot(const MeshType& m)
{
    Snapshot s;
    std::vector<int> index(m.vert.size(), -1);
    for (std::size_t i = 0; i < m.vert.size(); ++i)
        if (!m.vert[i].IsD()) {
            index[i] = int(s.points.size());
            s.points.push_back(vcg::Point3f::Construct(m.vert[i].cP()));
        }
    for (const auto& f : m.face)
        if (!f.IsD())
            s.faces.push_back({index[std::size_t(f.cV(0) - &m.vert[0])], index[std::size_t(f.cV(1) - &m.vert[0])],
                               index[std::size_t(f.cV(2) - &m.vert[0])]});
    return s;
}

// Every live face's vertices point back at it through their VF lists, and the lists hold
// live faces only.
template <class MeshType>
bool vfAdjacencyConsistent(MeshType& m)
{
    using FaceType = typename MeshType::FaceType;
    for (auto& f : m.face) {
        if (f.IsD())
            continue;
        for (int j = 0; j < 3; ++j) {
            bool found = false;
            for (vcg::face::VFIterator<FaceType> x(f.V(j)); !x.End(); ++x) {
                if (x.F()->IsD())
                    return false;
                found |= x.F() == &f && x.I() == j;
            }
            if (!found)
                return false;
        }
    }
    return true;
}

}  // namespace cadlod::test
