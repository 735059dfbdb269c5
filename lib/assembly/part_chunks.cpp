#include "assembly/part_chunks.h"

#include "assembly/hierarchical_lod.h"  // kDrawCallTriangles
#include "lod/cluster_tree.h"           // Box3
#include "lod/nearest_point.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <utility>

namespace cadlod {
namespace {

Box3 boxOf(const flt::Level& level)
{
    Box3 b;
    for (const flt::Part& part : level.parts)
        for (const flt::Vec3d& p : part.positions)
            b.add(p);
    return b;
}

Box3 boxOf(const std::vector<flt::Level>& levels)
{
    Box3 b;
    for (const flt::Level& l : levels)
        b.add(boxOf(l));
    return b;
}

double distance(const flt::Vec3d& a, const flt::Vec3d& b)
{
    double squared = 0;
    for (int i = 0; i < 3; ++i)
        squared += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(squared);
}

class ChunkGrid {
public:
    // `perAxis` cells along every axis but a thin one (a plate's thickness): one there.
    ChunkGrid(const Box3& box, int perAxis) : box_(box), perAxis_(perAxis)
    {
        double longest = 0;
        for (int a = 0; a < 3; ++a)
            longest = std::max(longest, box.hi[a] - box.lo[a]);
        for (int a = 0; a < 3; ++a) {
            size_[a] = std::max(box.hi[a] - box.lo[a], 1e-300);
            cells_[a] = size_[a] * perAxis < longest ? 1 : perAxis;
        }
    }

    int cellOf(const flt::Part& part, const flt::Triangle& t) const
    {
        int cell = 0;
        for (int a = 0; a < 3; ++a) {
            const double c =
                (part.positions[t[0]][a] + part.positions[t[1]][a] + part.positions[t[2]][a]) / 3.0 - box_.lo[a];
            const int i = std::clamp(int(c / size_[a] * cells_[a]), 0, cells_[a] - 1);
            cell = cell * perAxis_ + i;
        }
        return cell;
    }

private:
    Box3 box_;
    int perAxis_ = 1;
    std::array<double, 3> size_{};
    std::array<int, 3> cells_{};
};

// Level `level`'s triangles in each cell, every part with its own vertex pool.
std::map<int, flt::Level> splitLevel(const flt::Level& level, const ChunkGrid& grid)
{
    std::map<int, flt::Level> cells;
    for (const flt::Part& part : level.parts) {
        std::map<int, std::vector<std::uint32_t>> remaps;
        for (std::size_t t = 0; t < part.triangles.size(); ++t) {
            const int cell = grid.cellOf(part, part.triangles[t]);
            flt::Level& out = cells[cell];
            std::vector<std::uint32_t>& remap = remaps[cell];
            if (remap.empty()) {
                remap.assign(part.positions.size(), std::numeric_limits<std::uint32_t>::max());
                flt::Part copy;
                static_cast<PartIdentity&>(copy) = part;
                out.parts.push_back(std::move(copy));
            }
            flt::Part& piece = out.parts.back();
            flt::Triangle tri{};
            for (int k = 0; k < 3; ++k) {
                const std::uint32_t v = part.triangles[t][k];
                if (remap[v] == std::numeric_limits<std::uint32_t>::max()) {
                    remap[v] = std::uint32_t(piece.positions.size());
                    piece.positions.push_back(part.positions[v]);
                    if (part.hasNormals())
                        piece.normals.push_back(part.normals[v]);
                    if (part.hasUvs())
                        piece.uvs.push_back(part.uvs[v]);
                    if (part.hasVertexColors())
                        piece.vertexColors.push_back(part.vertexColors[v]);
                }
                tri[k] = remap[v];
            }
            piece.triangles.push_back(tri);
            if (part.hasTriangleColors())
                piece.triangleColors.push_back(part.triangleColors[t]);
        }
    }
    return cells;
}

// Whether the first simplified level of a node of this reach waits for the nearest-point
// floor: smaller pieces of it could switch it in nearer.
bool coarsensLate(const std::vector<flt::Level>& levels, double reach)
{
    return levels.size() > 1 && levels[1].switchOut < (kNearestPointReach - 1) * reach;
}

// How a node is cut: cells along each axis, the fewest finest-level triangles a piece holds
// on average, and how the pieces' names follow the node's.
struct Cut {
    int perAxis = kChunksPerAxis;
    double leastEach = double(kLeastChunkTriangles);
    const char* separator = " chunk ";
};
inline constexpr Cut kChunkCut{};
inline constexpr Cut kSubchunkCut{kSubchunksPerAxis, kDrawCallTriangles, "."};

std::vector<flt::PartChunk> cut(const std::vector<flt::Level>& levels, const Box3& box, const Cut& how,
                                const std::string& name, const flt::Vec3d& ownerCentre, double drawnTo);

// One cell's share of the chain (switches as at the centre), drawn while the eye is nearer
// than `drawnTo` to `ownerCentre`: each level from where it holds at the chunk's nearest
// point, up to the last one drawn there; nearer than its first simplified level, its own
// pieces where they could coarsen sooner.
flt::PartChunk makeChunk(std::vector<flt::Level> levels, const std::string& name, const flt::Vec3d& ownerCentre,
                         double drawnTo)
{
    // Centred on what it draws nearest the viewer: a coarse level's few long triangles, drawn
    // only from farther, would move its centre and widen its finest level's reach.
    const Box3 box = levels.front().triangleCount() > 0 ? boxOf(levels.front()) : boxOf(levels);
    const flt::Vec3d centre = box.center();
    std::vector<double> reach;
    for (std::size_t k = 0; k < levels.size(); ++k) {
        levels[k].center = centre;
        levels[k].name = name + " LOD" + std::to_string(k);
        reach.push_back(levels[k].reachFrom(centre));
    }
    std::vector<flt::Level> held = levels;
    holdAtNearestPoint(held, reach);
    const double farthest = drawnTo + distance(centre, ownerCentre);
    flt::PartChunk chunk;
    if (held.size() > 1 && held[1].switchOut < farthest && coarsensLate(levels, reach.front()))
        chunk.children = cut(levels, box, kSubchunkCut, name, centre, held[1].switchOut);
    std::size_t drawn = 1;
    while (drawn < held.size() && held[drawn].switchOut < farthest)
        ++drawn;
    held.resize(drawn);
    held.back().switchIn = kNeverCulled;  // the owner's own levels take over first
    if (!chunk.children.empty())
        held.erase(held.begin());  // its pieces are drawn where its finest level would be
    chunk.levels = std::move(held);
    return chunk;
}

// `levels` cut by a grid over `box`; empty when fewer than two cells hold triangles of the
// finest level, or they would hold fewer than how.leastEach each.
std::vector<flt::PartChunk> cut(const std::vector<flt::Level>& levels, const Box3& box, const Cut& how,
                                const std::string& name, const flt::Vec3d& ownerCentre, double drawnTo)
{
    const ChunkGrid grid(box, how.perAxis);
    std::vector<std::map<int, flt::Level>> split;
    std::map<int, bool> cells;
    for (const flt::Level& level : levels) {
        split.push_back(splitLevel(level, grid));
        for (const auto& entry : split.back())
            cells[entry.first] = true;
    }
    const double pieces = double(split.front().size());
    if (pieces < 2 || double(levels.front().triangleCount()) < how.leastEach * pieces)
        return {};
    std::vector<flt::PartChunk> chunks;
    for (const auto& entry : cells) {
        std::vector<flt::Level> chain;
        for (std::size_t k = 0; k < levels.size(); ++k) {
            const auto found = split[k].find(entry.first);
            flt::Level l = found != split[k].end() ? std::move(found->second) : flt::Level{};
            l.switchIn = levels[k].switchIn;
            l.switchOut = levels[k].switchOut;
            chain.push_back(std::move(l));
        }
        chunks.push_back(
            makeChunk(std::move(chain), name + how.separator + std::to_string(entry.first), ownerCentre, drawnTo));
    }
    return chunks;
}

}  // namespace

std::vector<flt::PartChunk> chunkLevels(const std::vector<flt::Level>& levels, double smallestRadius,
                                        double drawnTo)
{
    if (levels.size() < 2)
        return {};
    const Box3 box = boxOf(levels.front());
    const double radius = levels.front().reachFrom(box.center());
    if (radius < smallestRadius || !coarsensLate(levels, radius))
        return {};
    return cut(levels, box, kChunkCut, levels.front().name, levels.front().center, drawnTo);
}

std::size_t chunkCount(const std::vector<flt::PartChunk>& chunks)
{
    std::size_t n = chunks.size();
    for (const flt::PartChunk& chunk : chunks)
        n += chunkCount(chunk.children);
    return n;
}

}  // namespace cadlod
