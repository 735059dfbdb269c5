// Triangles as one OpenFlight triangle-strip primitive: each triangle is joined to the
// previous one by degenerate (zero-area) triangles, with its corners ordered so that the
// strip's alternating winding keeps every real triangle's orientation. One primitive per
// part lets OpenSceneGraph build one geometry instead of one per triangle.
#pragma once

#include "lod_model.h"

#include <cstdint>
#include <vector>

namespace cadlod::flt {

std::vector<std::uint32_t> stitchedStrip(const std::vector<Triangle>& triangles);

// The non-degenerate triangles of a strip, in order, with their original winding.
std::vector<Triangle> stripTriangles(const std::vector<std::uint32_t>& strip);

}  // namespace cadlod::flt
