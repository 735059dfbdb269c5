// Closing a tunnel. The link condition keeps every tunnel of a surface open: a board's
// through-hole, a handle, the gap a part leaves in itself. So a part with holes stops far
// above a far-field target, a board with sixteen pin holes at some two hundred faces. Once
// collapses have shrunk a tunnel's rim to three edges, the collapse of one of them fails
// the link condition: the endpoints share a third neighbour, and the three close a loop no
// face fills. Cutting the surface along that loop and capping each side with a triangle
// plugs the tunnel (on a loop that separates, it splits the surface at a neck). Collapses
// then flatten what is left of it like any other small feature.
//
// A cut is one more local operation in the collapse heap, offered by the refused collapse.
// Its error is the cap's inradius: no point of a cap is farther than that from the loop,
// and the loop lies on the surface. It is ranked like a feature break or a component
// removal: featurePenalty times the quadric cost of moving the loop's share of the planes
// by that error, the planes weighed by their capped areas alone, without the floor every
// plane has in the collapses' quadrics (cad_quadrics.h): a tunnel's wall is made of small
// faces, and with the floor it weighed twice as much, so a drilled plate at 12 faces broke
// two of its corners (17.9 off) before the cut. A maximum error (a chain level's budget)
// forbids wider caps.
//
// A cut needs three vertices and two faces. They are spares reserved before the session
// (reserveTunnelCuts), because adding elements during it would move the vertices and faces
// the heap points to.
#pragma once

#include "simplify/cad_edge_collapse.h"
#include "simplify/priced_operation.h"
#include "simplify/collapse_heap.h"
#include "mesh/components.h"
#include "mesh/layer_metadata.h"

#include <vcg/complex/algorithms/local_optimization.h>
#include <vcg/simplex/face/topology.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace cadlod {

namespace detail {

// At least as many tunnels (handles) as the components of `m` have, from each component's
// Euler characteristic χ = V - E + F: a surface of genus g with b boundary loops has
// 2 - χ = 2g + b. The boundary loops are counted as tunnels too, which only reserves a few
// spare elements more; counting E as 3F/2, as if every component were closed, found none
// on a KiCad RJ45 jack (190 boundary edges, χ = -15), which then stopped at 137 faces
// when asked for 101, every collapse refused by the link condition. Needs VF adjacency.
template <class MeshType>
int tunnelCount(MeshType& m)
{
    using VertexType = typename MeshType::VertexType;
    using FaceType = typename MeshType::FaceType;
    std::vector<char> seen(m.vert.size(), 0);
    std::vector<const VertexType*> around;  // one vertex's neighbours, no copy of the edges
    int tunnels = 0;
    for (const Component<MeshType>& c : connectedComponents(m)) {
        long vertices = 0, edges = 0;
        for (const auto* f : c.faces)
            for (int j = 0; j < 3; ++j) {
                VertexType* v = f->cV(j);
                char& s = seen[std::size_t(v - &m.vert[0])];
                if (s)
                    continue;
                s = 1;
                ++vertices;
                around.clear();
                for (vcg::face::VFIterator<FaceType> vfi(v); !vfi.End(); ++vfi)
                    for (int k = 0; k < 3; ++k)
                        if (vfi.F()->cV(k) > v)  // each edge from its lower vertex
                            around.push_back(vfi.F()->cV(k));
                std::sort(around.begin(), around.end());
                edges += long(std::unique(around.begin(), around.end()) - around.begin());
            }
        const long twoMinusChi = 2 - (vertices - edges + long(c.faces.size()));
        tunnels += int(std::max(0L, twoMinusChi));
    }
    return tunnels;
}

}  // namespace detail

// Reserves spare elements for the cuts a session on `m` may make, one per tunnel, before
// any pointer into `m` is taken: they are added and deleted at once.
template <class MeshType>
void reserveTunnelCuts(MeshType& m, CollapseContext<MeshType>& ctx)
{
    const int cuts = detail::tunnelCount(m);
    if (cuts == 0)
        return;
    auto firstVertex = vcg::tri::Allocator<MeshType>::AddVertices(m, std::size_t(3 * cuts));
    auto firstFace = vcg::tri::Allocator<MeshType>::AddFaces(m, std::size_t(2 * cuts));
    ctx.spareVertices.clear();
    ctx.spareFaces.clear();
    for (auto v = firstVertex; v != m.vert.end(); ++v) {
        vcg::tri::Allocator<MeshType>::DeleteVertex(m, *v);
        ctx.spareVertices.push_back(&*v);
    }
    for (auto f = firstFace; f != m.face.end(); ++f) {
        f->V(0) = f->V(1) = f->V(2) = nullptr;
        vcg::tri::Allocator<MeshType>::DeleteFace(m, *f);
        ctx.spareFaces.push_back(&*f);
    }
}

template <class MeshType>
class TunnelCut : public PricedOperation<MeshType>
{
    using Base = PricedOperation<MeshType>;

public:
    using typename Base::VertexType, typename Base::FaceType, typename Base::ScalarType;
    using typename Base::Context, typename Base::HeapType, typename Base::HeapElem;
    using VFIterator = vcg::face::VFIterator<FaceType>;
    using Corner = std::pair<FaceType*, int>;  // a face and the index of the loop vertex in it

    // The collapse of (a, b) failed the link condition: the cheapest cut of a loop of
    // three edges through it, if any is allowed, goes into the heap.
    static void offer(Context& ctx, VertexType* a, VertexType* b)
    {
        if (!ctx.heap || ctx.spareVertices.size() < 3 || ctx.spareFaces.size() < 2)
            return;
        VertexType* best = nullptr;
        ScalarType bestPriority = 0;
        for (VertexType* c : loopsThrough(a, b)) {
            Loop loop;
            if (!trace({a, b, c}, ctx, loop) || ctx.exceedsBound(loop.inradius, loop.inradius))
                continue;
            const double weight =
                (ctx.quadrics.cappedArea(a) + ctx.quadrics.cappedArea(b) + ctx.quadrics.cappedArea(c)) / 3.0;
            const double cost = std::max(1.0, ctx.params.featurePenalty) * weight * loop.inradius * loop.inradius;
            const auto priority = ScalarType(ctx.inFarField() ? ctx.farFieldPriority(loop.inradius)
                                                               : ctx.priority(cost, weight, 1.0));
            if (!best || priority < bestPriority) {
                best = c;
                bestPriority = priority;
            }
        }
        if (best) {
            heapPush(*ctx.heap, HeapElem(new TunnelCut({a, b, best}, ctx.mark, bestPriority)));
        }
    }


    // Out of date when a loop vertex was deleted or was the survivor of a collapse since.
    bool IsUpToDate() const override
    {
        for (const VertexType* v : loop_)
            if (v->IsD() || v->cIMark() > madeAt_)
                return false;
        return true;
    }

    // The faces around the loop may have changed since the offer (a neighbour collapsed), so
    // it is traced again; Execute, which follows at once, cuts along that trace. A loop that
    // separates its surface is no tunnel: cutting it would only split off a piece, which the
    // collapses squeeze and removals take anyway.
    bool IsFeasible(vcg::BaseParameterClass* pp) override
    {
        Context& ctx = this->contextOf(pp);
        return ctx.spareVertices.size() >= 3 && ctx.spareFaces.size() >= 2 && trace(loop_, ctx, traced_) &&
               !separates(traced_, ctx);
    }

    void Execute(MeshType& m, vcg::BaseParameterClass* pp) override
    {
        Context& ctx = this->contextOf(pp);
        const Loop& loop = traced_;
        // The left side (the faces holding the loop's edges in its direction) moves to
        // copies of the loop's vertices; each side gets a cap facing away from it.
        for (int i = 0; i < 3; ++i) {
            copies_[i] = takeVertex(m, ctx, loop_[i]);
            for (const Corner& c : loop.left[i])
                moveCorner(c, copies_[i]);
        }
        FaceType* leftCap =
            takeFace(m, ctx, *loop.left[0].front().first, {copies_[0], copies_[2], copies_[1]}, -loop.normal);
        FaceType* rightCap = takeFace(m, ctx, *loop.right[0].front().first, {loop_[0], loop_[1], loop_[2]}, loop.normal);
        capQuadrics(ctx, loop, *leftCap, *rightCap);

        const int mark = ++ctx.mark;
        for (int i = 0; i < 3; ++i)
            for (VertexType* v : {loop_[i], copies_[i]}) {
                v->IMark() = mark;  // the entries of their edges are out of date
                ctx.ringChanged(v) = mark;
            }
        ++ctx.stats->closedTunnels;
        ctx.stats->widestTunnelCap = std::max(ctx.stats->widestTunnelCap, loop.inradius);
        ctx.recordError(loop.inradius, loop.inradius);
    }

    // Every edge of the six vertices, anew.
    void UpdateHeap(HeapType& heap, vcg::BaseParameterClass* pp) override
    {
        for (int i = 0; i < 3; ++i)
            for (VertexType* v : {loop_[i], copies_[i]})
                CadEdgeCollapse<MeshType>::pushEdgesOf(heap, v, pp);
    }

private:
    struct Loop {
        std::array<std::vector<Corner>, 3> left, right;  // per loop vertex, its faces on each side
        double inradius = 0.0;
        vcg::Point3d normal;  // unit, of the triangle (a, b, c)
        double area = 0.0;
    };

    TunnelCut(std::array<VertexType*, 3> loop, int mark, ScalarType priority)
        : Base(priority), loop_(loop), madeAt_(mark)
    {
    }

    // The vertices c that close a loop (a, b, c) no face fills: neighbours of both that
    // are not the apex of a face on the edge.
    static std::vector<VertexType*> loopsThrough(VertexType* a, VertexType* b)
    {
        std::vector<VertexType*> nearA, nearB, apexes;
        for (VFIterator vfi(a); !vfi.End(); ++vfi) {
            nearA.push_back(vfi.V1());
            nearA.push_back(vfi.V2());
            if (vfi.V1() == b || vfi.V2() == b)
                apexes.push_back(vfi.V1() == b ? vfi.V2() : vfi.V1());
        }
        for (VFIterator vfi(b); !vfi.End(); ++vfi) {
            nearB.push_back(vfi.V1());
            nearB.push_back(vfi.V2());
        }
        for (auto* list : {&nearA, &nearB, &apexes}) {
            std::sort(list->begin(), list->end());
            list->erase(std::unique(list->begin(), list->end()), list->end());
        }
        std::vector<VertexType*> common, loops;
        std::set_intersection(nearA.begin(), nearA.end(), nearB.begin(), nearB.end(), std::back_inserter(common));
        std::set_difference(common.begin(), common.end(), apexes.begin(), apexes.end(), std::back_inserter(loops));
        return loops;
    }

    // The loop a → b → c → a and the faces on each side of it at each vertex. False unless
    // every loop vertex is writable and its faces form one closed fan that the loop splits
    // in two, and the cap has an area.
    static bool trace(const std::array<VertexType*, 3>& v, const Context& ctx, Loop& loop)
    {
        for (int i = 0; i < 3; ++i) {
            VertexType* x = v[i];
            VertexType* next = v[(i + 1) % 3];
            VertexType* prev = v[(i + 2) % 3];
            if (x->IsD() || !x->IsRW() || x->IsUserBit(ctx.bits.locked) || x->IsUserBit(ctx.bits.boundary))
                return false;
            std::vector<Corner> around;
            for (VFIterator vfi(x); !vfi.End(); ++vfi)
                around.push_back({vfi.F(), vfi.I()});
            if (!turn(around, next, prev, loop.left[i]) || !turn(around, prev, next, loop.right[i]) ||
                loop.left[i].size() + loop.right[i].size() != around.size())
                return false;
        }
        const vcg::Point3d a = vcg::Point3d::Construct(v[0]->cP()), b = vcg::Point3d::Construct(v[1]->cP()),
                           c = vcg::Point3d::Construct(v[2]->cP());
        const vcg::Point3d n = (b - a) ^ (c - a);
        const double doubleArea = n.Norm();
        const double perimeter = vcg::Distance(a, b) + vcg::Distance(b, c) + vcg::Distance(c, a);
        if (!(doubleArea > 0) || !std::isfinite(doubleArea))
            return false;
        loop.normal = n / doubleArea;
        loop.area = doubleArea / 2;
        loop.inradius = doubleArea / perimeter;
        return true;
    }

    // The faces around x from the one holding the edge x → `from` to the one holding the
    // edge `to` → x, turning from each face to the one across its other edge at x. False
    // when an edge at x is not shared by exactly one such face, or `to` is never reached.
    static bool turn(const std::vector<Corner>& around, VertexType* from, VertexType* to, std::vector<Corner>& out)
    {
        auto holding = [&](VertexType* y) -> const Corner* {  // the face holding x → y
            const Corner* found = nullptr;
            for (const Corner& c : around)
                if (c.first->V((c.second + 1) % 3) == y) {
                    if (found)
                        return nullptr;
                    found = &c;
                }
            return found;
        };
        out.clear();
        const Corner* c = holding(from);
        while (c && out.size() < around.size()) {
            out.push_back(*c);
            VertexType* across = c->first->V((c->second + 2) % 3);
            if (across == to)
                return true;
            c = holding(across);
        }
        return false;
    }

    // Whether the faces on the loop's left reach those on its right only across the loop.
    // Both sides are walked at once, a face at a time each, from face to face over shared
    // edges, never over the loop's own. A side whose walk runs out of faces is cut off from
    // the other: the loop separates. That side is mostly a small piece (a lead's tip, a pin
    // squeezed at its root), so the walk stops after twice its faces; from the left side
    // alone it went over the rest of the part, every time a collapse offered the loop again,
    // which on a board of a few hundred parts took more time than the collapses. A face one
    // walk reaches that the other has marked joins the two sides.
    bool separates(const Loop& loop, Context& ctx) const
    {
        auto onLoop = [&](const VertexType* x, const VertexType* y) {
            for (int i = 0; i < 3; ++i)
                if ((x == loop_[i] && y == loop_[(i + 1) % 3]) || (y == loop_[i] && x == loop_[(i + 1) % 3]))
                    return true;
            return false;
        };
        const auto [leftMark, rightMark] = ctx.newWalkMarks();
        struct Side {
            std::uint32_t own, other;  // the marks of its faces and of the other side's
            std::vector<FaceType*> stack;
        };
        // A side's walk reaching face g: false when the other side holds it, else g is marked
        // and stacked unless it already was.
        auto reach = [&](Side& side, FaceType* g) {
            std::uint32_t& m = ctx.walkMark[std::size_t(g - ctx.faceBase)];
            if (m == side.other)
                return false;
            if (m != side.own) {
                m = side.own;
                side.stack.push_back(g);
            }
            return true;
        };
        // One face off the side's stack, its neighbours across edges off the loop reached.
        auto step = [&](Side& side) {
            FaceType* f = side.stack.back();
            side.stack.pop_back();
            for (int j = 0; j < 3; ++j) {
                VertexType* x = f->V(j);
                VertexType* y = f->V((j + 1) % 3);
                if (onLoop(x, y))
                    continue;
                for (VFIterator vfi(x); !vfi.End(); ++vfi)
                    if (vfi.F() != f && (vfi.V1() == y || vfi.V2() == y) && !reach(side, vfi.F()))
                        return false;  // across the edge (x, y): the other side's
            }
            return true;
        };
        Side left{leftMark, rightMark, {}}, right{rightMark, leftMark, {}};
        for (auto [side, corners] : {std::pair{&left, &loop.left}, std::pair{&right, &loop.right}})
            for (const auto& around : *corners)
                for (const Corner& c : around)
                    if (!reach(*side, c.first))
                        return false;  // a face on both sides
        while (!left.stack.empty() && !right.stack.empty())
            if (!step(left) || !step(right))
                return false;
        return true;
    }

    static void moveCorner(const Corner& c, VertexType* to)
    {
        vcg::face::VFDetach(*c.first, c.second);
        c.first->V(c.second) = to;
        c.first->VFp(c.second) = nullptr;  // VFAppend keeps it when `to` has no face yet
        c.first->VFi(c.second) = -1;
        vcg::face::VFAppend(c.first, c.second);
    }

    // A spare vertex, alive again as a copy of `like` (its quadric too).
    static VertexType* takeVertex(MeshType& m, Context& ctx, VertexType* like)
    {
        VertexType* v = ctx.spareVertices.back();
        ctx.spareVertices.pop_back();
        v->ImportData(*like);
        v->Flags() = like->Flags();
        v->VFp() = nullptr;
        v->VFi() = -1;
        ++m.vn;
        ctx.quadrics.quadric(v) = ctx.quadrics.quadric(like);
        ctx.quadrics.area(v) = ctx.quadrics.area(like);
        ctx.quadrics.cappedArea(v) = ctx.quadrics.cappedArea(like);
        return v;
    }

    // A spare face, alive again with the corners `v` and the attributes of `like` (colour,
    // part), no feature edge; `normal`: its unit normal.
    static FaceType* takeFace(MeshType& m, Context& ctx, FaceType& like, std::array<VertexType*, 3> v,
                              const vcg::Point3d& normal)
    {
        FaceType* f = ctx.spareFaces.back();
        ctx.spareFaces.pop_back();
        f->ImportData(like);
        f->Flags() = 0;
        if (like.IsS())
            f->SetS();
        for (int j = 0; j < 3; ++j) {
            f->V(j) = v[j];
            f->VFp(j) = nullptr;
            f->VFi(j) = -1;
            vcg::face::VFAppend(f, j);
        }
        ++m.fn;
        if (vcg::tri::HasPerFaceAttribute(m, kPartAttribute)) {
            auto part = facePartHandle(m);
            part[f] = part[&like];
        }
        const std::size_t index = std::size_t(f - ctx.faceBase);
        ctx.inputNormal[index] = vcg::Point3f::Construct(normal);
        if (ctx.surface)
            ctx.surface->adopt(index, std::size_t(&like - ctx.faceBase));
        return f;
    }

    // The caps are surface now: their plane joins the quadrics of their corners.
    void capQuadrics(Context& ctx, const Loop& loop, FaceType& leftCap, FaceType& rightCap)
    {
        for (FaceType* cap : {&leftCap, &rightCap})
            for (int j = 0; j < 3; ++j)
                ctx.quadrics.addPlane(cap->V(j), loop.normal, loop.normal * vcg::Point3d::Construct(cap->cP(0)),
                                      loop.area);
    }

    std::array<VertexType*, 3> loop_;
    Loop traced_;                         // by IsFeasible, for Execute
    std::array<VertexType*, 3> copies_{};
    int madeAt_;
};

}  // namespace cadlod
