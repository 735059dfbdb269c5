#include "assembly_convert.h"

#include "cli_errors.h"
#include "progress_bar.h"

#include "lod/lod_chain.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace cadlod::cli {
namespace {

flt::Mat4d toFlt(const vrml::Mat4& m)
{
    flt::Mat4d out{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            out[r][c] = m.m[r][c];
    return out;
}

// The distinct geometries the placements use, in order of first placement.
std::vector<std::size_t> placedGeometries(const std::vector<vrml::Placement>& placements,
                                          std::map<std::size_t, std::size_t>& definitionOf)
{
    std::vector<std::size_t> order;
    for (const vrml::Placement& p : placements)
        if (definitionOf.emplace(p.geometry, order.size()).second)
            order.push_back(p.geometry);
    return order;
}

double radiusAbout(const flt::Level& level)
{
    double r2 = 0;
    for (const flt::Part& part : level.parts)
        for (const flt::Vec3d& p : part.positions) {
            const double dx = p[0] - level.center[0], dy = p[1] - level.center[1], dz = p[2] - level.center[2];
            r2 = std::max(r2, dx * dx + dy * dy + dz * dz);
        }
    return std::sqrt(r2);
}

// A part's LOD node picks its level by the eye's distance to the part's centre. Pushed out
// by the part's radius, every switch keeps its promise at the part's nearest point too: a
// viewer beside a long part is nearer to its end than to its centre.
void holdAtNearestPoint(std::vector<flt::Level>& levels, LodSetResult& result)
{
    if (levels.empty())
        return;
    const double radius = radiusAbout(levels.front());
    auto shift = [radius](double& d) {
        if (d > 0 && d < kNeverCulled)
            d += radius;
    };
    for (flt::Level& l : levels) {
        shift(l.switchIn);
        shift(l.switchOut);
    }
    for (LodLevel& l : result.levels) {
        shift(l.switchIn);
        shift(l.switchOut);
    }
}

PartChain convertPart(vrml::Geometry& geometry, const ImportSettings& settings, const BuildChain& buildChain,
                      flt::PartDefinition& definition, std::size_t& skippedFaces)
{
    PartChain chain;
    chain.name = geometry.name;
    CoreMesh original;
    LoadedMesh info;
    partToMesh(std::move(geometry.parts), geometry.name, original, settings, info);
    chain.triangles = original.fn;
    LevelStore store;
    chain.result = buildChain(original, store);
    if (!chain.result.ok())
        throw InputError("part " + geometry.name + ": " + chain.result.error);
    std::vector<CoreMesh*> meshes{&original};
    for (auto& m : store.meshes)
        meshes.push_back(m.get());
    std::size_t skipped = 0;
    flt::LodModel levels = lodMeshesToModel(meshes, chain.result.levels.front().setId, geometry.name, skipped);
    skippedFaces += skipped;
    definition.name = geometry.name;
    definition.levels = std::move(levels.levels);
    holdAtNearestPoint(definition.levels, chain.result);
    return chain;
}

}  // namespace

AssemblyConversion convertAssembly(vrml::Scene& scene, const std::string& modelName, const ImportSettings& settings,
                                   const BuildChain& buildChain)
{
    // What no shared node holds is placed under the input file's name.
    const std::vector<vrml::Placement> placements =
        vrml::flattenPlacements(scene.assembly, scene.assembly.empty() ? modelName : scene.assembly.geometries[0].name);
    std::map<std::size_t, std::size_t> definitionOf;
    const std::vector<std::size_t> geometries = placedGeometries(placements, definitionOf);
    AssemblyConversion out;
    out.model.name = modelName;
    out.model.definitions.resize(geometries.size());
    std::size_t done = 0, total = 0;
    for (std::size_t g : geometries)
        total += scene.assembly.geometries[g].triangleCount();
    for (std::size_t d = 0; d < geometries.size(); ++d) {
        vrml::Geometry& geometry = scene.assembly.geometries[geometries[d]];
        const std::size_t triangles = geometry.triangleCount();
        progress::beginSpan(int(100 * done / std::max<std::size_t>(total, 1)),
                            int(100 * (done + triangles) / std::max<std::size_t>(total, 1)),
                            "part " + std::to_string(d + 1) + "/" + std::to_string(geometries.size()) + " " +
                                geometry.name);
        out.parts.push_back(convertPart(geometry, settings, buildChain, out.model.definitions[d], out.skippedFaces));
        progress::endSpan();
        done += triangles;
    }
    for (const vrml::Placement& p : placements) {
        const std::size_t d = definitionOf.at(p.geometry);
        out.model.placements.push_back({p.path, toFlt(p.matrix), d});
        ++out.parts[d].placements;
    }
    return out;
}

}  // namespace cadlod::cli
