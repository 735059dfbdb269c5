// The levels of one LOD set (meshes carrying their LodLevel record) as one OpenFlight LOD
// model: each level is converted on its own oneTBB task (independent, read-only), then
// assembled in level order, so the file does not depend on the number of threads.
#pragma once
#include "mesh/core_mesh.h"
#include "openflight/lod_model.h"

#include <string>
#include <vector>

namespace cadlod::cli {

// Throws InputError when the set cannot be assembled.
flt::LodModel lodMeshesToModel(const std::vector<CoreMesh*>& meshes, int setId, const std::string& name,
                               std::size_t& skippedFaces);

}  // namespace cadlod::cli
