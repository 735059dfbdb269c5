// Triangle compactness (Guéziec): c = 4*sqrt(3)*A / (l0² + l1² + l2²).
// 1 for an equilateral triangle, towards 0 for slivers and needles, exactly 0 for
// zero-area or non-finite triangles. Used by the simplifier's tie-break, the
// "Compute Triangle Compactness" filter, the LOD reports and the benchmarks.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace cadlod {

// From twice the area and the sum of the squared edge lengths (the simplifier has both
// at hand when it scores a placement).
inline double compactnessFrom(double doubleArea, double sumSquaredEdges)
{
    if (!(sumSquaredEdges > 0.0) || !std::isfinite(sumSquaredEdges) || !std::isfinite(doubleArea))
        return 0.0;
    // 4*sqrt(3)*A = 2*sqrt(3)*(2A)
    const double c01 = 2.0 * std::sqrt(3.0) * doubleArea / sumSquaredEdges;
    return std::min(1.0, c01);  // rounding can push an equilateral a hair above 1
}

// Works on any point type with operator[] (vcg::Point3f/d, std::array, ...).
// Computed in double whatever the input precision, so float meshes do not lose
// the small areas that tell slivers apart.
template <class Point>
double compactness(const Point& a, const Point& b, const Point& c)
{
    const double ux = double(b[0]) - a[0], uy = double(b[1]) - a[1], uz = double(b[2]) - a[2];
    const double vx = double(c[0]) - a[0], vy = double(c[1]) - a[1], vz = double(c[2]) - a[2];
    const double wx = vx - ux, wy = vy - uy, wz = vz - uz;
    const double sumSquaredEdges = ux * ux + uy * uy + uz * uz + vx * vx + vy * vy + vz * vz
                                 + wx * wx + wy * wy + wz * wz;
    const double cx = uy * vz - uz * vy, cy = uz * vx - ux * vz, cz = ux * vy - uy * vx;
    return compactnessFrom(std::sqrt(cx * cx + cy * cy + cz * cz), sumSquaredEdges);
}

struct CompactnessStats {
    std::size_t faces = 0;
    double mean = 0.0;
    double min = 0.0;
    double p5 = 0.0;            // 5th percentile, nearest-rank
    double shareBelow01 = 0.0;  // fraction of faces with c < 0.1
    double shareBelow03 = 0.0;  // fraction of faces with c < 0.3
};

// Statistics of a set of per-face compactness values (consumed: partially sorted).
inline CompactnessStats summarizeCompactness(std::vector<double>& values)
{
    CompactnessStats s;
    s.faces = values.size();
    if (values.empty())
        return s;
    double sum = 0.0;
    std::size_t below01 = 0, below03 = 0;
    s.min = values.front();
    for (double v : values) {
        sum += v;
        s.min = std::min(s.min, v);
        below01 += v < 0.1;
        below03 += v < 0.3;
    }
    const double n = double(values.size());
    s.mean = sum / n;
    s.shareBelow01 = double(below01) / n;
    s.shareBelow03 = double(below03) / n;
    const std::size_t rank = std::size_t(std::ceil(0.05 * n));
    const std::size_t index = rank == 0 ? 0 : rank - 1;
    std::nth_element(values.begin(), values.begin() + index, values.end());
    s.p5 = values[index];
    return s;
}

// Compactness of every live face of a vcglib mesh, in face order (deleted faces skipped).
template <class MeshType>
std::vector<double> faceCompactness(const MeshType& m)
{
    std::vector<double> values;
    values.reserve(m.fn);
    for (const auto& f : m.face)
        if (!f.IsD())
            values.push_back(compactness(f.cP(0), f.cP(1), f.cP(2)));
    return values;
}

template <class MeshType>
CompactnessStats meshCompactness(const MeshType& m)
{
    std::vector<double> values = faceCompactness(m);
    return summarizeCompactness(values);
}

}  // namespace cadlod
