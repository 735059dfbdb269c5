// A part of an assembly, or a cluster's parts merged, as the simplifier takes it: welded as
// the importer welds a whole model (convert/scene_to_mesh.h), compact, with face normals,
// its box and vertex-face adjacency.
#pragma once

#include "mesh/core_mesh.h"
#include "vrml/part.h"
#include "vrml/scene.h"

#include <cstring>  // before wrap/callback.h, which uses strcpy without including it
#include <string>
#include <vector>

#include <wrap/callback.h>

namespace cadlod {

struct PartWelding {
    bool mergeVertices = true;
    float mergeTolerance = 0.0f;  // in the mesh's own units
};

struct WeldingStats {
    int mergedVertices = 0;
    int degenerateFaces = 0;  // faces welding left with a vertex twice, removed
};

// Compacts `m` and gives it face normals, its box and vertex-face adjacency.
void prepareForSimplifier(CoreMesh& m);

// The scene's parts, welded, into `m` (empty).
WeldingStats weldScene(vrml::Scene& scene, CoreMesh& m, const PartWelding& welding, vcg::CallBackPos* cb);

// `parts` (one part's, or a cluster's) into `m` (empty), ready for the simplifier. Throws
// std::runtime_error naming `name` when no triangle is left.
WeldingStats partToMesh(std::vector<vrml::Part>&& parts, const std::string& name, CoreMesh& m,
                        const PartWelding& welding, vcg::CallBackPos* cb);

}  // namespace cadlod
