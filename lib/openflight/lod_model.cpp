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
