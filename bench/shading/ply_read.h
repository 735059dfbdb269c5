// A small PLY reader for the shading measure's tools: vertex x y z and face vertex lists
// (polygons fanned into triangles), ascii or binary little-endian; other properties skipped.
#pragma once

#include "shading_error.h"

#include <string>
#include <vector>

namespace cadlod::shading {

// With `faceParts`, also the int face property "part" per triangle (0 where absent).
bool readPly(const std::string& path, IndexedMesh& mesh, std::string& error, std::vector<int>* faceParts = nullptr);

}  // namespace cadlod::shading
