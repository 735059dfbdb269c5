// Removing a small connected component whole: one more local operation in the collapse
// heap, beside the edge collapses. A component's own collapses stop at a tetrahedron, so an
// assembly of a hundred screws keeps hundreds of faces however far it is simplified, and
// squeezing a screw into a tetrahedron makes about as much error as dropping it. So the
// removal competes with the collapses on the same terms: its cost is the quadric cost of
// moving every plane of the component by its removal distance, ranked, like any feature
// break, at featurePenalty times that. Each of its faces' planes weighs at least the
// quadrics' area cap (cad_quadrics.h): a part far smaller than the faces around it would
// weigh next to nothing by area, yet removing it leaves a gap as wide as its removal
// distance, which the Hausdorff distance sees whole. The removal distance is the
// component's size (the distance a viewer's ray may miss by), or, where it stands off the
// rest of the model, the distance of its farthest vertex from the rest's surface: a small
// part floating beside a body, a tip beyond it, leaves a gap that wide where it was. The
// largest component is never removed; a maximum error forbids removing anything whose
// removal distance exceeds it. Components with a vertex where another has one (a surface
// exported unwelded, a triangle soup, faces split at a seam, a screw's head meeting its
// shank at a point) go together or not at all, as one touch group: removing one piece alone
// opens a hole in the others. The group of the largest component stays.
#pragma once

#include "simplify/cad_edge_collapse.h"
#include "simplify/priced_operation.h"
#include "mesh/components.h"
#include "simplify/rest_of_model.h"

#include <vcg/complex/algorithms/local_optimization.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace cadlod {

template <class MeshType>
class ComponentRemoval : public PricedOperation<MeshType>
{
public:
    using Base = PricedOperation<MeshType>;
    using typename Base::Context, typename Base::HeapType, typename Base::HeapElem;
    using typename Base::VertexType, typename Base::FaceType, typename Base::ScalarType;

    // Adds one removal per component but the largest (unless the context says the model's
    // largest is in another mesh) to `heap` (not re-heapified). Components that touch (a
    // vertex where another's stands) go together, as one removal of their touch group: one
    // of them alone would open a hole in the others, all of them leave only the gap the
    // group stands off the rest (a screw exported as a shank and a head meeting at a point).
    static void push(MeshType& m, Context& ctx, HeapType& heap)
    {
        const std::vector<Component<MeshType>> components = connectedComponents(m);
        const std::size_t removable =
            ctx.mayRemoveLargestComponent || components.empty() ? components.size() : components.size() - 1;
        if (removable == 0)
            return;  // a single part: nothing to find out about touching parts or gaps
        const std::vector<int> group = touchGroups(m, components);
        const int kept = removable < components.size() ? group.back() : -1;  // the largest's group
        const double penalty = std::max(1.0, ctx.params.featurePenalty);
        RestOfModel<MeshType> rest(m, components, ctx);
        for (const std::vector<std::size_t>& members : groupMembers(group)) {
            const int g = group[members.front()];
            if (g == kept)
                continue;
            vcg::Box3d box;
            for (std::size_t c : members)
                box.Add(components[c].box);
            const double size = box.IsNull() ? 0.0 : box.Diag();
            if (ctx.exceedsBound(size, size))
                continue;
            // (vcglib's visited bit is not free here: the collapse's Init leaves it set.)
            std::vector<VertexType*> vertices;
            for (std::size_t c : members)
                for (FaceType* f : components[c].faces)
                    for (int j = 0; j < 3; ++j)
                        vertices.push_back(f->V(j));
            std::sort(vertices.begin(), vertices.end());
            vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
            double weight = 0.0;
            for (VertexType* v : vertices)
                weight += ctx.quadrics.area(v) / 3.0;
            // In the far field a removal is ranked by the gap it leaves, as collapses are by
            // the distance they open there (far_field.h).
            const double distance = rest.farthest(vertices, members, ctx.inFarField() && rest.measures() ? 0.0 : size);
            if (ctx.exceedsBound(distance, distance))
                continue;
            const double cost = penalty * weight * distance * distance;
            const double priority = ctx.inFarField() ? ctx.farFieldPriority(distance) : ctx.priority(cost, weight, 1.0);
            heap.push_back(HeapElem(new ComponentRemoval(std::move(vertices), int(members.size()), size, distance,
                                                         nameOf(components, members),
                                                         components[members.back()].named, ScalarType(priority))));
        }
    }

    bool IsUpToDate() const override { return liveVertex() != nullptr; }
    bool IsFeasible(vcg::BaseParameterClass*) override { return true; }
    void UpdateHeap(HeapType&, vcg::BaseParameterClass*) override {}

    // The component as it is now (collapses inside it never join it to another one).
    void Execute(MeshType& m, vcg::BaseParameterClass* pp) override
    {
        Context& ctx = this->contextOf(pp);
        Component<MeshType> c;
        c.faces = facesConnectedTo(m, vertices_);
        if (ctx.farField)
            for (const FaceType* f : c.faces)
                ctx.farField->dropPointsOf(f);
        for (const FaceType* f : c.faces)
            if (const std::int32_t k = ctx.modelComponentOfFace(f); k >= 0)
                ctx.modelComponentsRemoved.push_back(k);
        removeComponent(m, c);
        ctx.stats->removedComponents += pieces_;
        ctx.stats->largestRemovedComponent = std::max(ctx.stats->largestRemovedComponent, size_);
        ctx.recordError(distance_, distance_);
        ctx.removals.add(ctx.stats->relaxed, name_, named_, c.faces.size(), size_, distance_, ctx.diagonal);
    }

private:
    // The components of each touch group (`group`: per component, its group), smallest
    // first within a group, groups in order of their smallest member.
    static std::vector<std::vector<std::size_t>> groupMembers(const std::vector<int>& group)
    {
        std::vector<std::vector<std::size_t>> members;
        std::vector<int> slot(group.size(), -1);
        for (std::size_t c = 0; c < group.size(); ++c) {
            int& k = slot[std::size_t(group[c])];
            if (k < 0) {
                k = int(members.size());
                members.emplace_back();
            }
            members[std::size_t(k)].push_back(c);
        }
        return members;
    }

    // What the log calls a touch group: its largest member's name, and how many more pieces
    // touch it.
    static std::string nameOf(const std::vector<Component<MeshType>>& components, const std::vector<std::size_t>& members)
    {
        std::string name = components[members.back()].name;
        if (members.size() > 1)
            name += " and " + std::to_string(members.size() - 1) + " piece" + (members.size() > 2 ? "s" : "") +
                    " touching it";
        return name;
    }

    ComponentRemoval(std::vector<VertexType*> vertices, int pieces, double size, double distance, std::string name,
                     bool named, ScalarType priority)
        : Base(priority), vertices_(std::move(vertices)), pieces_(pieces), size_(size), distance_(distance), name_(std::move(name)),
          named_(named)
    {
    }

    VertexType* liveVertex() const
    {
        for (VertexType* v : vertices_)
            if (!v->IsD())
                return v;
        return nullptr;
    }

    // The live faces of the components that hold the live vertices among `seeds`.
    static std::vector<FaceType*> facesConnectedTo(MeshType& m, const std::vector<VertexType*>& seeds)
    {
        std::vector<FaceType*> faces;
        std::vector<char> seen(m.vert.size(), 0);
        auto visit = [&](VertexType* v) {
            char& s = seen[std::size_t(v - &m.vert[0])];
            const bool first = !s;
            s = 1;
            return first;
        };
        std::vector<VertexType*> stack;
        for (VertexType* seed : seeds)
            if (!seed->IsD() && visit(seed))
                stack.push_back(seed);
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
    int pieces_;  // the components of its touch group
    double size_;
    double distance_;  // removal distance: the size, or the gap it leaves if wider
    std::string name_;
    bool named_;  // name_ is a CAD part's, not "component N"
};

}  // namespace cadlod
