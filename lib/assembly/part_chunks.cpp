#include "assembly/part_chunks.h"

#include "lod/cluster_tree.h"  // Box3
#include "lod/nearest_point.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

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

class ChunkGrid {
public:
    // kChunksPerAxis cells along every axis but a thin one (a plate's thickness): one there.
    explicit ChunkGrid(const Box3& box) : box_(box)
    {
        double longest = 0;
        for (int a = 0; a < 3; ++a)
            longest = std::max(longest, box.hi[a] - box.lo[a]);
        for (int a = 0; a < 3; ++a) {
            size_[a] = std::max(box.hi[a] - box.lo[a], 1e-300);
            cells_[a] = size_[a] * kChunksPerAxis < longest ? 1 : kChunksPerAxis;
        }
    }

    int cellOf(const flt::Part& part, const flt::Triangle& t) const
    {
        int cell = 0;
        for (int a = 0; a < 3; ++a) {
            const double c =
                (part.positions[t[0]][a] + part.positions[t[1]][a] + part.positions[t[2]][a]) / 3.0 - box_.lo[a];
            const int i = std::clamp(int(c / size_[a] * cells_[a]), 0, cells_[a] - 1);
            cell = cell * kChunksPerAxis + i;
        }
        return cell;
    }

private:
    Box3 box_;
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

// The chunk's levels, each from where it holds at the chunk's nearest point, up to the last
// one drawn while the eye is nearer than `drawnTo` to `partCentre`.
std::vector<flt::Level> chunkChain(std::vector<flt::Level> levels, const std::string& name,
                                   const flt::Vec3d& partCentre, double drawnTo)
{
    Box3 box;
    for (const flt::Level& l : levels)
        box.add(boxOf(l));
    const flt::Vec3d centre = box.center();
    std::vector<double> reach;
    for (std::size_t k = 0; k < levels.size(); ++k) {
        levels[k].center = centre;
        levels[k].name = name + " LOD" + std::to_string(k);
        reach.push_back(levels[k].reachFrom(centre));
    }
    holdAtNearestPoint(levels, reach);
    double squared = 0;
    for (int a = 0; a < 3; ++a)
        squared += (centre[a] - partCentre[a]) * (centre[a] - partCentre[a]);
    const double farthest = drawnTo + std::sqrt(squared);
    std::size_t drawn = 1;
    while (drawn < levels.size() && levels[drawn].switchOut < farthest)
        ++drawn;
    levels.resize(drawn);
    levels.back().switchIn = kNeverCulled;  // the part's own levels take over first
    return levels;
}

}  // namespace

std::vector<std::vector<flt::Level>> chunkLevels(const std::vector<flt::Level>& levels, double smallestRadius,
                                                 double drawnTo)
{
    if (levels.size() < 2)
        return {};
    const Box3 box = boxOf(levels.front());
    const double radius = levels.front().reachFrom(box.center());
    // Chunks help where the part's first simplified level waits for the nearest-point floor.
    if (radius < smallestRadius || levels[1].switchOut >= (kNearestPointReach - 1) * radius)
        return {};
    const ChunkGrid grid(box);
    std::vector<std::map<int, flt::Level>> split;
    std::map<int, bool> cells;
    for (const flt::Level& level : levels) {
        split.push_back(splitLevel(level, grid));
        for (const auto& entry : split.back())
            cells[entry.first] = true;
    }
    if (split.front().size() < 2 || levels.front().triangleCount() < kLeastChunkTriangles * split.front().size())
        return {};
    std::vector<std::vector<flt::Level>> chunks;
    for (const auto& entry : cells) {
        std::vector<flt::Level> chain;
        for (std::size_t k = 0; k < levels.size(); ++k) {
            const auto found = split[k].find(entry.first);
            flt::Level l = found != split[k].end() ? found->second : flt::Level{};
            l.switchIn = levels[k].switchIn;
            l.switchOut = levels[k].switchOut;
            chain.push_back(std::move(l));
        }
        chunks.push_back(chunkChain(std::move(chain), levels.front().name + " chunk " + std::to_string(entry.first),
                                    levels.front().center, drawnTo));
    }
    return chunks;
}

}  // namespace cadlod
