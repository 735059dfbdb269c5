// Triangulation of one planar-ish polygon (convex FALSE faces): ear clipping in the
// plane of the polygon's Newell normal. Always yields n-2 triangles (a degenerate or
// self-intersecting rest is fanned) so the result never loses a face.
#pragma once

#include "vrml/math.h"

#include <array>
#include <cstdint>
#include <vector>

namespace cadlod::vrml {

Vec3 newellNormal(const std::vector<Vec3>& polygon);  // length = 2 * area

// Appends triangles as indices into `polygon`, in the polygon's own winding.
void triangulatePolygon(const std::vector<Vec3>& polygon, std::vector<std::array<uint32_t, 3>>& out);

}  // namespace cadlod::vrml
