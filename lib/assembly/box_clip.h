// A triangle cut to a box (Sutherland–Hodgman against its six planes): what of it lies inside,
// as a fan of triangles whose new corners carry their normals, texture coordinates and colours
// interpolated along the cut edges.
#pragma once

#include "lod/cluster_tree.h"     // Box3
#include "openflight/lod_model.h"  // flt::Part

#include <cstddef>

namespace cadlod {

// Appends to `out` the part of triangle `t` of `part` inside `box`, with corners of its own;
// nothing where the triangle misses the box. `out` has `part`'s attributes (normals, texture
// coordinates, vertex or triangle colours) wherever `part` has them.
void appendClippedTriangle(const flt::Part& part, std::size_t t, const Box3& box, flt::Part& out);

}  // namespace cadlod
