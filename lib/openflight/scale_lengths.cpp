#include "openflight/scale_lengths.h"

#include "mesh/lod_level.h"  // kNeverCulled

namespace cadlod::flt {
namespace {

void scalePoint(Vec3d& p, double scale)
{
    for (double& c : p)
        c *= scale;
}

void scaleLevels(std::vector<Level>& levels, double scale)
{
    for (Level& level : levels)
        scaleLengths(level, scale);
}

}  // namespace

void scaleLengths(Level& level, double scale)
{
    level.switchOut *= scale;
    if (level.switchIn < kNeverCulled)
        level.switchIn *= scale;
    scalePoint(level.center, scale);
    for (Part& part : level.parts)
        for (Vec3d& p : part.positions)
            scalePoint(p, scale);
}

void scaleLengths(LodModel& model, double scale) { scaleLevels(model.levels, scale); }

// A placement's rotation and its own scale stay; its translation, in model units, moves.
void scaleLengths(InstancedModel& model, double scale)
{
    for (PartDefinition& definition : model.definitions) {
        scaleLevels(definition.levels, scale);
        forEachChunkLevel(definition.chunks, [&](Level& level) { scaleLengths(level, scale); });
    }
    for (PartPlacement& placement : model.placements)
        for (int row = 0; row < 3; ++row)
            placement.matrix[row][3] *= scale;
    scalePoint(model.origin, scale);
    for (PlacementCluster& cluster : model.clusters) {
        scalePoint(cluster.center, scale);
        scaleLevels(cluster.proxies, scale);
        for (int row = 0; row < 3; ++row)
            cluster.move[row][3] *= scale;
    }
    scaleLevels(model.proxyShapes, scale);
}

}  // namespace cadlod::flt
