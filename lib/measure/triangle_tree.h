// A bounding-volume hierarchy over triangles for closest-point queries: O(log n) for a
// point near the surface or far from it. vcglib's uniform grid searches shell by shell,
// so a point ten cells away from the surface (a coarse LOD level measured against the
// original) visits a thousand cells; vcglib's AABB tree allocates arrays the size of the
// mesh on every query.
//
// Built once by median splits along the longest axis of the centroids' box; a query walks
// it depth first, nearer child first, and skips every box farther than the best so far.
#pragma once

#include <vcg/space/box3.h>
#include <vcg/space/point3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace cadlod {

namespace detail {

// Pointers to the live faces of `m` (to const faces when `m` is const).
template <class MeshType>
auto liveFaces(MeshType& m)
{
    std::vector<decltype(&m.face[0])> faces;
    faces.reserve(std::size_t(m.fn));
    for (auto& f : m.face)
        if (!f.IsD())
            faces.push_back(&f);
    return faces;
}

}  // namespace detail

class TriangleTree
{
public:
    // Triangles as corner indices into a copy of the mesh's vertex positions, in single
    // precision as the meshes' coordinates are: a third of the memory of three double
    // corners, nothing lost. Distances are computed in double.
    using Corners = std::array<std::uint32_t, 3>;
    using Triangle = std::array<vcg::Point3d, 3>;

    // `triangles[i]` is the i-th triangle; closest() returns that index.
    TriangleTree(std::vector<vcg::Point3f> vertices, std::vector<Corners> triangles)
        : vertices_(std::move(vertices)), triangles_(std::move(triangles))
    {
        order_.resize(triangles_.size());
        for (std::uint32_t i = 0; i < order_.size(); ++i)
            order_[i] = i;
        centroids_.resize(triangles_.size());
        for (std::size_t i = 0; i < triangles_.size(); ++i) {
            const Triangle t = triangle(i);
            centroids_[i] = (t[0] + t[1] + t[2]) / 3.0;
        }
        if (!triangles_.empty()) {
            nodes_.reserve(2 * triangles_.size() / kLeafSize + 2);
            nodes_.emplace_back();
            build(0, 0, std::uint32_t(order_.size()));
        }
        centroids_.clear();
        centroids_.shrink_to_fit();
    }

    // The faces `faces` (pointers into m.face) over a copy of m's vertex positions.
    template <class MeshType, class FacePointer>
    static TriangleTree of(const MeshType& m, const std::vector<FacePointer>& faces)
    {
        std::vector<vcg::Point3f> vertices(m.vert.size());
        for (std::size_t i = 0; i < m.vert.size(); ++i)
            vertices[i] = vcg::Point3f::Construct(m.vert[i].cP());
        std::vector<Corners> corners(faces.size());
        for (std::size_t i = 0; i < faces.size(); ++i)
            for (int j = 0; j < 3; ++j)
                corners[i][std::size_t(j)] = std::uint32_t(faces[i]->cV(j) - &m.vert[0]);
        return TriangleTree(std::move(vertices), std::move(corners));
    }

    Triangle triangle(std::size_t index) const
    {
        const Corners& c = triangles_[index];
        return {vcg::Point3d::Construct(vertices_[c[0]]), vcg::Point3d::Construct(vertices_[c[1]]),
                vcg::Point3d::Construct(vertices_[c[2]])};
    }

    bool empty() const { return triangles_.empty(); }

    double distance(std::size_t index, const vcg::Point3d& p) const
    {
        return std::sqrt(triangleDistance2(triangle(index), p));
    }

    // Index of the closest triangle to p (-1 if none within maxDistance) and the distance.
    std::int64_t closest(const vcg::Point3d& p, double maxDistance, double& distance) const
    {
        return closest(p, maxDistance, distance, [](std::size_t) { return true; });
    }

    // The same among the triangles `accept(index)` takes.
    template <class Accept>
    std::int64_t closest(const vcg::Point3d& p, double maxDistance, double& distance, Accept accept) const
    {
        distance = maxDistance;
        if (nodes_.empty())
            return -1;
        double best2 = maxDistance * maxDistance;
        std::int64_t best = -1;
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes_[stack[--top]];
            if (boxDistance2(node.box, p) >= best2)
                continue;
            if (node.count > 0) {
                for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
                    if (!accept(order_[k]))
                        continue;
                    const double d2 = triangleDistance2(triangle(order_[k]), p);
                    if (d2 < best2) {
                        best2 = d2;
                        best = order_[k];
                    }
                }
                continue;
            }
            const std::uint32_t a = node.first, b = node.first + 1;  // children are adjacent
            const double da = boxDistance2(nodes_[a].box, p), db = boxDistance2(nodes_[b].box, p);
            // Push the farther first, so that the nearer is searched first.
            if (da <= db) {
                if (db < best2)
                    stack[top++] = b;
                if (da < best2)
                    stack[top++] = a;
            } else {
                if (da < best2)
                    stack[top++] = a;
                if (db < best2)
                    stack[top++] = b;
            }
        }
        distance = best >= 0 ? std::sqrt(best2) : maxDistance;
        return best;
    }

    // Index of some triangle within `radius` of p (-1 if none): the walk, nearer child
    // first, stops at the first one. Enough to show that p cannot raise a running maximum
    // of distances, at a fraction of the cost of finding the closest.
    std::int64_t anyWithin(const vcg::Point3d& p, double radius) const
    {
        if (nodes_.empty())
            return -1;
        const double radius2 = radius * radius;
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = nodes_[stack[--top]];
            if (boxDistance2(node.box, p) > radius2)
                continue;
            if (node.count > 0) {
                for (std::uint32_t k = node.first; k < node.first + node.count; ++k)
                    if (triangleDistance2(triangle(order_[k]), p) <= radius2)
                        return order_[k];
                continue;
            }
            const std::uint32_t a = node.first, b = node.first + 1;
            const bool aNearer = boxDistance2(nodes_[a].box, p) <= boxDistance2(nodes_[b].box, p);
            stack[top++] = aNearer ? b : a;
            stack[top++] = aNearer ? a : b;
        }
        return -1;
    }

    // The triangles found for the points just before: the next point most often lies
    // near one of them, and one triangle test settles it where a walk would take dozens.
    struct RecentHits {
        std::array<std::int64_t, 4> triangle{-1, -1, -1, -1};
        std::size_t next = 0;
        void add(std::int64_t t)
        {
            triangle[next] = t;
            next = (next + 1) % triangle.size();
        }
    };

    // anyWithin, trying the recent hits first; a triangle the walk finds joins them.
    std::int64_t anyWithin(const vcg::Point3d& p, double radius, RecentHits& recent) const
    {
        const double radius2 = radius * radius;
        for (const std::int64_t t : recent.triangle)
            if (t >= 0 && std::size_t(t) < triangles_.size() && triangleDistance2(triangle(std::size_t(t)), p) <= radius2)
                return t;
        const std::int64_t found = anyWithin(p, radius);
        if (found >= 0)
            recent.add(found);
        return found;
    }

    // Squared distance from p to the triangle.
    static double triangleDistance2(const Triangle& t, const vcg::Point3d& p)
    {
        const vcg::Point3d w = closestWeights(t, p);
        return (t[0] * w[0] + t[1] * w[1] + t[2] * w[2] - p).SquaredNorm();
    }

    // The barycentric weights of the triangle's point closest to p (Ericson, Real-Time
    // Collision Detection, 5.1.5: the corner, edge or face region p projects into).
    static vcg::Point3d closestWeights(const Triangle& t, const vcg::Point3d& p)
    {
        const vcg::Point3d &a = t[0], &b = t[1], &c = t[2];
        const vcg::Point3d ab = b - a, ac = c - a, ap = p - a;
        const double d1 = ab * ap, d2 = ac * ap;
        if (d1 <= 0 && d2 <= 0)
            return {1, 0, 0};
        const vcg::Point3d bp = p - b;
        const double d3 = ab * bp, d4 = ac * bp;
        if (d3 >= 0 && d4 <= d3)
            return {0, 1, 0};
        const double vc = d1 * d4 - d3 * d2;
        if (vc <= 0 && d1 >= 0 && d3 <= 0) {
            const double s = d1 / (d1 - d3);
            return {1 - s, s, 0};
        }
        const vcg::Point3d cp = p - c;
        const double d5 = ab * cp, d6 = ac * cp;
        if (d6 >= 0 && d5 <= d6)
            return {0, 0, 1};
        const double vb = d5 * d2 - d1 * d6;
        if (vb <= 0 && d2 >= 0 && d6 <= 0) {
            const double s = d2 / (d2 - d6);
            return {1 - s, 0, s};
        }
        const double va = d3 * d6 - d5 * d4;
        if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
            const double s = (d4 - d3) / ((d4 - d3) + (d5 - d6));
            return {0, 1 - s, s};
        }
        const double denom = 1.0 / (va + vb + vc);
        return {1 - (vb + vc) * denom, vb * denom, vc * denom};
    }

private:
    static constexpr std::uint32_t kLeafSize = 8;

    struct Node {
        vcg::Box3f box;  // of float corners: exact
        std::uint32_t first = 0;  // leaf: first index into order_; inner: index of the first child
        std::uint32_t count = 0;  // leaf: number of triangles; inner: 0
    };

    // Fills node `slot` with the triangles order_[begin, end); an inner node's two children
    // sit next to each other, so it needs one index.
    void build(std::uint32_t slot, std::uint32_t begin, std::uint32_t end)
    {
        vcg::Box3f box;
        vcg::Box3d centres;
        for (std::uint32_t k = begin; k < end; ++k) {
            for (const std::uint32_t v : triangles_[order_[k]])
                box.Add(vertices_[v]);
            centres.Add(centroids_[order_[k]]);
        }
        nodes_[slot].box = box;
        if (end - begin <= kLeafSize) {
            nodes_[slot].first = begin;
            nodes_[slot].count = end - begin;
            return;
        }
        const vcg::Point3d extent = centres.max - centres.min;
        const int axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : (extent[1] >= extent[2] ? 1 : 2);
        const std::uint32_t middle = begin + (end - begin) / 2;
        std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                         [&](std::uint32_t x, std::uint32_t y) { return centroids_[x][axis] < centroids_[y][axis]; });
        const std::uint32_t children = std::uint32_t(nodes_.size());
        nodes_.emplace_back();
        nodes_.emplace_back();
        nodes_[slot].first = children;
        nodes_[slot].count = 0;
        build(children, begin, middle);
        build(children + 1, middle, end);
    }

    static double boxDistance2(const vcg::Box3f& b, const vcg::Point3d& p)
    {
        double d2 = 0;
        for (int i = 0; i < 3; ++i) {
            const double lo = b.min[i], hi = b.max[i];
            const double d = p[i] < lo ? lo - p[i] : (p[i] > hi ? p[i] - hi : 0.0);
            d2 += d * d;
        }
        return d2;
    }

    std::vector<vcg::Point3f> vertices_;
    std::vector<Corners> triangles_;
    std::vector<std::uint32_t> order_;
    std::vector<vcg::Point3d> centroids_;
    std::vector<Node> nodes_;
};

}  // namespace cadlod
