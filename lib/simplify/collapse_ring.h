// The faces around an edge about to collapse, read once per evaluation: the ones that survive
// it (into the context's ring, what does not depend on the new vertex computed once), whether
// the endpoints and the edge lie on features, and the shape of the faces there now.
#pragma once

#include "simplify/collapse_context.h"
#include "measure/compactness.h"

#include <vcg/simplex/face/pos.h>

#include <algorithm>

namespace cadlod {

template <class MeshType>
struct CollapseRing {
    using VertexType = typename MeshType::VertexType;
    using FaceType = typename MeshType::FaceType;
    using VFIterator = vcg::face::VFIterator<FaceType>;
    using Context = CollapseContext<MeshType>;

    static constexpr double kSliver = 0.1;  // compactness below which a face counts as a sliver

    // What the faces around the edge say: surviving faces into ctx.ring, whether the
    // endpoints and the edge lie on features, the worst compactness of all of them.
    struct Neighbourhood {
        bool v0OnFeature = false, v1OnFeature = false, edgeIsFeature = false;
        bool v0Corner = false, v1Corner = false;  // on other than exactly two feature edges
        double worstCompactness = 1.0;
        int slivers = 0;  // faces below kSliver, the two the collapse removes included
        bool removesSliver = false;  // a face it removes is a sliver and the edge is its shortest
    };

    static Neighbourhood gatherRing(Context& ctx, VertexType* v0, VertexType* v1)
    {
        Neighbourhood n;
        ctx.ring.clear();
        for (int side = 0; side < 2; ++side) {
            VertexType* v = side == 0 ? v0 : v1;
            VertexType* other = side == 0 ? v1 : v0;
            bool onFeature = false;
            VertexType* featureEnds[2] = {nullptr, nullptr};
            bool corner = false;
            auto addFeatureEnd = [&](VertexType* x) {
                if (x == featureEnds[0] || x == featureEnds[1])
                    return;
                if (!featureEnds[0])
                    featureEnds[0] = x;
                else if (!featureEnds[1])
                    featureEnds[1] = x;
                else
                    corner = true;  // a third feature edge
            };
            for (VFIterator vfi(v); !vfi.End(); ++vfi) {
                FaceType* f = vfi.F();
                const int z = vfi.I();
                VertexType* a = f->V((z + 1) % 3);
                VertexType* b = f->V((z + 2) % 3);
                const bool featureA = f->IsUserBit(ctx.bits.edge[z]);
                const bool featureB = f->IsUserBit(ctx.bits.edge[(z + 2) % 3]);
                onFeature |= featureA || featureB;
                if (featureA)
                    addFeatureEnd(a);
                if (featureB)
                    addFeatureEnd(b);
                if (a == other || b == other) {
                    n.edgeIsFeature |= a == other ? featureA : featureB;
                    if (side == 0) {  // shared faces are seen from both sides
                        const double c = compactness(f->cP(0), f->cP(1), f->cP(2));
                        n.worstCompactness = std::min(n.worstCompactness, c);
                        n.slivers += c < kSliver;
                        n.removesSliver |= c < kSliver && isShortestEdge(*f, z, a == other ? (z + 1) % 3 : (z + 2) % 3);
                    }
                } else {
                    const vcg::Point3d pa = vcg::Point3d::Construct(a->cP());
                    const vcg::Point3d pb = vcg::Point3d::Construct(b->cP());
                    const vcg::Point3d pv = vcg::Point3d::Construct(v->cP());
                    const vcg::Point3d normal = (pa - pv) ^ (pb - pv);
                    RingFace face{pa, pb, normal, normal.Norm(),
                                  vcg::Point3d::Construct(ctx.inputNormal[f - ctx.faceBase]),
                                  (pb - pa).SquaredNorm()};
                    if (ctx.keepsSmoothJoins()) {
                        faceBeyond(f, a, b, v0, v1, face);
                        face.side = side;
                    }
                    const double edges = (pa - pv).SquaredNorm() + (pb - pv).SquaredNorm() + face.abSquared;
                    const double c = compactnessFrom(face.normalLength, edges);
                    n.worstCompactness = std::min(n.worstCompactness, c);
                    n.slivers += c < kSliver;
                    ctx.ring.push_back(face);
                }
            }
            (side == 0 ? n.v0OnFeature : n.v1OnFeature) = onFeature;
            (side == 0 ? n.v0Corner : n.v1Corner) = onFeature && (corner || !featureEnds[1]);
        }
        return n;
    }

    // The face across the outer edge a-b of ring face f, for the smooth-join guard.
    static void faceBeyond(const FaceType* f, VertexType* a, const VertexType* b,
                           const VertexType* v0, const VertexType* v1, RingFace& face)
    {
        for (VFIterator vfi(a); !vfi.End(); ++vfi) {
            const FaceType* g = vfi.F();
            if (g == f)
                continue;
            bool hasB = false, inRing = false;
            for (int k = 0; k < 3; ++k) {
                hasB |= g->cV(k) == b;
                inRing |= g->cV(k) == v0 || g->cV(k) == v1;
            }
            if (!hasB || inRing)
                continue;
            vcg::Point3d n = vcg::Point3d::Construct(vcg::TriangleNormal(*g));
            const double length = n.Norm();
            if (!(length > 0))
                return;
            face.beyond = n / length;
            return;
        }
    }

    // Whether the edge of f from corner i to corner j is no longer than its other two.
    static bool isShortestEdge(const FaceType& f, int i, int j)
    {
        const int k = 3 - i - j;
        const double edge = (f.cP(i) - f.cP(j)).SquaredNorm();
        return edge <= (f.cP(i) - f.cP(k)).SquaredNorm() && edge <= (f.cP(j) - f.cP(k)).SquaredNorm();
    }
};

}  // namespace cadlod
