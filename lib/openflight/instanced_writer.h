// Writes an assembly of placed parts as OpenFlight (design.md §7, instancing): each distinct
// part's levels once, and a Group with a Matrix per placement, named by its path.
//   Header, palettes, Push Group Push {
//     [Instance Definition n Push {levels} Pop]   before the first placement of a shared part
//     Group Matrix Push { Instance Reference n | levels } Pop
//   }* Pop Pop
// or, with clusters, Group Push { LOD near Push {clusters, placements} Pop, LOD proxy* } Pop
// in place of the list of placements. A proxy drawn by one cluster only is written inside its
// LOD record; one a cluster and its copies draw is an Instance Definition, referenced from
// each one's LOD record (under a Group with the copy's Matrix); a copy seen in a mirror
// draws the shape's mirrored form, its triangles turned round.
// A part placed once is written inside its Group. A part placed in a mirror (negative
// determinant) has a definition of its own, its triangles turned round, so that its faces
// stay outward. OSG drops a Matrix on an Instance Reference, so it goes on the Group.
#pragma once

#include "openflight/flt_writer.h"

#include <string>
#include <vector>

namespace cadlod::flt {

// A piece of a part's levels, switched by its own centre (assembly/part_chunks.h), in a Group
// of its own: drawn as `levels` (finest first, contiguous) from levels.front().switchOut on,
// and nearer than that (childrenDrawnTo) as its `children`, smaller pieces of the same levels.
// A chunk without children starts at its finest level, from 0.
struct PartChunk {
    std::string name;  // its group's (its levels are named after it); numbered after its part when empty
    std::vector<Level> levels;
    std::vector<PartChunk> children;

    double childrenDrawnTo() const { return children.empty() ? 0.0 : levels.front().switchOut; }
};

// `visit(level)` on every level of every chunk, at every depth.
template <class Chunks, class Visit>
void forEachChunkLevel(Chunks& chunks, const Visit& visit)
{
    for (auto& chunk : chunks) {
        for (auto& level : chunk.levels)
            visit(level);
        forEachChunkLevel(chunk.children, visit);
    }
}

struct PartDefinition {
    std::string name;
    std::vector<Level> levels;  // finest first, in the part's own frame
    // Non-empty: what is drawn in place of `levels` nearer than levels[1] is (chunksDrawnTo).
    // A chunked part has two levels or more.
    std::vector<PartChunk> chunks;

    double chunksDrawnTo() const { return levels.size() > 1 ? levels[1].switchOut : 0.0; }
};

struct PartPlacement {
    std::string name;           // unique in the model
    Mat4d matrix{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};  // part frame -> model
    std::size_t definition = 0;

    bool mirrored() const;
};

// Placements near each other (HLOD, design.md §5): drawn as what they hold nearer than
// nearRange() from the centre, as the proxies (their parts merged and simplified) from there
// on. Written as a Group holding a LOD record for the near range, over the child clusters
// and placements, beside one LOD record per proxy.
struct PlacementCluster {
    std::string name;
    Vec3d center{0, 0, 0};
    // Finest first, contiguous ranges: each one's name, range and centre; no parts. Proxy i
    // draws the model's proxyShapes[shapes[i]] moved by `move`: a cluster that is a copy of
    // another (moved, turned or mirrored alike) draws that one's shapes.
    std::vector<Level> proxies;
    std::vector<std::size_t> shapes;
    Mat4d move{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    std::vector<std::size_t> clusters;    // the clusters below, by index (greater than this one's)
    std::vector<std::size_t> placements;  // the placements in it, by index

    double nearRange() const { return proxies.empty() ? 0.0 : proxies.front().switchOut; }
    bool mirrored() const { return mirrors(move); }  // a copy seen in a mirror
};

struct InstancedModel {
    std::string name = "cadlod";
    Units units = Units::Meters;
    std::vector<PartDefinition> definitions;
    std::vector<PartPlacement> placements;
    // Empty: every placement right under the root. Else [0] is the root cluster, and every
    // placement is in exactly one cluster.
    std::vector<PlacementCluster> clusters;
    std::vector<Level> proxyShapes;  // the clusters' proxies' geometry, in model coordinates
    // Where the root Group puts the model: nonzero only for a model moved about a local origin
    // (local_origin.h), a translation a float holds exactly.
    Vec3d origin{0, 0, 0};

    std::size_t distinctTriangles() const;  // every definition's levels once
    std::size_t placedTriangles() const;    // the finest level of every placement
    std::size_t proxyTriangles() const;     // every proxy shape once
};

struct InstancedWriteStats : WriteStats {
    std::size_t placements = 0;
    std::size_t instanceDefinitions = 0;
    std::size_t instanceReferences = 0;
    std::size_t clusters = 0;
    std::size_t proxyLevels = 0;
};

// A Matrix record holds 32-bit floats, and so does a reader that builds its scene from them:
// a placement far from the origin stands only to within their spacing there. Each placement
// counts where its finest level's centre is placed. `spacing`: that spacing at the placement
// farthest from the origin; `extent`: the largest side of the box of the placed parts (each
// a sphere about its centre); `farthest`: how far the farthest centre stands from the origin
// along an axis. All in the model's unit.
struct PlacementPrecision {
    double farthest = 0;
    double spacing = 0;
    double extent = 0;
};
PlacementPrecision placementPrecision(const InstancedModel& model);

// Where placements stand off by more than this share of how far apart they are, a viewer
// sees it (gaps between parts that touch): such a model is moved about a local origin
// (local_origin.h).
inline constexpr double kVisiblePlacementSpacing = 1e-5;

// Mesh records only (Face records share one Vertex Palette, which instances cannot).
bool writeInstancedOpenFlight(const InstancedModel& model, const WriteOptions& options, std::vector<std::uint8_t>& out,
                              std::string& error, InstancedWriteStats* stats = nullptr);
// Through a temporary file renamed into place, as writeOpenFlightFile.
bool writeInstancedOpenFlightFile(const std::string& path, const InstancedModel& model, const WriteOptions& options,
                                  std::string& error, InstancedWriteStats* stats = nullptr);

}  // namespace cadlod::flt
