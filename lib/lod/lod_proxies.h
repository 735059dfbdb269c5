// The proxies at the far end of a LOD chain (lod_chain.h): closed shapes, one per connected
// component of what the collapses left, made from boxes. A box keeps the part and colour of
// the faces it stands for, so a proxy draws like the part it replaces.
#pragma once

#include "measure/hausdorff.h"  // liveVertexBox
#include "mesh/components.h"
#include "mesh/layer_metadata.h"
#include "simplify/simplify_params.h"  // SimplifyStats

#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/space/box3.h>
#include <vcg/space/color4.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace cadlod {

// The box proxy is tried with these shares of each component's area left out at both ends
// of each axis (trimmedBox), and the one with the smallest measured error is kept: 0 is the
// box of the component's vertices.
inline constexpr double kBoxTrims[] = {0.0, 0.02, 0.05, 0.1};
// The tetrahedra are tried inscribed in their boxes and in the boxes grown by these factors
// about their centres, and the one with the smallest measured error is kept. Inscribed in a
// cube, a tetrahedron leaves four corners a third of the diagonal off; grown 1.5 times, those
// corners and its own vertices sticking out stand a quarter of the diagonal off each.
inline constexpr double kTetrahedronScales[] = {1.0, 1.25, 1.5};

namespace detail {

// What a proxy is made from: a box, and the part and colour of the faces it stands for.
struct ProxyBox {
    vcg::Box3d box;
    int part = 0;
    vcg::Color4b color = vcg::Color4b(vcg::Color4b::Gray);

    bool operator==(const ProxyBox& o) const
    {
        return box.min == o.box.min && box.max == o.box.max && part == o.part && color == o.color;
    }
};

// The part and colour of component `c`'s first face, with the box `box`.
template <class MeshType>
ProxyBox proxyBoxOf(MeshType& m, const Component<MeshType>& c, const vcg::Box3d& box)
{
    ProxyBox b;
    b.box = box;
    const auto* first = c.faces.front();
    if (hasParts(m))
        b.part = facePartHandle(m)[first];
    if (vcg::tri::HasPerFaceColor(m))
        b.color = first->cC();
    return b;
}

// `boxes`, each grown by `factor` about its centre.
inline std::vector<ProxyBox> grownBoxes(std::vector<ProxyBox> boxes, double factor)
{
    for (ProxyBox& b : boxes) {
        const vcg::Point3d c = b.box.Center(), half = b.box.Dim() * (0.5 * factor);
        b.box = vcg::Box3d(c - half, c + half);
    }
    return boxes;
}

// Replaces `m` by one closed shape per box, `append(m, box, part, colour)` making it.
template <class MeshType, class AppendShape>
void replaceByProxies(MeshType& m, const std::vector<ProxyBox>& boxes, const AppendShape& append)
{
    deleteEverything(m);
    for (const ProxyBox& b : boxes)
        append(m, b.box, b.part, b.color);
}

// The box of component `c`'s surface without its outermost `share` of area at either end of
// each axis. A pin or a leg sticking out of a body holds little of the area, and the box of
// the rest stands closer for the body: the box of all its vertices is off by the pin's length
// over the whole bottom face. Each face counts as its corners and its centroid, a quarter of
// its area each. share 0, or nothing left: the box of its vertices.
template <class MeshType>
vcg::Box3d trimmedBox(const Component<MeshType>& c, double share)
{
    if (!(share > 0))
        return c.box;
    struct Weighted {
        vcg::Point3d p;
        double w;
    };
    std::vector<Weighted> points;
    points.reserve(4 * c.faces.size());
    double total = 0.0;
    for (const auto* f : c.faces) {
        const vcg::Point3d a = vcg::Point3d::Construct(f->cP(0)), b = vcg::Point3d::Construct(f->cP(1)),
                           d = vcg::Point3d::Construct(f->cP(2));
        const double w = 0.125 * ((b - a) ^ (d - a)).Norm();
        for (const vcg::Point3d& p : {a, b, d, (a + b + d) / 3.0})
            points.push_back({p, w});
        total += 4.0 * w;
    }
    if (!(total > 0))
        return c.box;
    vcg::Box3d box;
    for (int axis = 0; axis < 3; ++axis) {
        std::sort(points.begin(), points.end(),
                  [axis](const Weighted& x, const Weighted& y) { return x.p[axis] < y.p[axis]; });
        double below = 0.0;
        std::size_t lo = 0;
        while (lo + 1 < points.size() && below + points[lo].w <= share * total)
            below += points[lo++].w;
        double above = 0.0;
        std::size_t hi = points.size() - 1;
        while (hi > lo && above + points[hi].w <= share * total)
            above += points[hi--].w;
        box.min[axis] = points[lo].p[axis];
        box.max[axis] = points[hi].p[axis];
    }
    return box;
}

// The connected components of `m` at least `minSize` large; the smaller ones, which no proxy
// stands for, are counted in `stats`.
template <class MeshType>
std::vector<Component<MeshType>> componentsToKeep(MeshType& m, double minSize, SimplifyStats& stats)
{
    vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    std::vector<Component<MeshType>> kept;
    for (Component<MeshType>& c : connectedComponents(m)) {
        if (c.size() < minSize) {
            ++stats.removedComponents;
            stats.largestRemovedComponent = std::max(stats.largestRemovedComponent, c.size());
            continue;
        }
        kept.push_back(std::move(c));
    }
    return kept;
}

// One box per component of `m` in `kept`, trimmed by `trim` (see trimmedBox), with the
// component's part and colour.
template <class MeshType>
std::vector<ProxyBox> proxyBoxes(MeshType& m, const std::vector<Component<MeshType>>& kept, double trim)
{
    std::vector<ProxyBox> boxes;
    for (const Component<MeshType>& c : kept)
        boxes.push_back(proxyBoxOf(m, c, trimmedBox(c, trim)));
    return boxes;
}

// The boxes of the components in `kept` for each of kBoxTrims, with the trim that made
// them. A trim that cuts nothing off makes the boxes a smaller one made: they are listed
// once (most parts have nothing sticking out), with the smaller trim.
struct TrimmedProxyBoxes {
    double trim = 0.0;
    std::vector<ProxyBox> boxes;
};

template <class MeshType>
std::vector<TrimmedProxyBoxes> distinctTrimmedBoxes(MeshType& m, const std::vector<Component<MeshType>>& kept)
{
    std::vector<TrimmedProxyBoxes> distinct;
    for (double trim : kBoxTrims) {
        std::vector<ProxyBox> boxes = proxyBoxes(m, kept, trim);
        const bool seen = std::any_of(distinct.begin(), distinct.end(),
                                      [&](const TrimmedProxyBoxes& d) { return d.boxes == boxes; });
        if (!seen)
            distinct.push_back({trim, std::move(boxes)});
    }
    return distinct;
}

// The box of each connected component of `m` at least `minSize` large, with its part and
// colour; the smaller ones, which no proxy stands for, are counted in `stats`.
template <class MeshType>
std::vector<ProxyBox> boxPerComponent(MeshType& m, double minSize, SimplifyStats& stats)
{
    return proxyBoxes(m, componentsToKeep(m, minSize, stats), 0.0);
}

// The box of all of a model's live vertices, with the part and colour of its largest
// component: what one proxy for the whole model is made from (null box: no faces).
template <class MeshType>
ProxyBox modelBox(MeshType& m)
{
    vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    const auto components = connectedComponents(m);
    return components.empty() ? ProxyBox() : proxyBoxOf(m, components.back(), liveVertexBox(m));
}

}  // namespace detail

}  // namespace cadlod
