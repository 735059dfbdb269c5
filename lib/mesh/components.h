// Connected components of a triangle mesh, for the steps that treat a small part as one
// thing: removing it whole when it is smaller than the error a level may make (a screw
// seen from 50 m), and replacing the parts of the coarsest level by their boxes.
// Components are found through the VF adjacency (faces sharing a vertex are connected),
// so the pass needs no edge table; deleted faces are ignored.
#pragma once

#include "mesh/layer_metadata.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace cadlod {

template <class MeshType>
struct Component {
    std::vector<typename MeshType::FacePointer> faces;
    vcg::Box3d box;        // of its vertices
    std::string name;      // the CAD part most of its faces belong to, or "component N"
    bool named = false;    // the name is a CAD part's (from the part table)
    double size() const { return box.IsNull() ? 0.0 : box.Diag(); }
};

// Every connected component of the live faces, smallest (bbox diagonal) first; ties keep
// the order of their first face, so the result is deterministic. Needs VF adjacency.
template <class MeshType>
std::vector<Component<MeshType>> connectedComponents(MeshType& m)
{
    using FaceType = typename MeshType::FaceType;
    std::vector<Component<MeshType>> out;
    std::vector<char> seen(m.face.size(), 0);
    // A vertex's faces are walked once: walked again from each of its faces, the hub of a
    // fan (a cylinder's cap, thousands of faces around one vertex) costs its valence squared.
    std::vector<char> walked(m.vert.size(), 0);
    std::vector<FaceType*> stack;
    const bool parts = hasParts(m);
    typename MeshType::template PerFaceAttributeHandle<int> partOf;
    PartTable table;
    if (parts) {
        partOf = facePartHandle(m);
        table = partTableHandle(m)();
    }
    for (std::size_t i = 0; i < m.face.size(); ++i) {
        if (m.face[i].IsD() || seen[i])
            continue;
        Component<MeshType> c;
        std::map<int, int> partVotes;
        seen[i] = 1;
        stack.assign(1, &m.face[i]);
        while (!stack.empty()) {
            FaceType* f = stack.back();
            stack.pop_back();
            c.faces.push_back(f);
            if (parts)
                ++partVotes[partOf[f]];
            for (int j = 0; j < 3; ++j) {
                c.box.Add(vcg::Point3d::Construct(f->cP(j)));
                char& done = walked[std::size_t(f->V(j) - &m.vert[0])];
                if (done)
                    continue;
                done = 1;
                for (vcg::face::VFIterator<FaceType> vfi(f->V(j)); !vfi.End(); ++vfi) {
                    const std::size_t k = std::size_t(vfi.F() - &m.face[0]);
                    if (!vfi.F()->IsD() && !seen[k]) {
                        seen[k] = 1;
                        stack.push_back(vfi.F());
                    }
                }
            }
        }
        c.name = "component " + std::to_string(out.size() + 1);
        if (!partVotes.empty()) {
            const auto top = std::max_element(partVotes.begin(), partVotes.end(),
                                              [](const auto& a, const auto& b) { return a.second < b.second; });
            if (top->first >= 0 && top->first < int(table.size()) && !table[std::size_t(top->first)].name.empty()) {
                c.name = table[std::size_t(top->first)].name;
                c.named = true;
            }
        }
        out.push_back(std::move(c));
    }
    std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.size() < b.size(); });
    return out;
}

// Groups of components that touch: a vertex of one stands exactly where a vertex of
// another stands (a surface exported unwelded, faces split at a seam). Per component, the
// index of its group, numbered in order of first member.
template <class MeshType>
std::vector<int> touchGroups(MeshType& m, const std::vector<Component<MeshType>>& components)
{
    struct Key {
        float x, y, z;
        bool operator==(const Key& k) const { return x == k.x && y == k.y && z == k.z; }
    };
    struct Hash {
        std::size_t operator()(const Key& k) const
        {
            std::size_t h = std::hash<float>()(k.x);
            h = h * 1000003u ^ std::hash<float>()(k.y);
            return h * 1000003u ^ std::hash<float>()(k.z);
        }
    };
    std::vector<std::size_t> parent(components.size());
    for (std::size_t c = 0; c < parent.size(); ++c)
        parent[c] = c;
    auto root = [&](std::size_t c) {
        while (parent[c] != c)
            c = parent[c] = parent[parent[c]];
        return c;
    };
    std::vector<char> seen(m.vert.size(), 0);
    std::unordered_map<Key, std::size_t, Hash> owner;
    for (std::size_t c = 0; c < components.size(); ++c)
        for (auto* f : components[c].faces)
            for (int j = 0; j < 3; ++j) {
                char& s = seen[std::size_t(f->V(j) - &m.vert[0])];
                if (s)
                    continue;
                s = 1;
                const auto& p = f->V(j)->cP();
                const auto [it, added] = owner.emplace(Key{float(p[0]), float(p[1]), float(p[2])}, c);
                if (!added)
                    parent[root(c)] = root(it->second);
            }
    std::vector<int> group(components.size(), -1);
    std::vector<int> numberOfRoot(components.size(), -1);
    int groups = 0;
    for (std::size_t c = 0; c < components.size(); ++c) {
        int& n = numberOfRoot[root(c)];
        if (n < 0)
            n = groups++;
        group[c] = n;
    }
    return group;
}

// Deletes every face and vertex of `m` (its attributes stay) and compacts it.
template <class MeshType>
void deleteEverything(MeshType& m)
{
    for (auto& f : m.face)
        if (!f.IsD())
            vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
    for (auto& v : m.vert)
        if (!v.IsD())
            vcg::tri::Allocator<MeshType>::DeleteVertex(m, v);
    vcg::tri::Allocator<MeshType>::CompactEveryVector(m);
}

// Deletes the component's faces and the vertices they use (no other live face uses them).
template <class MeshType>
void removeComponent(MeshType& m, const Component<MeshType>& c)
{
    for (auto* f : c.faces) {
        if (f->IsD())
            continue;
        for (int j = 0; j < 3; ++j)
            if (!f->V(j)->IsD())
                vcg::tri::Allocator<MeshType>::DeleteVertex(m, *f->V(j));
        vcg::tri::Allocator<MeshType>::DeleteFace(m, *f);
    }
}

namespace detail {

// The corners of `box` listed in `corners` (numbered by bits x, y, z), appended to `m`.
template <class MeshType, std::size_t N>
std::array<typename MeshType::VertexPointer, N> appendBoxCorners(MeshType& m, const vcg::Box3d& box,
                                                                 const std::array<int, N>& corners)
{
    using CoordType = typename MeshType::CoordType;
    auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, N);
    std::array<typename MeshType::VertexPointer, N> v;
    for (std::size_t k = 0; k < N; ++k, ++vi) {
        const int c = corners[k];
        vi->P() = CoordType::Construct(vcg::Point3d(c & 1 ? box.max[0] : box.min[0], c & 2 ? box.max[1] : box.min[1],
                                                    c & 4 ? box.max[2] : box.min[2]));
        v[k] = &*vi;
    }
    return v;
}

// `count` faces of `m` from `first` on get part `part` and colour `color`, where the mesh
// carries parts and face colours.
template <class MeshType>
void tagFaces(MeshType& m, typename MeshType::FaceIterator first, int count, int part, const vcg::Color4b& color)
{
    const bool parts = vcg::tri::HasPerFaceAttribute(m, kPartAttribute);
    const bool colors = vcg::tri::HasPerFaceColor(m);
    typename MeshType::template PerFaceAttributeHandle<int> partOf;
    if (parts)
        partOf = facePartHandle(m);
    for (int k = 0; k < count; ++k, ++first) {
        if (colors)
            first->C() = color;
        if (parts)
            partOf[first] = part;
    }
}

}  // namespace detail

// The twelve triangles of an axis-aligned box, outward facing, appended to `m` as part
// `part` (when the mesh has parts) with the given face colour.
template <class MeshType>
void appendBox(MeshType& m, const vcg::Box3d& box, int part, const vcg::Color4b& color)
{
    const auto v = detail::appendBoxCorners(m, box, std::array<int, 8>{0, 1, 2, 3, 4, 5, 6, 7});
    // Each face lists its corners counter-clockwise seen from outside.
    static const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                    {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    const auto first = vcg::tri::Allocator<MeshType>::AddFaces(m, 12);
    auto fi = first;
    for (const auto& q : quads)
        for (int t = 0; t < 2; ++t, ++fi) {
            fi->V(0) = v[q[0]];
            fi->V(1) = v[q[1 + t]];
            fi->V(2) = v[q[2 + t]];
        }
    detail::tagFaces(m, first, 12, part, color);
}

// The tetrahedron inscribed in an axis-aligned box (four of its corners, no two on one
// edge), outward facing, appended to `m` as part `part` with the given face colour.
template <class MeshType>
void appendTetrahedron(MeshType& m, const vcg::Box3d& box, int part, const vcg::Color4b& color)
{
    // Corners 0, 3, 5 and 6 differ pairwise in two bits.
    const auto v = detail::appendBoxCorners(m, box, std::array<int, 4>{0, 3, 5, 6});
    const auto first = vcg::tri::Allocator<MeshType>::AddFaces(m, 4);
    auto fi = first;
    for (int opposite = 0; opposite < 4; ++opposite, ++fi) {
        int f[3], n = 0;
        for (int k = 0; k < 4; ++k)
            if (k != opposite)
                f[n++] = k;
        // Outward: the fourth corner lies behind the face.
        const auto a = v[f[0]]->cP(), b = v[f[1]]->cP(), c = v[f[2]]->cP();
        if (((b - a) ^ (c - a)).dot(v[opposite]->cP() - a) > 0)
            std::swap(f[1], f[2]);
        for (int j = 0; j < 3; ++j)
            fi->V(j) = v[f[j]];
    }
    detail::tagFaces(m, first, 4, part, color);
}

}  // namespace cadlod
