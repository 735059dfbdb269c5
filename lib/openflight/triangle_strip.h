// Triangles as one OpenFlight triangle-strip primitive. Strips are grown greedily across
// shared edges (each new vertex adds a triangle of the right winding); separate strips
// are joined by degenerate (zero-area) triangles, padded so that every strip starts at
// an even position and keeps its orientation. One primitive per part lets
// OpenSceneGraph build one geometry instead of one per triangle.
#pragma once

#include "openflight/lod_model.h"

#include <cstdint>
#include <vector>

namespace cadlod::flt {

std::vector<std::uint32_t> stitchedStrip(const std::vector<Triangle>& triangles);

// The non-degenerate triangles of a strip, in order, with their original winding.
std::vector<Triangle> stripTriangles(const std::vector<std::uint32_t>& strip);

// The non-degenerate triangles of a Mesh Primitive record of `type`: a triangle strip (1), a
// fan (2), a quadrilateral strip (3) or a polygon (4, fanned); none for another type.
std::vector<Triangle> primitiveTriangles(std::int16_t type, const std::vector<std::uint32_t>& indices);

}  // namespace cadlod::flt
