// Small vector and 4x4 matrix types for scene evaluation (double precision while
// composing transforms; the scene stores float).
#pragma once

#include <array>
#include <cmath>

namespace cadlod::vrml {

struct Vec3 {
    double x = 0, y = 0, z = 0;
    Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
    Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
    Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
    Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
};

inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double length(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline Vec3 normalized(const Vec3& a)
{
    const double l = length(a);
    return l > 0 ? a * (1.0 / l) : Vec3{0, 0, 0};
}

// Column-vector convention: p' = M * p, m[row][col].
struct Mat4 {
    std::array<std::array<double, 4>, 4> m{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};

    static Mat4 identity() { return {}; }
    static Mat4 translation(const Vec3& t);
    static Mat4 scale(const Vec3& s);
    static Mat4 rotation(const Vec3& axis, double angle);  // zero axis: identity

    Mat4 operator*(const Mat4& o) const;
    Vec3 transformPoint(const Vec3& p) const;
    Vec3 transformVector(const Vec3& v) const;
    double determinant3() const;
    // Inverse transpose of the upper 3x3, for normals (not normalized).
    Mat4 normalMatrix() const;
};

}  // namespace cadlod::vrml
