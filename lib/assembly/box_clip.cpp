#include "assembly/box_clip.h"

#include <cmath>
#include <vector>

namespace cadlod {
namespace {

struct Corner {
    flt::Vec3d position{};
    flt::Vec3f normal{};
    flt::Vec2f uv{};
    Rgba color{};
};

Corner cornerOf(const flt::Part& part, std::uint32_t v)
{
    Corner c;
    c.position = part.positions[v];
    if (part.hasNormals())
        c.normal = part.normals[v];
    if (part.hasUvs())
        c.uv = part.uvs[v];
    if (part.hasVertexColors())
        c.color = part.vertexColors[v];
    return c;
}

template <class Array>
Array lerp(const Array& a, const Array& b, double s)
{
    Array out{};
    for (std::size_t i = 0; i < a.size(); ++i)
        out[i] = typename Array::value_type(a[i] + (b[i] - a[i]) * s);
    return out;
}

// Where the edge a-b crosses the plane at `value` along `axis`.
Corner crossing(const Corner& a, const Corner& b, int axis, double value)
{
    const double s = (value - a.position[axis]) / (b.position[axis] - a.position[axis]);
    Corner c;
    c.position = lerp(a.position, b.position, s);
    c.position[axis] = value;
    c.normal = lerp(a.normal, b.normal, s);
    double length = 0;
    for (float n : c.normal)
        length += double(n) * n;
    if (length > 0)
        for (float& n : c.normal)
            n = float(n / std::sqrt(length));
    c.uv = lerp(a.uv, b.uv, s);
    c.color = lerp(a.color, b.color, s);
    return c;
}

// The polygon's part on the side of the plane at `value` along `axis` that `keepBelow` says.
std::vector<Corner> clipped(const std::vector<Corner>& polygon, int axis, double value, bool keepBelow)
{
    std::vector<Corner> out;
    const auto inside = [&](const Corner& c) {
        return keepBelow ? c.position[axis] <= value : c.position[axis] >= value;
    };
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Corner& a = polygon[i];
        const Corner& b = polygon[(i + 1) % polygon.size()];
        if (inside(a))
            out.push_back(a);
        if (inside(a) != inside(b))
            out.push_back(crossing(a, b, axis, value));
    }
    return out;
}

}  // namespace

void appendClippedTriangle(const flt::Part& part, std::size_t t, const Box3& box, flt::Part& out)
{
    std::vector<Corner> polygon;
    for (int k = 0; k < 3; ++k)
        polygon.push_back(cornerOf(part, part.triangles[t][k]));
    for (int axis = 0; axis < 3 && polygon.size() >= 3; ++axis) {
        polygon = clipped(polygon, axis, box.lo[axis], false);
        if (polygon.size() >= 3)
            polygon = clipped(polygon, axis, box.hi[axis], true);
    }
    if (polygon.size() < 3)
        return;
    const auto first = std::uint32_t(out.positions.size());
    for (const Corner& c : polygon) {
        out.positions.push_back(c.position);
        if (part.hasNormals())
            out.normals.push_back(c.normal);
        if (part.hasUvs())
            out.uvs.push_back(c.uv);
        if (part.hasVertexColors())
            out.vertexColors.push_back(c.color);
    }
    for (std::uint32_t k = 1; k + 1 < polygon.size(); ++k) {
        out.triangles.push_back({first, first + k, first + k + 1});
        if (part.hasTriangleColors())
            out.triangleColors.push_back(part.triangleColors[t]);
    }
}

}  // namespace cadlod
