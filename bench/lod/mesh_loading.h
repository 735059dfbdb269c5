// Loading a bench input into a TestMesh: PLY through vcglib, VRML (97, 1.0, gzip) through
// cadlod's reader and mesh_io's scene conversion (welded, one cadlod part per VRML part).
#pragma once

#include "test_mesh.h"

#include "convert/scene_to_mesh.h"
#include "vrml/importer.h"

#include <string>

namespace cadlod::bench {

inline bool loadMesh(const std::string& path, test::TestMesh& m, std::string& error)
{
    if (path.size() > 4 && path.compare(path.size() - 4, 4, ".ply") == 0) {
        int mask = 0;
        return test::loadPly(path, m, mask, error);
    }
    vrml::ImportResult r = vrml::importVrmlFile(path, vrml::ImportOptions{});
    if (!r.ok()) {
        error = r.error;
        return false;
    }
    mesh_io::sceneToMesh(r.scene, m, mesh_io::SceneToMeshOptions{});
    return true;
}

}  // namespace cadlod::bench
