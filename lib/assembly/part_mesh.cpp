#include "assembly/part_mesh.h"

#include "convert/scene_to_mesh.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <stdexcept>

namespace cadlod {

void prepareForSimplifier(CoreMesh& m)
{
    vcg::tri::Allocator<CoreMesh>::CompactEveryVector(m);
    vcg::tri::UpdateNormal<CoreMesh>::PerFaceNormalized(m);
    vcg::tri::UpdateBounding<CoreMesh>::Box(m);
    vcg::tri::UpdateTopology<CoreMesh>::VertexFace(m);
}

WeldingStats weldScene(vrml::Scene& scene, CoreMesh& m, const PartWelding& welding, vcg::CallBackPos* cb)
{
    mesh_io::SceneToMeshOptions toMesh;
    toMesh.mergeVertices = welding.mergeVertices;
    toMesh.mergeTolerance = welding.mergeTolerance;
    mesh_io::SceneToMeshStats stats;
    mesh_io::sceneToMesh(scene, m, toMesh, cb, &stats);
    return {stats.mergedVertices, stats.facesRepeatingVertex};
}

WeldingStats partToMesh(std::vector<vrml::Part>&& parts, const std::string& name, CoreMesh& m,
                        const PartWelding& welding, vcg::CallBackPos* cb)
{
    vrml::Scene scene;
    scene.parts = std::move(parts);
    const WeldingStats stats = weldScene(scene, m, welding, cb);
    if (m.fn == 0)
        throw std::runtime_error(name + ": no triangles in the part");
    prepareForSimplifier(m);
    return stats;
}

}  // namespace cadlod
