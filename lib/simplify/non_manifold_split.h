// Cutting a mesh apart along its non-manifold edges before it is simplified (a LOD chain's
// levels, a simplification toward a target; not with SimplifyParams::relaxToReachTarget off).
//
// An edge shared by three or more faces (a fin welded around a tube, a cap fanned over a
// rim it overlaps, two boxes welded where their edges meet) locks both its vertices for
// good (feature_edges.h): no collapse at such an edge keeps its faces consistent. A model
// with thousands of them (a hand-modelled room, a robot's welded castings) keeps every
// face around them in every level of its chain, however far it is seen from, and reaches
// a face target only by removing whole parts. A level is held to a measured distance and a
// simplification to its error, not to the input's topology, so each such edge keeps the
// two faces that continue each other (the pair that runs the edge in
// opposite directions, of one part if any, whose normals agree most: the tube under the
// fin) and lets go of the others. Around each vertex the faces joined across kept edges
// form fans, and every fan but the first gets a copy of the vertex of its own. Each let-go
// face's edge becomes a boundary, which has its boundary quadrics (a feature that gives
// way only where the level's budget allows it); the pieces stay one touch group for
// whole-part removals (component_removal.h). An edge whose faces still meet around both
// its ends (joined the long way round), or that holds a face twice (the same three
// vertices), stays as it was, locked.
#pragma once

#include "mesh/layer_metadata.h"
#include "simplify/simplify_params.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace cadlod {

struct NonManifoldSplit {
    int edges = 0;         // edges with three faces or more before the cut
    int vertexCopies = 0;  // vertices added
    int edgesLeft = 0;     // of those edges, still non-manifold after it
};

namespace detail {

// One face around a vertex: the face's index and the vertex's corner in it.
struct FaceCorner {
    std::size_t face;
    int corner;
};

inline std::size_t rootOf(std::vector<std::size_t>& parent, std::size_t x)
{
    while (parent[x] != x)
        x = parent[x] = parent[parent[x]];
    return x;
}

// The faces around `v` (none that repeats a vertex) into `around`, and the other end of
// each of their two edges at `v` into `ends`, sorted, each with the face's position in
// `around`.
template <class MeshType>
void facesAround(MeshType& m, typename MeshType::VertexType& v, std::vector<FaceCorner>& around,
                 std::vector<std::pair<typename MeshType::VertexType*, std::size_t>>& ends)
{
    around.clear();
    ends.clear();
    for (vcg::face::VFIterator<typename MeshType::FaceType> vfi(&v); !vfi.End(); ++vfi) {
        auto* f = vfi.F();
        if (f->V(0) == f->V(1) || f->V(1) == f->V(2) || f->V(2) == f->V(0))
            continue;
        const int z = vfi.I();
        ends.push_back({f->V((z + 1) % 3), around.size()});
        ends.push_back({f->V((z + 2) % 3), around.size()});
        around.push_back({std::size_t(f - &m.face[0]), z});
    }
    std::sort(ends.begin(), ends.end());
}

// Calls `edge(i, j)` for each edge at a vertex: the run ends[i, j) of its faces (`ends` as
// facesAround sorts them, by the edge's other end).
template <class End, class EdgeRun>
void forEachEdgeRun(const std::vector<End>& ends, const EdgeRun& edge)
{
    for (std::size_t i = 0; i < ends.size();) {
        std::size_t j = i + 1;
        while (j < ends.size() && ends[j].first == ends[i].first)
            ++j;
        edge(i, j);
        i = j;
    }
}

// Of the faces `faces` (indices into m.face, sorted) around the edge from `a` to `b`, the
// two that continue each other, as positions in `faces`; {0, 0} when no two run the edge
// in opposite directions. The same whichever end asks, so both ends keep the same pair.
template <class MeshType>
std::pair<std::size_t, std::size_t> continuingPair(MeshType& m, const std::vector<std::size_t>& faces,
                                                   const typename MeshType::VertexType* a,
                                                   const typename MeshType::VertexType* b)
{
    if (a > b)
        std::swap(a, b);  // one direction for both ends
    auto forward = [&](std::size_t f) {
        const auto& face = m.face[f];
        for (int k = 0; k < 3; ++k)
            if (face.cV(k) == a && face.cV((k + 1) % 3) == b)
                return true;
        return false;
    };
    const bool parts = hasParts(m);
    auto partOf = parts ? facePartHandle(m) : typename MeshType::template PerFaceAttributeHandle<int>();
    std::pair<std::size_t, std::size_t> best{0, 0};
    double bestScore = -1e300;
    for (std::size_t i = 0; i < faces.size(); ++i)
        for (std::size_t j = i + 1; j < faces.size(); ++j) {
            const auto& f = m.face[faces[i]];
            const auto& g = m.face[faces[j]];
            if (forward(faces[i]) == forward(faces[j]))
                continue;
            const double agree = double(vcg::NormalizedTriangleNormal(f) * vcg::NormalizedTriangleNormal(g));
            const double score = agree + (parts && partOf[f] == partOf[g] ? 4.0 : 0.0);
            if (score > bestScore) {
                bestScore = score;
                best = {i, j};
            }
        }
    return best;
}

// True if two of `faces` (indices into m.face) have the same three vertices: a surface
// written twice (both sides of a sheet, a part exported twice). A twin cut off would stay
// where it is, over the surface its other half simplifies away from.
template <class MeshType>
bool holdsTwins(MeshType& m, const std::vector<std::size_t>& faces)
{
    std::vector<std::array<const void*, 3>> corners;
    for (std::size_t f : faces) {
        std::array<const void*, 3> c{m.face[f].cV(0), m.face[f].cV(1), m.face[f].cV(2)};
        std::sort(c.begin(), c.end());
        corners.push_back(c);
    }
    std::sort(corners.begin(), corners.end());
    return std::adjacent_find(corners.begin(), corners.end()) != corners.end();
}

// The fans around `v`: per face in `around`, the root of its fan in `parent`. True if some
// edge at `v` has three faces or more (counted in `edges` when `v` is its lower end).
template <class MeshType>
bool fansAround(MeshType& m, typename MeshType::VertexType& v, const std::vector<FaceCorner>& around,
                const std::vector<std::pair<typename MeshType::VertexType*, std::size_t>>& ends,
                std::vector<std::size_t>& parent, int& edges)
{
    parent.resize(around.size());
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    auto join = [&](std::size_t x, std::size_t y) { parent[rootOf(parent, x)] = rootOf(parent, y); };
    bool nonManifold = false;
    std::vector<std::size_t> faces;
    forEachEdgeRun(ends, [&](std::size_t i, std::size_t j) {
        if (j - i == 2) {
            join(ends[i].second, ends[i + 1].second);
        } else if (j - i > 2) {
            nonManifold = true;
            edges += ends[i].first > &v;
            // The edge's faces by index, as the other end sees them too.
            std::vector<std::size_t> byFace(j - i);
            std::iota(byFace.begin(), byFace.end(), i);
            auto faceOf = [&](std::size_t e) { return around[ends[e].second].face; };
            std::sort(byFace.begin(), byFace.end(), [&](std::size_t x, std::size_t y) { return faceOf(x) < faceOf(y); });
            faces.clear();
            for (std::size_t e : byFace)
                faces.push_back(faceOf(e));
            if (holdsTwins(m, faces)) {  // one surface written twice: cutting frees neither
                for (std::size_t k = i + 1; k < j; ++k)
                    join(ends[i].second, ends[k].second);
            } else if (const auto [p, q] = continuingPair(m, faces, &v, ends[i].first); p != q) {
                join(ends[byFace[p]].second, ends[byFace[q]].second);
            }
        }
    });
    return nonManifold;
}

}  // namespace detail

// Cuts `m` apart along its non-manifold edges as described above (its VF adjacency is
// rebuilt, before and after).
template <class MeshType>
NonManifoldSplit splitNonManifoldEdges(MeshType& m)
{
    using VertexType = typename MeshType::VertexType;
    vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    NonManifoldSplit result;
    struct Copy {
        std::size_t vertex;                   // the vertex copied
        std::vector<detail::FaceCorner> fan;  // the faces that take the copy
    };
    std::vector<Copy> copies;
    std::vector<detail::FaceCorner> around;
    std::vector<std::pair<VertexType*, std::size_t>> ends;
    std::vector<std::size_t> parent;
    for (VertexType& v : m.vert) {
        if (v.IsD())
            continue;
        detail::facesAround(m, v, around, ends);
        if (!detail::fansAround(m, v, around, ends, parent, result.edges))
            continue;
        // The fan of the first face keeps the vertex; every other fan gets a copy.
        const std::size_t kept = detail::rootOf(parent, 0);
        std::vector<std::size_t> copyOfRoot(around.size(), 0);  // 1 + index into copies
        for (std::size_t a = 0; a < around.size(); ++a) {
            const std::size_t r = detail::rootOf(parent, a);
            if (r == kept)
                continue;
            if (copyOfRoot[r] == 0) {
                copies.push_back({std::size_t(&v - &m.vert[0]), {}});
                copyOfRoot[r] = copies.size();
            }
            copies[copyOfRoot[r] - 1].fan.push_back(around[a]);
        }
    }
    if (copies.empty())
        return result;
    // Adding vertices may move them all: only indices are held across it.
    auto added = vcg::tri::Allocator<MeshType>::AddVertices(m, copies.size());
    const std::size_t first = std::size_t(&*added - &m.vert[0]);
    for (std::size_t c = 0; c < copies.size(); ++c) {
        VertexType& copy = m.vert[first + c];
        copy.ImportData(m.vert[copies[c].vertex]);
        for (const detail::FaceCorner& fc : copies[c].fan)
            m.face[fc.face].V(fc.corner) = &copy;
    }
    result.vertexCopies = int(copies.size());
    vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    // What is left non-manifold: the edges whose faces still meet around both their ends.
    for (VertexType& v : m.vert) {
        if (v.IsD())
            continue;
        detail::facesAround(m, v, around, ends);
        detail::forEachEdgeRun(ends, [&](std::size_t i, std::size_t j) {
            result.edgesLeft += j - i > 2 && ends[i].first > &v;
        });
    }
    return result;
}

// Cuts `m` apart as above, unless `params` keeps every lock (relaxToReachTarget off), and,
// where it had such edges, says so in `stats.relaxed`.
template <class MeshType>
void cutNonManifoldEdges(MeshType& m, const SimplifyParams& params, SimplifyStats& stats)
{
    if (!params.relaxToReachTarget)
        return;
    const NonManifoldSplit split = splitNonManifoldEdges(m);
    if (split.edges > 0)
        stats.relaxed.push_back("cut apart along " + std::to_string(split.edges - split.edgesLeft) + " of " +
                                std::to_string(split.edges) +
                                " non-manifold edges (edges of three faces or more), whose vertices no collapse "
                                "may move: " + std::to_string(split.vertexCopies) + " vertices copied");
}

}  // namespace cadlod
