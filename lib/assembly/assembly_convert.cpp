#include "assembly/assembly_convert.h"

#include "assembly/parallel_tasks.h"

#include "assembly/part_chunks.h"
#include "assembly/stretched_placements.h"

#include "lod/cluster_tree.h"  // Box3
#include "lod/lod_chain.h"
#include "lod/scale_lengths.h"
#include "lod/nearest_point.h"
#include "openflight/scale_lengths.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace cadlod {
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

// The box of every placement's geometry, where it is placed.
Box3 placedBox(const vrml::Assembly& assembly, const std::vector<vrml::Placement>& placements)
{
    std::vector<Box3> local(assembly.geometries.size());
    for (std::size_t g = 0; g < assembly.geometries.size(); ++g)
        for (const vrml::Part& part : assembly.geometries[g].parts)
            for (const auto& p : part.positions)
                local[g].add(std::array<double, 3>{p[0], p[1], p[2]});
    Box3 placed;
    for (const vrml::Placement& p : placements) {
        const Box3& b = local[p.geometry];
        if (b.empty())
            continue;
        for (int corner = 0; corner < 8; ++corner) {
            const vrml::Vec3 w = p.matrix.transformPoint(
                {corner & 1 ? b.hi[0] : b.lo[0], corner & 2 ? b.hi[1] : b.lo[1], corner & 4 ? b.hi[2] : b.lo[2]});
            placed.add(std::array<double, 3>{w.x, w.y, w.z});
        }
    }
    return placed;
}

// How far each level's vertices reach from its centre.
std::vector<double> reachOf(const std::vector<flt::Level>& levels)
{
    std::vector<double> reach;
    for (const flt::Level& level : levels)
        reach.push_back(level.reachFrom(level.center));
    return reach;
}

// Keeps the `kept` levels of a chain result, and what it says of each.
void keepLevels(LodSetResult& result, const std::vector<std::size_t>& kept)
{
    const LodSetResult all = result;
    result.levels.clear();
    result.compactness.clear();
    result.distance.clear();
    result.steps.clear();
    for (std::size_t k : kept) {
        result.levels.push_back(all.levels[k]);
        if (all.compactness.size() == all.levels.size())
            result.compactness.push_back(all.compactness[k]);
        if (all.distance.size() == all.levels.size())
            result.distance.push_back(all.distance[k]);
        if (k > 0 && all.steps.size() + 1 == all.levels.size())
            result.steps.push_back(all.steps[k - 1]);
    }
}

// Where the first simplified level of `levels` is switched in once held at the nearest point
// (0: it has one level).
double firstHeldSwitch(const std::vector<flt::Level>& levels)
{
    std::vector<flt::Level> ranges(levels.size());
    for (std::size_t k = 0; k < levels.size(); ++k) {
        ranges[k].switchIn = levels[k].switchIn;
        ranges[k].switchOut = levels[k].switchOut;
    }
    cadlod::holdAtNearestPoint(ranges, reachOf(levels));
    return ranges.size() > 1 ? ranges[1].switchOut : 0.0;
}

// A part's LOD node picks its level by the eye's distance to the part's centre; moved out
// as nearest_point.h says, every switch keeps its promise at the part's nearest point too.
void holdAtNearestPoint(std::vector<flt::Level>& levels, LodSetResult& result)
{
    if (levels.empty())
        return;
    const std::vector<double> reach = reachOf(levels);
    const std::vector<std::size_t> kept = cadlod::holdAtNearestPoint(levels, reach);
    if (result.levels.size() != reach.size())
        return;
    std::vector<LodLevel> ranges = result.levels;
    cadlod::holdAtNearestPoint(ranges, reach);
    keepLevels(result, kept);
    for (std::size_t i = 0; i < kept.size(); ++i) {
        result.levels[i].switchIn = ranges[i].switchIn;
        result.levels[i].switchOut = ranges[i].switchOut;
        result.levels[i].level = int(i);
    }
}

PartChain convertPart(vrml::Geometry& geometry, const PartWelding& welding, const BuildChain& buildChain,
                      double smallestChunkedRadius, flt::PartDefinition& definition, std::size_t& skippedFaces,
                      const ProgressSpans& progress)
{
    PartChain chain;
    chain.name = geometry.name;
    CoreMesh original;
    WeldingStats welded;
    {
        ProgressSpan span(progress, 0, kWeldingShare);
        welded = partToMesh(std::move(geometry.parts), geometry.name, original, welding, progress.step);
    }
    chain.triangles = original.fn;
    chain.weldedVertices = welded.mergedVertices;
    chain.degenerateFaces = welded.degenerateFaces;
    LevelStore store;
    {
        ProgressSpan span(progress, kWeldingShare, 100);
        chain.result = buildChain(original, store, progress.step);
    }
    if (!chain.result.ok())
        throw std::runtime_error("part " + geometry.name + ": " + chain.result.error);
    std::vector<CoreMesh*> meshes{&original};
    for (auto& m : store.meshes)
        meshes.push_back(m.get());
    std::size_t skipped = 0;
    flt::LodModel levels = lodMeshesToModel(meshes, chain.result.levels.front().setId, geometry.name, skipped);
    skippedFaces += skipped;
    definition.name = geometry.name;
    definition.levels = std::move(levels.levels);
    std::vector<double> errors;
    for (const LodLevel& level : chain.result.levels)
        errors.push_back(level.hausdorffMax);
    definition.chunks = chunkLevels(definition.name, definition.levels, errors, smallestChunkedRadius,
                                    firstHeldSwitch(definition.levels));
    holdAtNearestPoint(definition.levels, chain.result);
    return chain;
}

}  // namespace

AssemblyConversion convertAssembly(vrml::Scene& scene, const std::string& modelName, const PartWelding& welding,
                                   const BuildChain& buildChain, bool chunkLargeParts, const ProgressSpans& progress)
{
    // What no shared node holds is placed under the input file's name.
    std::vector<vrml::Placement> placements =
        vrml::flattenPlacements(scene.assembly, scene.assembly.empty() ? modelName : scene.assembly.geometries[0].name);
    const std::size_t stretchedPlacements = buildStretchesIn(scene.assembly, placements);
    std::map<std::size_t, std::size_t> definitionOf;
    const std::vector<std::size_t> geometries = placedGeometries(placements, definitionOf);
    AssemblyConversion out;
    out.stretchedPlacements = stretchedPlacements;
    out.model.name = modelName;
    out.model.definitions.resize(geometries.size());
    const double chunkedRadius = chunkLargeParts ? kChunkedPartShare * placedBox(scene.assembly, placements).halfDiagonal()
                                                 : std::numeric_limits<double>::infinity();
    std::size_t total = 0;
    std::vector<std::size_t> before;  // the triangles of the parts before each
    for (std::size_t g : geometries) {
        if (scene.assembly.geometries[g].name.empty())  // what no node names: the model's own
            scene.assembly.geometries[g].name = modelName;
        before.push_back(total);
        total += scene.assembly.geometries[g].triangleCount();
    }
    const auto percent = [&](std::size_t triangles) { return int(100 * triangles / std::max<std::size_t>(total, 1)); };
    out.parts.resize(geometries.size());
    std::vector<std::size_t> skipped(geometries.size(), 0);
    runTasks(
        geometries.size(),
        [&](std::size_t d, const ProgressSpans& progress) {
            vrml::Geometry& geometry = scene.assembly.geometries[geometries[d]];
            ProgressSpan span(progress, percent(before[d]), percent(before[d] + geometry.triangleCount()),
                              "part " + std::to_string(d + 1) + "/" + std::to_string(geometries.size()) + " " +
                                  geometry.name);
            out.parts[d] = convertPart(geometry, welding, buildChain, chunkedRadius, out.model.definitions[d],
                                       skipped[d], progress);
        },
        progress);
    for (std::size_t s : skipped)
        out.skippedFaces += s;
    for (const vrml::Placement& p : placements) {
        const std::size_t d = definitionOf.at(p.geometry);
        out.model.placements.push_back({p.path, toFlt(p.matrix), d});
        ++out.parts[d].placements;
    }
    return out;
}

void scaleLengths(AssemblyConversion& c, double factor)
{
    flt::scaleLengths(c.model, factor);
    for (PartChain& part : c.parts)
        scaleLengths(part.result, factor);
}

}  // namespace cadlod
