// The identity of a CAD part: its name and colour. It is the one thing about a part that
// every stage carries unchanged: the VRML reader finds it (vrml::Part), the mesh keeps it
// in its part table (layer_metadata.h), the OpenFlight writer and reader store it in an
// Object (flt::Part). Those types add their own geometry to it, which differs on purpose
// (float positions, per-vertex colours and textures from VRML; double positions and a
// level's local vertex pool in OpenFlight). Plain data: no vcglib, no MeshLab.
#pragma once

#include <array>
#include <string>

namespace cadlod {

using Rgba = std::array<float, 4>;  // 0..1

struct PartIdentity {
    std::string name;                       // nearest DEF name or node path; Object name in .flt
    Rgba color{0.8f, 0.8f, 0.8f, 1.0f};     // diffuse RGBA (alpha = 1 - transparency)
};

}  // namespace cadlod
