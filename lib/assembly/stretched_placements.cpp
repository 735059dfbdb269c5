#include "assembly/stretched_placements.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <utility>

namespace cadlod {
namespace {

// A placement's linear part as the turn R that follows the stretch P: M = R P, P symmetric
// and positive (semi)definite, R orthogonal (a mirror when M is one).
struct TurnAndStretch {
    Eigen::Matrix3d turn;
    Eigen::Matrix3d stretch;
    double anisotropy = 1;  // largest principal scale over the smallest; 1 when flattened
};

// A placement that flattens its part (a scale of 0 along some axis) is left as written: built
// in, the stretch would leave the part no area, while the placement draws nothing anyway.
constexpr double kFlattened = 1e-9;

TurnAndStretch decompose(const vrml::Mat4& m)
{
    Eigen::Matrix3d linear;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            linear(r, c) = m.m[r][c];
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(linear, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Vector3d scales = svd.singularValues();  // largest first
    TurnAndStretch out;
    out.turn = svd.matrixU() * svd.matrixV().transpose();
    out.stretch = svd.matrixV() * scales.asDiagonal() * svd.matrixV().transpose();
    out.anisotropy = scales(2) > kFlattened * scales(0) ? scales(0) / scales(2) : 1.0;
    return out;
}

// Stretches alike to within rounding share a key.
using StretchKey = std::pair<std::size_t, std::array<long long, 9>>;

StretchKey keyOf(std::size_t geometry, const Eigen::Matrix3d& stretch)
{
    const double unit = std::max(stretch.norm(), 1e-300);
    StretchKey key{geometry, {}};
    for (int i = 0; i < 9; ++i)
        key.second[i] = std::llround(stretch(i / 3, i % 3) / unit * 1e9);
    return key;
}

// `geometry`'s parts with `stretch` built in. Normals go through its cofactor matrix (the
// inverse transpose times the determinant, which is positive), so that a flattened stretch
// still gives them a direction.
vrml::Geometry stretched(const vrml::Geometry& geometry, const Eigen::Matrix3d& stretch, std::size_t number)
{
    vrml::Geometry out;
    out.name = geometry.name + " stretched" + (number > 1 ? " " + std::to_string(number) : "");
    out.parts = geometry.parts;
    Eigen::Matrix3d cofactor;
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            cofactor(r, c) = stretch((r + 1) % 3, (c + 1) % 3) * stretch((r + 2) % 3, (c + 2) % 3) -
                             stretch((r + 1) % 3, (c + 2) % 3) * stretch((r + 2) % 3, (c + 1) % 3);
    for (vrml::Part& part : out.parts) {
        for (vrml::Vec3f& p : part.positions) {
            const Eigen::Vector3d q = stretch * Eigen::Vector3d(p[0], p[1], p[2]);
            p = {float(q(0)), float(q(1)), float(q(2))};
        }
        for (vrml::Vec3f& n : part.normals) {
            const Eigen::Vector3d q = cofactor * Eigen::Vector3d(n[0], n[1], n[2]);
            const double length = q.norm();
            if (length > 0)
                n = {float(q(0) / length), float(q(1) / length), float(q(2) / length)};
        }
    }
    return out;
}

}  // namespace

std::size_t buildStretchesIn(vrml::Assembly& assembly, std::vector<vrml::Placement>& placements)
{
    std::map<StretchKey, std::size_t> made;
    std::map<std::size_t, std::size_t> stretchesOf;  // per geometry, for their names
    std::size_t count = 0;
    for (vrml::Placement& placement : placements) {
        const TurnAndStretch parts = decompose(placement.matrix);
        if (parts.anisotropy <= 1 + kStretchTolerance)
            continue;
        const StretchKey key = keyOf(placement.geometry, parts.stretch);
        auto found = made.find(key);
        if (found == made.end()) {
            const vrml::Geometry variant = stretched(assembly.geometries[placement.geometry], parts.stretch,
                                                     ++stretchesOf[placement.geometry]);
            found = made.emplace(key, assembly.geometries.size()).first;
            assembly.geometries.push_back(variant);
        }
        placement.geometry = found->second;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c)
                placement.matrix.m[r][c] = parts.turn(r, c);
        ++count;
    }
    return count;
}

}  // namespace cadlod
