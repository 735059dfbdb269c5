// The tests' vcglib mesh: cadlod::CoreMesh (filter_cadlod/metadata/core_mesh.h), plus PLY
// read/write.
#pragma once

#include "core_mesh.h"

#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/io_mask.h>

#include <string>

namespace cadlod::test {

using TVertex = CoreVertex;
using TFace = CoreFace;
using TestMesh = CoreMesh;

// Loads a PLY; returns false (and says why in `error`) when the file is missing or bad.
bool loadPly(const std::string& path, TestMesh& m, int& mask, std::string& error);
bool loadPly(const std::string& path, TestMesh& m);
// Saves with the given vcg::tri::io::Mask bits (e.g. IOM_FACEQUALITY), binary PLY.
bool savePly(const std::string& path, TestMesh& m, int mask = 0);

}  // namespace cadlod::test
