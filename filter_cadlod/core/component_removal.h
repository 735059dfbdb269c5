// Removing a small connected component whole: one more local operation in the collapse
// heap, beside the edge collapses. A component's own collapses stop at a tetrahedron, so an
// assembly of a hundred screws keeps hundreds of faces however far it is simplified, and
// squeezing a screw into a tetrahedron makes about as much error as dropping it. So the
// removal competes with the collapses on the same terms: its cost is the quadric cost of
// moving every plane of the component by its size (the distance a viewer's ray may miss by),
// ranked, like any feature break, at featurePenalty times that. The largest component is
// never removed; a maximum error forbids removing anything larger than it. Neither is a
// component with a vertex where another component has one: that is a piece of a surface
// exported unwelded (a triangle soup, faces split at a seam), and removing it opens a hole.
#pragma once

#include "cad_edge_collapse.h"
#include "components.h"

#include <vcg/complex/algorithms/local_optimization.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace cadlod {

template <class MeshType>
class ComponentRemoval : public vcg::LocalModification<MeshType>
{
public:
    using VertexType = typename MeshType::VertexType;
    using FaceType = typename MeshType::FaceType;
    using ScalarType = typename MeshType::ScalarType;
    using HeapType = typename vcg::LocalOptimization<MeshType>::HeapType;
    using HeapElem = typename vcg::LocalOptimization<MeshType>::HeapElem;
    using Context = CollapseContext<MeshType>;

    // Adds one removal per component but the largest (unless the context says the model's
    // largest is in another mesh) to `heap` (not re-heapified).
    static void push(MeshType& m, Context& ctx, HeapType& heap)
    {
        const std::vector<Component<MeshType>> components = connectedComponents(m);
        const std::vector<bool> touching = touchingOthers(m, components);
        const double penalty = std::max(1.0, ctx.params.featurePenalty);
        const std::size_t removable =
            ctx.mayRemoveLargestComponent || components.empty() ? components.size() : components.size() - 1;
        for (std::size_t i = 0; i < removable; ++i) {
            const Component<MeshType>& c = components[i];
            if (ctx.maxErrorAbs > 0 && c.size() > ctx.maxErrorAbs)
                break;
            if (touching[i])
                continue;
            // (vcglib's visited bit is not free here: the collapse's Init leaves it set.)
            std::vector<VertexType*> vertices;
            double weight = 0.0;
            for (FaceType* f : c.faces)
                for (int j = 0; j < 3; ++j)
                    vertices.push_back(f->V(j));
            std::sort(vertices.begin(), vertices.end());
            vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
            for (VertexType* v : vertices)
                weight += ctx.quadrics.area(v) / 3.0;
            const double cost = penalty * weight * c.size() * c.size();
            heap.push_back(HeapElem(new ComponentRemoval(std::move(vertices), c.size(), c.name,
                                                         ScalarType(ctx.priority(cost, weight, 1.0)))));
        }
    }

    vcg::ModifierType IsOfType() override { return vcg::TriEdgeCollapseOp; }
    bool IsUpToDate() const override { return liveVertex() != nullptr; }
    bool IsFeasible(vcg::BaseParameterClass*) override { return true; }
    ScalarType ComputePriority(vcg::BaseParameterClass*) override { return priority_; }
    ScalarType Priority() const override { return priority_; }
    void UpdateHeap(HeapType&, vcg::BaseParameterClass*) override {}

    // The component as it is now (collapses inside it never join it to another one).
    void Execute(MeshType& m, vcg::BaseParameterClass* pp) override
    {
        Context& ctx = *static_cast<Context*>(pp);
        VertexType* seed = liveVertex();
        Component<MeshType> c;
        c.faces = facesConnectedTo(m, seed);
        removeComponent(m, c);
        ++ctx.stats->removedComponents;
        ctx.stats->largestRemovedComponent = std::max(ctx.stats->largestRemovedComponent, size_);
        ctx.largestError = std::max(ctx.largestError, size_);
        char line[256];
        std::snprintf(line, sizeof line, "removed %s whole (%zu faces, size %.4g %% of the diagonal)", name_.c_str(),
                      c.faces.size(), ctx.diagonal > 0 ? 100.0 * size_ / ctx.diagonal : 0.0);
        ctx.stats->relaxed.push_back(line);
    }

private:
    // Per component: whether one of its vertices stands exactly where a vertex of another
    // component stands.
    static std::vector<bool> touchingOthers(MeshType& m, const std::vector<Component<MeshType>>& components)
    {
        const std::vector<int> group = touchGroups(m, components);
        std::vector<int> members(components.size(), 0);
        for (int g : group)
            ++members[std::size_t(g)];
        std::vector<bool> touching(components.size());
        for (std::size_t c = 0; c < components.size(); ++c)
            touching[c] = members[std::size_t(group[c])] > 1;
        return touching;
    }

    ComponentRemoval(std::vector<VertexType*> vertices, double size, std::string name, ScalarType priority)
        : vertices_(std::move(vertices)), size_(size), name_(std::move(name)), priority_(priority)
    {
    }

    VertexType* liveVertex() const
    {
        for (VertexType* v : vertices_)
            if (!v->IsD())
                return v;
        return nullptr;
    }

    static std::vector<FaceType*> facesConnectedTo(MeshType& m, VertexType* seed)
    {
        std::vector<FaceType*> faces;
        std::vector<char> seen(m.vert.size(), 0);
        auto visit = [&](VertexType* v) {
            char& s = seen[std::size_t(v - &m.vert[0])];
            const bool first = !s;
            s = 1;
            return first;
        };
        std::vector<VertexType*> stack{seed};
        visit(seed);
        while (!stack.empty()) {
            VertexType* v = stack.back();
            stack.pop_back();
            for (vcg::face::VFIterator<FaceType> vfi(v); !vfi.End(); ++vfi) {
                FaceType* f = vfi.F();
                if (f->IsD())
                    continue;
                if (f->V(0) == v)  // each face once: from its vertex 0
                    faces.push_back(f);
                for (int j = 0; j < 3; ++j)
                    if (visit(f->V(j)))
                        stack.push_back(f->V(j));
            }
        }
        return faces;
    }

    std::vector<VertexType*> vertices_;
    double size_;
    std::string name_;
    ScalarType priority_;
};

}  // namespace cadlod
