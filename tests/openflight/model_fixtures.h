// Small neutral LOD models for the OpenFlight tests, and helpers to compare triangles
// independently of vertex order and numbering.
#pragma once

#include "openflight/lod_model.h"
#include "osg_probe.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace cadlod::test {

// A wavy (n x n)-quad sheet: 2n² triangles, (n+1)² vertices with analytic normals.
inline flt::Part wavySheet(int n, double size, const std::string& name, flt::Rgba color, double z0 = 0.0)
{
    flt::Part p;
    p.name = name;
    p.color = color;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            const double x = size * i / n, y = size * j / n;
            const double z = z0 + 0.1 * size * std::sin(x) * std::cos(y);
            p.positions.push_back({x, y, z});
            const double dx = 0.1 * size * std::cos(x) * std::cos(y), dy = -0.1 * size * std::sin(x) * std::sin(y);
            const double len = std::sqrt(dx * dx + dy * dy + 1.0);
            p.normals.push_back({float(-dx / len), float(-dy / len), float(1.0 / len)});
        }
    auto at = [n](int i, int j) { return std::uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            p.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            p.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return p;
}

// A level made of two parts, one with a name too long for an 8-byte ID.
inline flt::Level twoPartLevel(int n, const std::string& suffix)
{
    flt::Level level;
    level.parts.push_back(wavySheet(n, 4.0, "bracket_left_" + suffix, {0.9f, 0.1f, 0.1f, 1.0f}));
    level.parts.push_back(wavySheet(n, 2.0, "pin" + suffix, {0.1f, 0.2f, 0.9f, 1.0f}, 3.0));
    return level;
}

// Three levels with decreasing detail and outward-moving ranges.
inline flt::LodModel threeLevelModel()
{
    flt::LodModel m;
    const int detail[3] = {12, 6, 3};
    const double edges[4] = {0.0, 50.0, 200.0, 1000.0};
    for (int l = 0; l < 3; ++l) {
        flt::Level level = twoPartLevel(detail[l], std::to_string(l));
        level.name = "lod_level_" + std::to_string(l);
        level.switchOut = edges[l];
        level.switchIn = edges[l + 1];
        level.center = {2.0, 2.0, 1.5};
        m.levels.push_back(level);
    }
    return m;
}

inline flt::LodModel singleLevelModel(int n = 8)
{
    flt::LodModel m;
    m.levels.push_back(twoPartLevel(n, "a"));
    return m;
}

// A triangle as 9 floats (positions) + 9 (normals), rotated so that its lexicographically
// smallest corner comes first (keeps the winding).
struct FlatTriangle {
    std::array<std::array<float, 3>, 3> p{};
    std::array<std::array<float, 3>, 3> n{};

    void canonicalize()
    {
        int first = 0;
        for (int k = 1; k < 3; ++k)
            if (p[k] < p[first])
                first = k;
        std::rotate(p.begin(), p.begin() + first, p.end());
        std::rotate(n.begin(), n.begin() + first, n.end());
    }
    bool operator<(const FlatTriangle& o) const { return p < o.p; }
};

// What OpenSceneGraph drew, in the same canonical, sorted form.
inline std::vector<FlatTriangle> osgTriangles(const std::vector<OsgTriangle>& in)
{
    std::vector<FlatTriangle> out;
    for (const OsgTriangle& t : in) {
        FlatTriangle f;
        f.p = t.position;
        f.n = t.normal;
        f.canonicalize();
        out.push_back(f);
    }
    std::sort(out.begin(), out.end());
    return out;
}

inline std::vector<FlatTriangle> flatTriangles(const flt::Part& part, float scale = 1.0f)
{
    std::vector<FlatTriangle> out;
    for (const flt::Triangle& t : part.triangles) {
        FlatTriangle f;
        for (int k = 0; k < 3; ++k) {
            for (int c = 0; c < 3; ++c)
                f.p[k][c] = float(part.positions[t[k]][c]) * scale;
            if (part.hasNormals())
                f.n[k] = part.normals[t[k]];
        }
        f.canonicalize();
        out.push_back(f);
    }
    return out;
}

inline std::vector<FlatTriangle> flatTriangles(const flt::Level& level, float scale = 1.0f)
{
    std::vector<FlatTriangle> out;
    for (const flt::Part& p : level.parts) {
        const auto t = flatTriangles(p, scale);
        out.insert(out.end(), t.begin(), t.end());
    }
    std::sort(out.begin(), out.end());
    return out;
}

// Largest position / normal difference between two sorted triangle lists of equal size.
struct TriangleDiff {
    float position = 0, normal = 0;
};
inline TriangleDiff compareTriangles(const std::vector<FlatTriangle>& a, const std::vector<FlatTriangle>& b)
{
    TriangleDiff d;
    for (std::size_t t = 0; t < std::min(a.size(), b.size()); ++t)
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) {
                d.position = std::max(d.position, std::fabs(a[t].p[k][c] - b[t].p[k][c]));
                d.normal = std::max(d.normal, std::fabs(a[t].n[k][c] - b[t].n[k][c]));
            }
    return d;
}

}  // namespace cadlod::test
