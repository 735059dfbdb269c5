#include "openflight/triangle_strip.h"

#include <unordered_map>

namespace cadlod::flt {
namespace {

std::uint64_t edgeKey(std::uint32_t from, std::uint32_t to) { return std::uint64_t(from) << 32 | to; }

// Directed edge -> a triangle that has it in its winding order, and the opposite vertex.
class EdgeIndex {
public:
    explicit EdgeIndex(const std::vector<Triangle>& triangles)
    {
        map_.reserve(3 * triangles.size());
        for (std::uint32_t t = 0; t < triangles.size(); ++t)
            for (int k = 0; k < 3; ++k)
                map_.emplace(edgeKey(triangles[t][k], triangles[t][(k + 1) % 3]), t);
    }

    // An unused triangle holding from->to; false when there is none.
    bool find(std::uint32_t from, std::uint32_t to, const std::vector<bool>& used, std::uint32_t& t) const
    {
        const auto it = map_.find(edgeKey(from, to));
        if (it == map_.end() || used[it->second])
            return false;
        t = it->second;
        return true;
    }

private:
    std::unordered_map<std::uint64_t, std::uint32_t> map_;
};

std::uint32_t thirdVertex(const Triangle& t, std::uint32_t a, std::uint32_t b)
{
    for (std::uint32_t v : t)
        if (v != a && v != b)
            return v;
    return t[0];
}

// Appends `t` so that it starts at an even position, joined to what is already there by
// degenerate triangles.
void startStrip(std::vector<std::uint32_t>& strip, const Triangle& t)
{
    if (!strip.empty()) {
        strip.push_back(strip.back());
        strip.push_back(t[0]);
        strip.push_back(t[0]);
        if ((strip.size() - 1) % 2 == 1)
            strip.push_back(t[0]);
        strip.pop_back();  // the last t[0] is the strip's own first vertex
    }
    strip.insert(strip.end(), t.begin(), t.end());
}

}  // namespace

std::vector<std::uint32_t> stitchedStrip(const std::vector<Triangle>& triangles)
{
    std::vector<std::uint32_t> strip;
    strip.reserve(2 * triangles.size() + 3);
    const EdgeIndex edges(triangles);
    std::vector<bool> used(triangles.size(), false);
    for (std::uint32_t first = 0; first < triangles.size(); ++first) {
        if (used[first])
            continue;
        used[first] = true;
        startStrip(strip, triangles[first]);
        // The triangle a new vertex w makes is (u, v, w) at an even position and
        // (v, u, w) at an odd one; it must be an unused triangle with that winding.
        for (;;) {
            const std::size_t n = strip.size();
            const std::uint32_t u = strip[n - 2], v = strip[n - 1];
            const bool even = (n - 2) % 2 == 0;
            std::uint32_t next = 0;
            if (!(even ? edges.find(u, v, used, next) : edges.find(v, u, used, next)))
                break;
            used[next] = true;
            strip.push_back(thirdVertex(triangles[next], u, v));
        }
    }
    return strip;
}

std::vector<Triangle> stripTriangles(const std::vector<std::uint32_t>& strip)
{
    std::vector<Triangle> triangles;
    for (std::size_t i = 0; i + 2 < strip.size(); ++i) {
        const Triangle t = i % 2 == 0 ? Triangle{strip[i], strip[i + 1], strip[i + 2]}
                                      : Triangle{strip[i + 1], strip[i], strip[i + 2]};
        if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
            triangles.push_back(t);
    }
    return triangles;
}

std::vector<Triangle> primitiveTriangles(std::int16_t type, const std::vector<std::uint32_t>& v)
{
    std::vector<Triangle> out;
    auto add = [&out](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (a != b && b != c && a != c)
            out.push_back({a, b, c});
    };
    switch (type) {
    case 1: return stripTriangles(v);
    case 2:
    case 4:
        for (std::size_t i = 1; i + 1 < v.size(); ++i)
            add(v[0], v[i], v[i + 1]);
        break;
    case 3:
        for (std::size_t i = 0; i + 3 < v.size(); i += 2) {
            add(v[i], v[i + 1], v[i + 3]);
            add(v[i], v[i + 3], v[i + 2]);
        }
        break;
    default: break;
    }
    return out;
}

}  // namespace cadlod::flt
