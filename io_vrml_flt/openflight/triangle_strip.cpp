#include "triangle_strip.h"

namespace cadlod::flt {

std::vector<std::uint32_t> stitchedStrip(const std::vector<Triangle>& triangles)
{
    std::vector<std::uint32_t> strip;
    if (triangles.empty())
        return strip;
    strip.reserve(5 * triangles.size());
    strip.insert(strip.end(), triangles[0].begin(), triangles[0].end());
    for (std::size_t t = 1; t < triangles.size(); ++t) {
        const Triangle& tri = triangles[t];
        strip.push_back(strip.back());
        strip.push_back(tri[0]);
        strip.push_back(tri[0]);
        // A strip triangle starting at an odd position is drawn (v1, v0, v2).
        const bool odd = (strip.size() - 1) % 2 == 1;
        strip.push_back(odd ? tri[2] : tri[1]);
        strip.push_back(odd ? tri[1] : tri[2]);
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

}  // namespace cadlod::flt
