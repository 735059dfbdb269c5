// The smooth fans of a mesh's vertices: around a vertex, the faces that meet it with no
// crease between them, each fan with its own normal.
//
// A renderer lights a triangle from its vertices' normals. Where a vertex sits on a crease
// (a box's corner, the rim of a drilled hole) one shared normal averages the faces on both
// sides, and the crease is drawn as a soft gradient; VRML's creaseAngle and the shading
// measure (bench/shading) give such a vertex one normal per fan instead. Two faces sharing
// a manifold edge are in one fan when their normals differ by at most the crease angle; the
// fan's normal is the area-weighted sum of its faces' normals. Welded meshes (the importer
// welds coincident points, and the simplifier keeps them welded) need this at export: the
// OpenFlight writer gives a vertex with several fans one vertex record per fan, and the
// simplifier's plane-weight trials (core/shading_deviation.h) compare a result's shading
// with its input's through them.
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

namespace cadlod {

class CreaseFans
{
public:
    static constexpr double kCreaseDegrees = 30.0;  // VRML creaseAngle 0.5236, the shading measure's

    template <class Mesh>
    explicit CreaseFans(const Mesh& m, double creaseDegrees = kCreaseDegrees)
    {
        const std::size_t corners = 3 * m.face.size();
        parent_.resize(corners);
        std::iota(parent_.begin(), parent_.end(), 0u);
        joinAcrossSmoothEdges(m, std::cos(creaseDegrees * M_PI / 180.0));
        pointEveryCornerAtItsRoot();
        sumFanNormals(m);
        countFansPerVertex(m);
    }

    // The fan of corner k of face f (an id shared by the corners of one fan). Only reads:
    // threads may share the fans (the simplifier's weight trials run two at a time).
    std::uint32_t fanOf(std::size_t face, int k) const { return parent_[3 * face + std::size_t(k)]; }
    // The fan's unit normal (zero where its faces have no area).
    vcg::Point3f normal(std::uint32_t fan) const { return fanNormal_[fan]; }
    // Whether the vertex has more than one fan: it sits on a crease.
    bool onCrease(std::size_t vertex) const { return vertex < fans_.size() && fans_[vertex] > 1; }

private:
    template <class Mesh>
    static bool usable(const typename Mesh::FaceType& f)
    {
        return !f.IsD() && f.cV(0) != f.cV(1) && f.cV(1) != f.cV(2) && f.cV(0) != f.cV(2);
    }

    std::uint32_t root(std::uint32_t x)
    {
        while (parent_[x] != x) {
            parent_[x] = parent_[parent_[x]];  // path halving
            x = parent_[x];
        }
        return x;
    }
    // Once the fans are joined: every corner's parent is its fan's id.
    void pointEveryCornerAtItsRoot()
    {
        for (std::uint32_t x = 0; x < std::uint32_t(parent_.size()); ++x)
            parent_[x] = root(x);
    }
    void unite(std::uint32_t a, std::uint32_t b)
    {
        a = root(a);
        b = root(b);
        if (a != b)
            parent_[std::max(a, b)] = std::min(a, b);
    }

    // Each manifold edge whose two faces turn by no more than the crease angle joins the
    // corners of its two ends on both sides.
    template <class Mesh>
    void joinAcrossSmoothEdges(const Mesh& m, double cosCrease)
    {
        struct EdgeUse {
            std::uint64_t key;
            std::uint32_t face;
            std::uint8_t corner;  // the edge runs from this corner to the next
        };
        std::vector<EdgeUse> edges;
        for (std::size_t i = 0; i < m.face.size(); ++i) {
            if (!usable<Mesh>(m.face[i]))
                continue;
            for (int k = 0; k < 3; ++k) {
                const std::uint64_t a = vcg::tri::Index(m, m.face[i].cV(k));
                const std::uint64_t b = vcg::tri::Index(m, m.face[i].cV((k + 1) % 3));
                edges.push_back({std::min(a, b) << 32 | std::max(a, b), std::uint32_t(i), std::uint8_t(k)});
            }
        }
        std::sort(edges.begin(), edges.end(), [](const EdgeUse& x, const EdgeUse& y) { return x.key < y.key; });
        for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
            const bool manifold = edges[i].key == edges[i + 1].key &&
                                  (i + 2 >= edges.size() || edges[i + 2].key != edges[i].key) &&
                                  (i == 0 || edges[i - 1].key != edges[i].key);
            if (!manifold)
                continue;
            const EdgeUse& e = edges[i];
            const EdgeUse& g = edges[i + 1];
            const auto& fe = m.face[e.face];
            const auto& fg = m.face[g.face];
            vcg::Point3d ne = vcg::Point3d::Construct(vcg::TriangleNormal(fe));
            vcg::Point3d ng = vcg::Point3d::Construct(vcg::TriangleNormal(fg));
            const double lengths = ne.Norm() * ng.Norm();
            if (!(lengths > 0) || ne * ng < cosCrease * lengths)
                continue;
            for (int end = 0; end < 2; ++end) {
                const auto* v = fe.cV((e.corner + end) % 3);
                unite(3 * e.face + std::uint32_t((e.corner + end) % 3), cornerOf(fg, g.face, v));
            }
        }
    }

    template <class Face, class Vertex>
    static std::uint32_t cornerOf(const Face& f, std::uint32_t face, const Vertex* v)
    {
        for (int k = 0; k < 3; ++k)
            if (f.cV(k) == v)
                return 3 * face + std::uint32_t(k);
        return 3 * face;  // not reached: the edge's ends are corners of both faces
    }

    template <class Mesh>
    void sumFanNormals(const Mesh& m)
    {
        std::vector<vcg::Point3d> sum(parent_.size(), vcg::Point3d(0, 0, 0));
        for (std::size_t i = 0; i < m.face.size(); ++i)
            if (usable<Mesh>(m.face[i]))
                for (int k = 0; k < 3; ++k)
                    sum[fanOf(i, k)] += vcg::Point3d::Construct(vcg::TriangleNormal(m.face[i]));
        fanNormal_.assign(parent_.size(), vcg::Point3f(0, 0, 0));
        for (std::size_t c = 0; c < sum.size(); ++c)
            if (sum[c].Norm() > 0)
                fanNormal_[c] = vcg::Point3f::Construct(sum[c] / sum[c].Norm());
    }

    template <class Mesh>
    void countFansPerVertex(const Mesh& m)
    {
        std::vector<std::uint32_t> firstFan(m.vert.size(), UINT32_MAX);
        fans_.assign(m.vert.size(), 0);
        for (std::size_t i = 0; i < m.face.size(); ++i) {
            if (!usable<Mesh>(m.face[i]))
                continue;
            for (int k = 0; k < 3; ++k) {
                const std::size_t v = vcg::tri::Index(m, m.face[i].cV(k));
                const std::uint32_t fan = fanOf(i, k);
                if (firstFan[v] == UINT32_MAX) {
                    firstFan[v] = fan;
                    fans_[v] = 1;
                } else if (firstFan[v] != fan) {
                    fans_[v] = 2;  // more than one: all that is asked
                }
            }
        }
    }

    std::vector<std::uint32_t> parent_;  // per corner (3 × face index + k): union-find
    std::vector<vcg::Point3f> fanNormal_;  // per fan root
    std::vector<std::uint8_t> fans_;     // per vertex: 0, 1 or 2 (two or more)
};

}  // namespace cadlod
