// How far a connected component stands off the rest of the model: the gap that removing it
// whole leaves (component_removal.h). Where that gap is wider than the component (a small
// part floating beside a body, a tip beyond it), the Hausdorff distance sees the gap.
//
// The vertex farthest from the rest is one of the component's extremes (along the axes and
// the box diagonals), and only those are looked up: each search has to pass over every face
// of the component's own that lies nearer, so searching from every vertex of a large
// component would take its size squared.
#pragma once

#include "simplify/cad_edge_collapse.h"
#include "mesh/components.h"
#include "measure/triangle_tree.h"

#include <vcg/space/point3.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

namespace cadlod {

// The faces of a set of components in one search tree, each knowing its component.
class ComponentSurfaces
{
public:
    // The live faces of `components` (of `m`); componentOfFace() answers for m.face as it is now.
    template <class MeshType>
    ComponentSurfaces(const MeshType& m, const std::vector<Component<MeshType>>& components)
    {
        componentOfFace_.assign(m.face.size(), -1);
        std::vector<const typename MeshType::FaceType*> faces;
        vcg::Box3d all;
        for (std::size_t c = 0; c < components.size(); ++c) {
            for (const auto* f : components[c].faces) {
                faces.push_back(f);
                componentOfTriangle_.push_back(std::int32_t(c));
                componentOfFace_[std::size_t(f - &m.face[0])] = std::int32_t(c);
            }
            all.Add(components[c].box);
        }
        tree_ = TriangleTree::of(m, faces);
        gone_.assign(components.size(), 0);
        maxDistance_ = all.IsNull() ? 1.0 : 4 * all.Diag() + 1;
    }

    // The component of face `face` of the mesh this was made of; -1: none (deleted, or made
    // since).
    std::int32_t componentOfFace(std::size_t face) const
    {
        return face < componentOfFace_.size() ? componentOfFace_[face] : -1;
    }

    // Component c is gone (removed whole): from here on no distance is measured to it.
    void markGone(std::int32_t c)
    {
        if (c >= 0 && std::size_t(c) < gone_.size())
            gone_[std::size_t(c)] = 1;
    }

    // The largest distance from `points` to the nearest face of a component that is not gone
    // and that `skip` does not claim, or `floor` where that is larger.
    template <class Skip>
    double farthest(const std::vector<vcg::Point3d>& points, const Skip& skip, double floor) const
    {
        double farthest = floor;
        auto another = [&](std::size_t k) {
            const std::int32_t c = componentOfTriangle_[k];
            return !gone_[std::size_t(c)] && !skip(c);
        };
        for (const vcg::Point3d& p : points) {
            double d = 0.0;
            if (tree_.closest(p, farthest, d, another) >= 0)
                continue;  // nearer than the farthest so far
            if (tree_.closest(p, maxDistance_, d, another) >= 0)
                farthest = std::max(farthest, d);
        }
        return farthest;
    }

private:
    TriangleTree tree_{{}, {}};
    std::vector<std::int32_t> componentOfTriangle_;  // per tree triangle
    std::vector<std::int32_t> componentOfFace_;      // per face of the mesh
    std::vector<char> gone_;                         // per component: markGone
    double maxDistance_ = 1.0;
};

// The positions of the vertices farthest along the axes and the box diagonals, both ways
// (at most 14 distinct vertices).
template <class VertexType>
std::vector<vcg::Point3d> extremePoints(const std::vector<VertexType*>& vertices)
{
    std::vector<const VertexType*> chosen;
    if (vertices.empty())
        return {};
    std::vector<vcg::Point3d> directions;
    for (int axis = 0; axis < 3; ++axis) {
        vcg::Point3d d(0, 0, 0);
        d[axis] = 1;
        directions.push_back(d);
        directions.push_back(-d);
    }
    for (int x = -1; x <= 1; x += 2)
        for (int y = -1; y <= 1; y += 2)
            for (int z = -1; z <= 1; z += 2)
                directions.push_back(vcg::Point3d(x, y, z));
    for (const vcg::Point3d& d : directions) {
        const VertexType* best = vertices.front();
        for (const VertexType* v : vertices)
            if (vcg::Point3d::Construct(v->cP()) * d > vcg::Point3d::Construct(best->cP()) * d)
                best = v;
        if (std::find(chosen.begin(), chosen.end(), best) == chosen.end())
            chosen.push_back(best);
    }
    std::vector<vcg::Point3d> points;
    for (const VertexType* v : chosen)
        points.push_back(vcg::Point3d::Construct(v->cP()));
    return points;
}

// How far a component of a session's mesh stands off the rest. A session over a whole
// model measures against the other components of its mesh, as they are now. A session over
// one piece of a model (collapse_buckets.h) measures against the whole model as it was
// dealt (CollapseContext::modelComponents), less the components removed since, the rest
// having moved by no more than the budgets of the levels between: its own mesh lacks the
// other pieces' components, and one of them may be the nearest. A piece without that index
// takes the size for the gap.
template <class MeshType>
class RestOfModel
{
public:
    using VertexType = typename MeshType::VertexType;
    using FaceType = typename MeshType::FaceType;
    using Context = CollapseContext<MeshType>;

    // The own mesh's faces are indexed at the first distance asked for: where every
    // small component touches another (an unwelded export) or exceeds the maximum
    // error, none is.
    RestOfModel(MeshType& m, const std::vector<Component<MeshType>>& components, const Context& ctx)
        : m_(m), components_(components), ctx_(ctx),
          measure_(ctx.modelComponents || (!ctx.mayRemoveLargestComponent && components.size() >= 2))
    {
    }

    // Whether distances to the rest are measured here (else farthest() is its floor).
    bool measures() const { return measure_; }

    // The largest distance from the extreme vertices of `vertices` (of the components
    // `members`, in increasing order) to the nearest face of another component, or
    // `floor` if that is larger.
    double farthest(const std::vector<VertexType*>& vertices, const std::vector<std::size_t>& members, double floor)
    {
        if (!measure_)
            return floor;
        const std::vector<vcg::Point3d> points = extremePoints(vertices);
        if (ctx_.modelComponents) {
            const std::vector<std::int32_t> skipped = ownAndRemoved(members);
            return ctx_.modelComponents->farthest(
                points, [&](std::int32_t k) { return std::binary_search(skipped.begin(), skipped.end(), k); }, floor);
        }
        if (!ownMesh_)
            ownMesh_.emplace(m_, components_);
        return ownMesh_->farthest(
            points, [&](std::int32_t k) { return std::binary_search(members.begin(), members.end(), std::size_t(k)); },
            floor);
    }

private:
    // The model's components no distance is measured to, sorted: those the faces of
    // `members` came from, and those this session removed (the index marks the other
    // pieces' removals only between levels).
    std::vector<std::int32_t> ownAndRemoved(const std::vector<std::size_t>& members) const
    {
        std::vector<std::int32_t> skipped = ctx_.modelComponentsRemoved;
        for (std::size_t c : members)
            for (const FaceType* f : components_[c].faces)
                if (const std::int32_t k = ctx_.modelComponentOfFace(f); k >= 0)
                    skipped.push_back(k);
        std::sort(skipped.begin(), skipped.end());
        skipped.erase(std::unique(skipped.begin(), skipped.end()), skipped.end());
        return skipped;
    }

    MeshType& m_;
    const std::vector<Component<MeshType>>& components_;
    const Context& ctx_;
    bool measure_;
    std::optional<ComponentSurfaces> ownMesh_;
};

}  // namespace cadlod
