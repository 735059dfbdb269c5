#include "assembly/level_store.h"

#include "convert/mesh_to_lod_model.h"
#include "openflight/lod_assembly.h"

#include <stdexcept>

#include <tbb/parallel_for.h>

namespace cadlod {
namespace {

flt::LodSetMember memberOf(CoreMesh& m, const std::string& name, std::size_t& skipped)
{
    const LodLevel info = lodLevelHandle(m)();
    mesh_io::LevelOptions options;
    options.label = name;
    options.faceColors = true;
    mesh_io::LevelStats stats;
    flt::LodSetMember member;
    member.setId = info.setId;
    member.level = info.level;
    member.geometry = mesh_io::meshToLevel(m, options, stats);
    member.geometry.switchIn = info.switchIn;
    member.geometry.switchOut = info.switchOut;
    member.geometry.center = info.center;
    skipped = stats.skippedFaces;
    return member;
}

}  // namespace

flt::LodModel lodMeshesToModel(const std::vector<CoreMesh*>& meshes, int setId, const std::string& name,
                               std::size_t& skippedFaces)
{
    std::vector<CoreMesh*> inSet;
    for (CoreMesh* m : meshes)
        if (m && hasLodLevel(*m) && lodLevelHandle(*m)().setId == setId)
            inSet.push_back(m);
    std::vector<flt::LodSetMember> members(inSet.size());
    std::vector<std::size_t> skipped(inSet.size(), 0);
    tbb::parallel_for(std::size_t(0), inSet.size(),
                      [&](std::size_t i) { members[i] = memberOf(*inSet[i], name, skipped[i]); });
    skippedFaces = 0;
    for (std::size_t s : skipped)
        skippedFaces += s;
    flt::LodModel model;
    model.name = name;
    std::string error;
    if (!flt::assembleLodSet(std::move(members), setId, model, error))
        throw std::runtime_error("cannot assemble the LOD set: " + error);
    return model;
}

}  // namespace cadlod
