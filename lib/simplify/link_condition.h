// Where the link condition (vcglib's EdgeCollapser::LinkConditions: Lk(a) ∩ Lk(b) = Lk(ab),
// the topology stays as it is) is not the whole story about a collapse.
//
// vcglib's test counts instead of comparing sets: it counts the neighbours each endpoint
// sees twice, in one map for both endpoints, and compares the count with the size of
// Lk(ab). On closed surfaces the two agree. Beside a boundary they do not: a boundary run
// of the second endpoint whose ends are also the first's neighbours is missed. Then
//   - it passes some collapses that give an edge four faces (a vertex where two boundary
//     runs meet, a pinch, as in a forest of thin trees simplified far):
//     makesNonManifoldEdge refuses those besides;
//   - it refuses some that keep the topology (an interior vertex into a boundary one).
//
// And where the topology does change, a collapse may still keep every edge manifold: it
// closes a hole whose rim has shrunk to three edges, or joins two boundary runs at a vertex.
// A mesh modelled as patches that meet at points (a scanned or hand-modelled figure: the
// castle demo's alien has 919 boundary edges in 4 200 faces) has hundreds of such places
// and, toward a face target, no other collapse left but ones that destroy whole parts.
// joinsBoundaryOnly tells those apart; the collapse is then offered priced like a feature
// break (cad_edge_collapse.h), the refusals of the second kind with them.
#pragma once

#include <vcg/simplex/face/pos.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace cadlod {

namespace detail {

// The edges of v's link: for each face around v, its edge opposite v, as an ordered pair.
template <class VertexType>
std::vector<std::pair<const VertexType*, const VertexType*>> linkEdges(VertexType* v)
{
    using FaceType = typename VertexType::FaceType;
    std::vector<std::pair<const VertexType*, const VertexType*>> edges;
    for (vcg::face::VFIterator<FaceType> vfi(v); !vfi.End(); ++vfi) {
        const VertexType* p = vfi.V1();
        const VertexType* q = vfi.V2();
        edges.push_back(p < q ? std::make_pair(p, q) : std::make_pair(q, p));
    }
    std::sort(edges.begin(), edges.end());
    return edges;
}

}  // namespace detail

// Whether collapsing v0 into v1 leaves an edge with more than two faces that had at most
// two: after the collapse, edge (v1,x) carries the faces of (v1,x) and of (v0,x) that do
// not vanish with the edge.
template <class VertexType>
bool makesNonManifoldEdge(VertexType* v0, VertexType* v1)
{
    using FaceType = typename VertexType::FaceType;
    struct Use {
        const VertexType* x;
        int from0, from1;
    };
    std::vector<Use> uses;  // a ring's neighbours: a linear search is cheapest
    auto count = [&](const VertexType* x, bool of0) {
        for (Use& u : uses)
            if (u.x == x) {
                ++(of0 ? u.from0 : u.from1);
                return;
            }
        uses.push_back({x, of0 ? 1 : 0, of0 ? 0 : 1});
    };
    for (VertexType* v : {v0, v1}) {
        const VertexType* other = v == v0 ? v1 : v0;
        for (vcg::face::VFIterator<FaceType> vfi(v); !vfi.End(); ++vfi) {
            if (vfi.V1() == other || vfi.V2() == other)
                continue;  // vanishes with the edge
            count(vfi.V1(), v == v0);
            count(vfi.V2(), v == v0);
        }
    }
    return std::any_of(uses.begin(), uses.end(), [](const Use& u) {
        return u.from0 > 0 && u.from1 > 0 && u.from0 <= 2 && u.from1 <= 2 && u.from0 + u.from1 > 2;
    });
}

// Whether collapsing v0 into v1, where the link condition fails, keeps every edge manifold
// (it closes a hole or joins boundary runs, or vcglib refused it wrongly): no edge gets
// more than two faces, no two faces come to share their three vertices (an edge in both
// links), and faces are left around v1.
template <class VertexType>
bool joinsBoundaryOnly(VertexType* v0, VertexType* v1)
{
    const auto a = detail::linkEdges(v0), b = detail::linkEdges(v1);
    std::vector<std::pair<const VertexType*, const VertexType*>> shared;  // faces v0xy and v1xy: they would coincide
    std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(shared));
    const bool folds = !shared.empty();
    if (folds || makesNonManifoldEdge(v0, v1))
        return false;
    using FaceType = typename VertexType::FaceType;
    for (VertexType* v : {v0, v1})  // a lone triangle would vanish: that is a removal's to do
        for (vcg::face::VFIterator<FaceType> vfi(v); !vfi.End(); ++vfi)
            if (vfi.V1() != v0 && vfi.V1() != v1 && vfi.V2() != v0 && vfi.V2() != v1)
                return true;
    return false;
}

}  // namespace cadlod
