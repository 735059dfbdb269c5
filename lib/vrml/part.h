// A part as read: an indexed triangle mesh with optional per-vertex normals, colors and
// texture coordinates and optional per-triangle colors. No MeshLab dependency.
#pragma once

#include "mesh/part_identity.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cadlod::vrml {

using Vec3f = std::array<float, 3>;
using Vec2f = std::array<float, 2>;
using Rgba8 = std::array<uint8_t, 4>;

// A part as read: its identity (nearest DEF name, or the node path; material diffuse
// + (1 - transparency)) and its triangles.
struct Part : PartIdentity {
    std::vector<Vec3f> positions;
    std::vector<Vec3f> normals;       // empty or one per position
    std::vector<Rgba8> colors;        // empty or one per position
    std::vector<Vec2f> texCoords;     // empty or one per position
    std::string texture;              // image file (resolved path) or empty
    std::vector<uint32_t> triangles;  // 3 indices per triangle, counter-clockwise front
    std::vector<Rgba8> faceColors;    // empty or one per triangle
    // Whose faces these are: the Parts of one owner (one per colour) are one CAD part.
    // `named`: the owner is a DEF'd node, a part the CAD system named, not a shape named by
    // its path.
    int owner = -1;
    bool named = false;

    size_t triangleCount() const { return triangles.size() / 3; }
};

}  // namespace cadlod::vrml
