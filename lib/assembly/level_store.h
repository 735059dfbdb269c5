// The levels of one LOD set (meshes carrying their LodLevel record) as one OpenFlight LOD
// model: each level is converted on its own oneTBB task (independent, read-only), then
// assembled in level order, so the file does not depend on the number of threads.
#pragma once
#include "mesh/core_mesh.h"
#include "openflight/lod_model.h"

#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace cadlod {

// The level meshes of a chain live here until the model is written.
struct LevelStore {
    std::deque<std::unique_ptr<CoreMesh>> meshes;
    CoreMesh& add()
    {
        meshes.push_back(std::make_unique<CoreMesh>());
        return *meshes.back();
    }
};

// Throws std::runtime_error when the set cannot be assembled.
flt::LodModel lodMeshesToModel(const std::vector<CoreMesh*>& meshes, int setId, const std::string& name,
                               std::size_t& skippedFaces);

}  // namespace cadlod
