// The neutral LOD model the OpenFlight writer takes and the reader returns: no MeshLab,
// no vcglib. A model is a list of levels (one OpenFlight LOD node each); a level is a
// list of parts (one OpenFlight Object each), each an indexed triangle mesh.
#pragma once

#include "mesh/part_identity.h"

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace cadlod::flt {

// OpenFlight header "vertex coordinate units" codes (byte 62).
enum class Units : std::uint8_t { Meters = 0, Kilometers = 1, Feet = 4, Inches = 5, NauticalMiles = 8 };

using Vec3d = std::array<double, 3>;
using Vec3f = std::array<float, 3>;
using Vec2f = std::array<float, 2>;
using Triangle = std::array<std::uint32_t, 3>;  // indices into the part's vertex arrays
using Mat4d = std::array<std::array<double, 4>, 4>;  // [row][column], p' = M p

Mat4d multiply(const Mat4d& a, const Mat4d& b);  // a b: b applied first
Mat4d translationMatrix(const Vec3d& t);          // moves every point by t
Vec3d transformed(const Mat4d& m, const Vec3d& p);  // the point p placed by m
double distance(const Vec3d& a, const Vec3d& b);    // between two points
Mat4d inverse(const Mat4d& m);                   // an affine placement undone (its 3x3 part invertible)
double determinant3(const Mat4d& m);             // of the 3x3 part: negative for a mirror
bool turns(const Mat4d& m);                      // its 3x3 part is not exactly the identity
bool mirrors(const Mat4d& m);                    // its 3x3 part's determinant is negative
double largestScale(const Mat4d& m);             // the longest of its 3x3 part's columns
bool isIdentity(const Mat4d& m);                 // neither turns nor moves
using cadlod::Rgba;                             // 0..1

// One Object: the part's identity (Object name in a Long ID record, colour) and its
// own indexed vertex pool. A part whose faces have different colours (per-face colours of
// a CAD export) lists one colour per triangle; without that list every face has `color`.
struct Part : PartIdentity {
    std::vector<Vec3d> positions;
    std::vector<Vec3f> normals;  // one per position, or empty
    std::vector<Vec2f> uvs;      // one per position, or empty
    std::vector<Triangle> triangles;
    std::vector<Rgba> triangleColors;  // one per triangle, or empty (all `color`)
    std::vector<Rgba> vertexColors;    // one per position, or empty: drawn instead of face colours

    bool hasVertexColors() const { return !positions.empty() && vertexColors.size() == positions.size(); }

    bool hasTriangleColors() const { return !triangles.empty() && triangleColors.size() == triangles.size(); }
    const Rgba& colorOf(std::size_t triangle) const
    {
        return hasTriangleColors() ? triangleColors[triangle] : color;
    }

    bool hasNormals() const { return !positions.empty() && normals.size() == positions.size(); }
    bool hasUvs() const { return !positions.empty() && uvs.size() == positions.size(); }
};

// Where a part's vertices stand in another part built from some of its triangles: one entry
// per vertex of the first, kNotCopied until the vertex is copied.
inline constexpr std::uint32_t kNotCopied = std::numeric_limits<std::uint32_t>::max();

// Vertex `v` of `from` in `to`: copied there with its attributes the first time, and its
// index in `to` kept in `copied` (sized to `from`'s vertices, kNotCopied where not yet copied).
std::uint32_t copiedVertex(const Part& from, std::uint32_t v, std::vector<std::uint32_t>& copied, Part& to);

struct Level {
    std::string name;
    double switchIn = 0.0;   // FAR distance: visible while switchOut <= d < switchIn
    double switchOut = 0.0;  // NEAR distance
    Vec3d center{0, 0, 0};
    std::vector<Part> parts;

    bool hasRange() const { return switchIn > switchOut; }
    std::size_t triangleCount() const;
    double reachFrom(const Vec3d& point) const;  // the largest distance from `point` to a vertex
};

struct LodModel {
    std::string name = "cadlod";
    Units units = Units::Meters;
    std::vector<Level> levels;

    std::size_t triangleCount() const;
};

const char* unitsName(Units units);
// Accepts the header codes above; false for any other byte.
bool unitsFromCode(int code, Units& units);

}  // namespace cadlod::flt
