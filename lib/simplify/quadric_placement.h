// Where a quadric puts the vertex of a collapsed edge: its optimum near the edge, or the
// point of its line of minima nearest the edge's middle, and what a point costs.
#pragma once

#include "simplify/cad_quadrics.h"

#include <vcg/space/point3.h>

#include <algorithm>
#include <cmath>

namespace cadlod {

// Cheapest point of a quadric, when its matrix is well conditioned (scale-free test).
inline bool quadricMinimum(const Quadric& q, vcg::Point3d& x)
{
    const double a = q.a[0], b = q.a[1], c = q.a[2], d = q.a[3], e = q.a[4], f = q.a[5];
    const double c00 = d * f - e * e, c01 = c * e - b * f, c02 = b * e - c * d;
    const double det = a * c00 + b * c01 + c * c02;
    const double norm = std::sqrt(a * a + d * d + f * f + 2 * (b * b + c * c + e * e));
    if (!(norm > 0) || std::abs(det) < 1e-6 * norm * norm * norm)
        return false;
    const double c11 = a * f - c * c, c12 = b * c - a * e, c22 = a * d - b * b;
    const double rx = -0.5 * q.b[0], ry = -0.5 * q.b[1], rz = -0.5 * q.b[2];
    x = vcg::Point3d(c00 * rx + c01 * ry + c02 * rz, c01 * rx + c11 * ry + c12 * rz,
                     c02 * rx + c12 * ry + c22 * rz) / det;
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

// The minimum of q(x) + eps |x - m|^2, eps a small share of q's trace: the quadric's
// optimum where it is well determined, and the point nearest m along the directions where
// it is flat. On a cylinder's strips or along a crease the planes meet in a line, so the
// plain optimum does not exist (quadricMinimum refuses it), but the best placement near
// the edge still lies off the edge, on that line.
inline bool nearestMinimum(const Quadric& q, const vcg::Point3d& m, vcg::Point3d& x)
{
    constexpr double kPullToM = 1e-3;
    const double eps = kPullToM * (q.a[0] + q.a[3] + q.a[5]);
    if (!(eps > 0))
        return false;
    Quadric pulled = q;
    pulled.a[0] += eps;
    pulled.a[3] += eps;
    pulled.a[5] += eps;
    for (int i = 0; i < 3; ++i)
        pulled.b[i] -= 2.0 * eps * m[i];
    return quadricMinimum(pulled, x);
}

// Whether x lies beside the segment p0 -> p1: between its ends, off it by at most a tenth
// of its length (a chord's sag is a few hundredths of it). A minimum along a line could
// otherwise slide far along a crease or an axis, where the quadric sees no cost but the
// faces around stretch past the end of the crease.
inline bool besideTheEdge(const vcg::Point3d& x, const vcg::Point3d& p0, const vcg::Point3d& p1)
{
    const vcg::Point3d e = p1 - p0;
    const double length2 = e.SquaredNorm();
    if (!(length2 > 0))
        return false;
    const double t = ((x - p0) * e) / length2;
    const double off2 = (x - (p0 + e * t)).SquaredNorm();
    return t >= 0.0 && t <= 1.0 && off2 <= length2 / 100.0;
}

// The quadric's own placement for the edge p0 -> p1: its optimum where the planes meet in a
// point, near the edge; where they meet in a line (a cylinder's strips, a crease), the
// point of that line nearest the edge's middle, beside the edge.
inline bool quadricPlacement(const Quadric& q, const vcg::Point3d& p0, const vcg::Point3d& p1, vcg::Point3d& x)
{
    const vcg::Point3d middle = (p0 + p1) * 0.5;
    if (quadricMinimum(q, x))
        return vcg::Distance(x, middle) <= vcg::Distance(p0, p1);
    return nearestMinimum(q, middle, x) && besideTheEdge(x, p0, p1);
}

inline double applyQuadric(const Quadric& q, const vcg::Point3d& p)
{
    return std::max(0.0, q.Apply(p));
}

}  // namespace cadlod
