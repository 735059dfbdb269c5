#include "openflight/local_origin.h"

#include "mesh/float_spacing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cadlod::flt {
namespace {

// Stands off visibly when its coordinates are floats: spaced more than `share` of `size`.
bool standsOff(const Vec3d& p, double size, double share)
{
    for (double c : p)
        if (floatSpacing(c) > share * size)
            return true;
    return false;
}

// A part's own vertices and LOD centre are seen against the part alone: rounded by less than
// this share of its size, the part filling the screen is off by under a pixel. (Placements
// are held to kVisiblePlacementSpacing of the whole model: gaps between parts show sooner.)
constexpr double kVisibleVertexSpacing = 1e-3;

// The nearest float to x, a number a Matrix record holds exactly.
double asFloat(double x)
{
    const double spacing = floatSpacing(x);
    return spacing == 0 ? x : std::round(x / spacing) * spacing;
}

Vec3d asFloats(const Vec3d& p) { return {asFloat(p[0]), asFloat(p[1]), asFloat(p[2])}; }

void shift(Vec3d& p, const Vec3d& by)
{
    for (int a = 0; a < 3; ++a)
        p[a] += by[a];
}

void moveLevel(Level& level, const Vec3d& by)
{
    for (Part& part : level.parts)
        for (Vec3d& p : part.positions)
            shift(p, by);
    shift(level.center, by);
}

void moveChunks(std::vector<PartChunk>& chunks, const Vec3d& by)
{
    forEachChunkLevel(chunks, [&](Level& level) { moveLevel(level, by); });
}

// Where a part's geometry lies far from its own frame's origin (shapes a file placed without
// a Transform, in site coordinates): its centre, a translation a float holds; else zero.
Vec3d ownGeometryOffset(const PartDefinition& definition)
{
    if (definition.levels.empty())
        return {0, 0, 0};
    const Level& finest = definition.levels.front();
    const Vec3d centre = asFloats(finest.center);
    return standsOff(centre, 2.0 * finest.reachFrom(finest.center), kVisibleVertexSpacing) ? centre : Vec3d{0, 0, 0};
}

// Such parts are moved to lie about their own origin, and their placements move them back.
// Returns how many were moved.
std::size_t centreOwnGeometry(InstancedModel& model)
{
    std::vector<Vec3d> offsets;
    std::size_t centred = 0;
    for (PartDefinition& definition : model.definitions) {
        const Vec3d offset = ownGeometryOffset(definition);
        offsets.push_back(offset);
        if (offset == Vec3d{0, 0, 0})
            continue;
        const Vec3d back{-offset[0], -offset[1], -offset[2]};
        for (Level& level : definition.levels)
            moveLevel(level, back);
        moveChunks(definition.chunks, back);
        ++centred;
    }
    for (PartPlacement& p : model.placements)
        if (offsets[p.definition] != Vec3d{0, 0, 0})
            p.matrix = multiply(p.matrix, translationMatrix(offsets[p.definition]));
    return centred;
}

}  // namespace

std::size_t moveToLocalOrigin(InstancedModel& model)
{
    const std::size_t centred = centreOwnGeometry(model);
    const PlacementPrecision precision = placementPrecision(model);
    if (precision.spacing <= kVisiblePlacementSpacing * precision.extent && centred == 0)
        return 0;
    // The model's own centre: its root cluster's, else its placements' mean.
    Vec3d centre{0, 0, 0};
    if (!model.clusters.empty()) {
        centre = model.clusters.front().center;
    } else if (!model.placements.empty()) {
        for (const PartPlacement& p : model.placements)
            for (int a = 0; a < 3; ++a)
                centre[a] += p.matrix[a][3] / double(model.placements.size());
    }
    const Vec3d origin = asFloats(centre);
    const Vec3d back{-origin[0], -origin[1], -origin[2]};
    for (PartPlacement& p : model.placements)
        p.matrix = multiply(translationMatrix(back), p.matrix);
    for (PlacementCluster& cluster : model.clusters) {
        shift(cluster.center, back);
        for (Level& range : cluster.proxies)
            shift(range.center, back);
        cluster.move = multiply(translationMatrix(back), multiply(cluster.move, translationMatrix(origin)));
    }
    for (Level& shape : model.proxyShapes)
        moveLevel(shape, back);
    shift(model.origin, origin);
    return centred;
}

std::string localOriginNote(const InstancedModel& model, std::size_t centred, const std::string& unitName)
{
    if (model.origin == Vec3d{0, 0, 0})
        return {};
    char text[400];
    std::snprintf(text, sizeof text,
                  "the model stands far from the origin, where OpenFlight's 32-bit numbers would place it only to "
                  "%.3g %s: it is written about a local origin at (%.10g, %.10g, %.10g) %s, which its root Group's "
                  "Matrix restores exactly; %zu %s moved to lie about %s own origin",
                  floatSpacing(std::max({std::abs(model.origin[0]), std::abs(model.origin[1]), std::abs(model.origin[2])})),
                  unitName.c_str(), model.origin[0], model.origin[1], model.origin[2], unitName.c_str(), centred,
                  centred == 1 ? "part's geometry was" : "parts' geometry was", centred == 1 ? "its" : "their");
    return text;
}

}  // namespace cadlod::flt
