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

}  // namespace cadlod::flt
