// Helpers for the VRML core tests: import text the test wrote, and query the scene.
#pragma once

#include "vrml/importer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace cadlod::vrml::test {

inline Scene load(const std::string& text, const ImportOptions& options = {}, const std::string& name = "test.wrl")
{
    ImportResult r = importVrmlText(text, name, options);
    EXPECT_TRUE(r.ok()) << r.error;
    return std::move(r.scene);
}

// World-space corners of every triangle of every part, in emission order.
inline std::vector<std::array<Vec3f, 3>> triangles(const Scene& s)
{
    std::vector<std::array<Vec3f, 3>> out;
    for (const Part& p : s.parts)
        for (size_t t = 0; t < p.triangleCount(); ++t)
            out.push_back({p.positions[p.triangles[3 * t]], p.positions[p.triangles[3 * t + 1]],
                           p.positions[p.triangles[3 * t + 2]]});
    return out;
}

inline Vec3f triangleNormal(const std::array<Vec3f, 3>& t)
{
    const float ux = t[1][0] - t[0][0], uy = t[1][1] - t[0][1], uz = t[1][2] - t[0][2];
    const float vx = t[2][0] - t[0][0], vy = t[2][1] - t[0][1], vz = t[2][2] - t[0][2];
    return {uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
}

inline double area(const std::array<Vec3f, 3>& t)
{
    const Vec3f n = triangleNormal(t);
    return 0.5 * std::sqrt(double(n[0]) * n[0] + double(n[1]) * n[1] + double(n[2]) * n[2]);
}

inline bool hasPoint(const Scene& s, float x, float y, float z, float eps = 1e-5f)
{
    for (const Part& p : s.parts)
        for (const Vec3f& v : p.positions)
            if (std::fabs(v[0] - x) < eps && std::fabs(v[1] - y) < eps && std::fabs(v[2] - z) < eps) return true;
    return false;
}

inline std::string ifs97(const std::string& points, const std::string& indices, const std::string& extra = "")
{
    return "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [ " + points +
           " ] } coordIndex [ " + indices + " ] " + extra + " } }\n";
}

}  // namespace cadlod::vrml::test
