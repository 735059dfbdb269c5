// The change an edge collapse makes to a mesh with VF adjacency: v0 is merged into v1, which
// moves to p; the faces on both ends are deleted, and every other face of v0 takes v1 in
// its place. It touches only the faces around v0 and the adjacency lists of their vertices.
//
// vcglib's EdgeCollapser::Do makes the same change (the same adjacency order, so a session
// gives the same mesh with either), but also counts the deleted elements in the mesh (m.fn,
// m.vn). Two collapse sessions on the two halves of one mesh (collapse_halves.h) would then
// both write those counters; here the caller counts, each session its own.
#pragma once

#include <vcg/simplex/face/pos.h>
#include <vcg/simplex/face/topology.h>

#include <vector>

namespace cadlod {

// What collapseEdge deleted.
struct CollapseCount {
    int faces = 0;
    int vertices = 0;
};

template <class VertexType, class PointType>
CollapseCount collapseEdge(VertexType* v0, VertexType* v1, const PointType& p)
{
    using FaceType = typename VertexType::FaceType;
    CollapseCount deleted;
    // The faces around v0, in adjacency order, split into those on both ends (deleted) and
    // those on v0 alone (they take v1). Both lists are read before any link changes.
    thread_local std::vector<vcg::face::VFIterator<FaceType>> onBoth, onV0;
    onBoth.clear();
    onV0.clear();
    for (vcg::face::VFIterator<FaceType> x(v0); !x.End(); ++x) {
        FaceType* f = x.F();
        const bool hasV1 = f->V(0) == v1 || f->V(1) == v1 || f->V(2) == v1;
        (hasV1 ? onBoth : onV0).push_back(x);
    }
    for (auto x : onBoth) {
        FaceType& f = *x.F();
        const int z = x.I();
        vcg::face::VFDetach(f, (z + 1) % 3);
        vcg::face::VFDetach(f, (z + 2) % 3);
        f.Dealloc();
        f.SetD();
        ++deleted.faces;
    }
    // Each face of v0 alone goes to the front of v1's list, in turn.
    for (auto x : onV0) {
        FaceType* f = x.F();
        const int z = x.I();
        f->V(z) = v1;
        f->VFp(z) = v1->VFp();
        f->VFi(z) = v1->VFi();
        v1->VFp() = f;
        v1->VFi() = z;
    }
    v0->SetD();
    ++deleted.vertices;
    v1->P() = p;
    return deleted;
}

}  // namespace cadlod
