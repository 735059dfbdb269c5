#include "openflight/lod_model.h"

#include <algorithm>
#include <cmath>

namespace cadlod::flt {

Mat4d multiply(const Mat4d& a, const Mat4d& b)
{
    Mat4d out{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            for (int k = 0; k < 4; ++k)
                out[r][c] += a[r][k] * b[k][c];
    return out;
}

Mat4d translationMatrix(const Vec3d& t)
{
    return {{{1, 0, 0, t[0]}, {0, 1, 0, t[1]}, {0, 0, 1, t[2]}, {0, 0, 0, 1}}};
}

Vec3d transformed(const Mat4d& m, const Vec3d& p)
{
    Vec3d out{};
    for (int r = 0; r < 3; ++r)
        out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3];
    return out;
}

std::uint32_t copiedVertex(const Part& from, std::uint32_t v, std::vector<std::uint32_t>& copied, Part& to)
{
    if (copied[v] == kNotCopied) {
        copied[v] = std::uint32_t(to.positions.size());
        to.positions.push_back(from.positions[v]);
        if (from.hasNormals())
            to.normals.push_back(from.normals[v]);
        if (from.hasUvs())
            to.uvs.push_back(from.uvs[v]);
        if (from.hasVertexColors())
            to.vertexColors.push_back(from.vertexColors[v]);
    }
    return copied[v];
}

double distance(const Vec3d& a, const Vec3d& b)
{
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

double determinant3(const Mat4d& m)
{
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// The 3x3 part inverted (its cofactors over its determinant), the shift turned back.
Mat4d inverse(const Mat4d& m)
{
    const double det = determinant3(m);
    Mat4d out{};
    out[3][3] = 1;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
            out[r][c] = (m[r1][c1] * m[r2][c2] - m[r1][c2] * m[r2][c1]) / det;
        }
    for (int r = 0; r < 3; ++r)
        out[r][3] = -(out[r][0] * m[0][3] + out[r][1] * m[1][3] + out[r][2] * m[2][3]);
    return out;
}

bool turns(const Mat4d& m)
{
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            if (m[r][c] != (r == c ? 1.0 : 0.0))
                return true;
    return false;
}

bool mirrors(const Mat4d& m)
{
    return determinant3(m) < 0;
}

double largestScale(const Mat4d& m)
{
    double s = 0;
    for (int c = 0; c < 3; ++c)
        s = std::max(s, std::sqrt(m[0][c] * m[0][c] + m[1][c] * m[1][c] + m[2][c] * m[2][c]));
    return s;
}

bool isIdentity(const Mat4d& m)
{
    return !turns(m) && m[0][3] == 0 && m[1][3] == 0 && m[2][3] == 0;
}

std::size_t Level::triangleCount() const
{
    std::size_t n = 0;
    for (const Part& p : parts)
        n += p.triangles.size();
    return n;
}

double Level::reachFrom(const Vec3d& point) const
{
    double r2 = 0;
    for (const Part& part : parts)
        for (const Vec3d& p : part.positions) {
            const double dx = p[0] - point[0], dy = p[1] - point[1], dz = p[2] - point[2];
            r2 = std::max(r2, dx * dx + dy * dy + dz * dz);
        }
    return std::sqrt(r2);
}

std::size_t LodModel::triangleCount() const
{
    std::size_t n = 0;
    for (const Level& l : levels)
        n += l.triangleCount();
    return n;
}

const char* unitsName(Units units)
{
    switch (units) {
    case Units::Meters: return "meters";
    case Units::Kilometers: return "kilometers";
    case Units::Feet: return "feet";
    case Units::Inches: return "inches";
    case Units::NauticalMiles: return "nautical miles";
    }
    return "unknown";
}

bool unitsFromCode(int code, Units& units)
{
    switch (code) {
    case 0: case 1: case 4: case 5: case 8:
        units = static_cast<Units>(code);
        return true;
    default:
        return false;
    }
}

}  // namespace cadlod::flt
