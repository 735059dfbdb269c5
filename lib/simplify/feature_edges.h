// Finds the edges a CAD simplification must keep: boundary edges, creases (dihedral
// angle above the feature angle), part/material borders, and the non-manifold edges
// and degenerate faces whose vertices must not move at all. Edges are found through
// the VF adjacency (no global edge table), so the pass needs no extra memory.
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cadlod {

// User bits allocated in the face/vertex flags for one simplification.
struct FeatureBits {
    int edge[3] = {0, 0, 0};  // face bit: edge j (V(j), V(j+1)) is a feature edge
    int locked = 0;           // vertex bit: never collapse an edge touching this vertex
    int boundary = 0;         // vertex bit: on a kept boundary, never leaves its place
};

struct FeatureEdgeCounts {
    int feature = 0;      // creases and part borders
    int boundary = 0;
    int nonManifold = 0;
    int degenerateFaces = 0;
};

namespace detail {

struct IncidentEdge {
    void* other;  // the edge's other vertex
    void* face;
    int edge;     // edge index in face
    bool operator<(const IncidentEdge& e) const { return other < e.other; }
};

template <class FaceType>
vcg::Point3d faceNormal(const FaceType& f)
{
    const vcg::Point3d a = vcg::Point3d::Construct(f.cP(0));
    const vcg::Point3d b = vcg::Point3d::Construct(f.cP(1));
    const vcg::Point3d c = vcg::Point3d::Construct(f.cP(2));
    return (b - a) ^ (c - a);
}

// True when the two faces meet at an angle sharper than the feature angle; faces with no
// area have no normal and never make a crease.
template <class FaceType>
bool isCrease(const FaceType& f, const FaceType& g, double cosFeatureAngle)
{
    const vcg::Point3d n = faceNormal(f), m = faceNormal(g);
    const double len = n.Norm() * m.Norm();
    return len > 0 && (n * m) / len < cosFeatureAngle;
}

}  // namespace detail

template <class FaceType>
bool repeatsVertex(const FaceType& f)
{
    return f.cV(0) == f.cV(1) || f.cV(1) == f.cV(2) || f.cV(2) == f.cV(0);
}

// Marks feature edges with bits.edge[j] on every face sharing them, non-moving
// vertices with bits.locked and the vertices of kept boundary edges with bits.boundary
// (the caller clears the vertex bits beforehand, as simplify() does). `partOf(face)`
// returns the face's part id (faces of different parts meeting at an edge make a part
// border); pass a function returning a constant to ignore parts. Needs VF adjacency.
template <class MeshType, class PartOf>
FeatureEdgeCounts markFeatureEdges(MeshType& m, const FeatureBits& bits, double featureAngleDeg,
                                   bool boundaryIsFeature, PartOf partOf)
{
    using FaceType = typename MeshType::FaceType;
    using VertexType = typename MeshType::VertexType;
    FeatureEdgeCounts counts;
    const double cosFeature = std::cos(featureAngleDeg * M_PI / 180.0);

    for (FaceType& f : m.face) {
        if (f.IsD())
            continue;
        for (int j = 0; j < 3; ++j)
            f.ClearUserBit(bits.edge[j]);
        if (repeatsVertex(f)) {
            ++counts.degenerateFaces;
            for (int j = 0; j < 3; ++j)
                f.V(j)->SetUserBit(bits.locked);
        }
    }

    std::vector<detail::IncidentEdge> around;
    for (VertexType& v : m.vert) {
        if (v.IsD())
            continue;
        around.clear();
        for (vcg::face::VFIterator<FaceType> vfi(&v); !vfi.End(); ++vfi) {
            FaceType* f = vfi.F();
            if (repeatsVertex(*f))
                continue;
            const int z = vfi.I();
            around.push_back({f->V((z + 1) % 3), f, z});
            around.push_back({f->V((z + 2) % 3), f, (z + 2) % 3});
        }
        std::sort(around.begin(), around.end());
        for (std::size_t i = 0; i < around.size();) {
            std::size_t j = i + 1;
            while (j < around.size() && around[j].other == around[i].other)
                ++j;
            auto* other = static_cast<VertexType*>(around[i].other);
            if (other > &v) {  // each edge once
                const std::size_t faces = j - i;
                bool feature = false;
                if (faces == 1) {
                    ++counts.boundary;
                    feature = boundaryIsFeature;
                    if (feature) {
                        v.SetUserBit(bits.boundary);
                        other->SetUserBit(bits.boundary);
                    }
                } else if (faces == 2) {
                    auto* f = static_cast<FaceType*>(around[i].face);
                    auto* g = static_cast<FaceType*>(around[i + 1].face);
                    feature = partOf(*f) != partOf(*g) || detail::isCrease(*f, *g, cosFeature);
                    counts.feature += feature;
                } else {
                    ++counts.nonManifold;
                    v.SetUserBit(bits.locked);
                    other->SetUserBit(bits.locked);
                }
                if (feature)
                    for (std::size_t k = i; k < j; ++k)
                        static_cast<FaceType*>(around[k].face)->SetUserBit(bits.edge[around[k].edge]);
            }
            i = j;
        }
    }
    return counts;
}

}  // namespace cadlod
