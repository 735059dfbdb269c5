#include "assembly/part_chunks.h"

#include "assembly/hierarchical_lod.h"  // kDrawCallTriangles
#include "lod/cluster_tree.h"           // Box3
#include "lod/nearest_point.h"
#include "measure/triangle_tree.h"

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

double distance(const flt::Vec3d& a, const flt::Vec3d& b)
{
    double squared = 0;
    for (int i = 0; i < 3; ++i)
        squared += (a[i] - b[i]) * (a[i] - b[i]);
    return std::sqrt(squared);
}

flt::Vec3d centroidOf(const flt::Part& part, const flt::Triangle& t)
{
    flt::Vec3d c{};
    for (int a = 0; a < 3; ++a)
        c[a] = (part.positions[t[0]][a] + part.positions[t[1]][a] + part.positions[t[2]][a]) / 3.0;
    return c;
}

flt::Vec3f extentOf(const flt::Part& part, const flt::Triangle& t)
{
    flt::Vec3f extent{};
    for (int a = 0; a < 3; ++a) {
        const double p = part.positions[t[0]][a], q = part.positions[t[1]][a], r = part.positions[t[2]][a];
        extent[a] = float(std::max({p, q, r}) - std::min({p, q, r}));
    }
    return extent;
}

// A level's triangles in one tree, their corners in single precision about `origin` (which
// keeps the precision of site coordinates), numbered part after part.
TriangleTree treeOf(const flt::Level& level, const flt::Vec3d& origin)
{
    std::vector<vcg::Point3f> vertices;
    std::vector<TriangleTree::Corners> corners;
    for (const flt::Part& part : level.parts) {
        const auto first = std::uint32_t(vertices.size());
        for (const flt::Vec3d& p : part.positions)
            vertices.emplace_back(float(p[0] - origin[0]), float(p[1] - origin[1]), float(p[2] - origin[2]));
        for (const flt::Triangle& t : part.triangles)
            corners.push_back({first + t[0], first + t[1], first + t[2]});
    }
    return TriangleTree(std::move(vertices), std::move(corners));
}

// The index in treeOf(level) of the triangle nearest `p`.
std::uint32_t nearestIn(const TriangleTree& tree, const flt::Vec3d& p, const flt::Vec3d& origin)
{
    double distance = 0;
    const std::int64_t i = tree.closest(vcg::Point3d(p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]),
                                        std::numeric_limits<double>::infinity(), distance);
    return std::uint32_t(std::max<std::int64_t>(i, 0));
}

// The finest level's triangles: where each lies and how far it spans along each axis.
class FinestTriangles {
public:
    explicit FinestTriangles(const flt::Level& finest)
    {
        for (const flt::Part& part : finest.parts)
            for (const flt::Triangle& t : part.triangles) {
                centroids_.push_back(centroidOf(part, t));
                extents_.push_back(extentOf(part, t));
            }
    }

    std::size_t size() const { return centroids_.size(); }
    const flt::Vec3d& centroid(std::uint32_t i) const { return centroids_[i]; }
    const flt::Vec3f& extent(std::uint32_t i) const { return extents_[i]; }

private:
    std::vector<flt::Vec3d> centroids_;
    std::vector<flt::Vec3f> extents_;
};

// A level's triangles, each with the finest triangles it stands for (a finest triangle:
// itself), as indices into FinestTriangles.
struct SupportedLevel {
    struct Support {
        std::vector<std::uint32_t> start{0};  // triangle t's are finest[start[t], start[t + 1])
        std::vector<std::uint32_t> finest;
    };
    flt::Level level;
    std::vector<Support> support;  // one per part
};

// What each triangle of coarse level `level` stands for: the finest triangles whose
// centroid it is the nearest triangle to, so that wherever a finest triangle was, the coarse
// triangles of its chunk cover it; or, where it is nearest to none, the finest triangle
// nearest its own centroid.
SupportedLevel supportOf(const flt::Level& level, const FinestTriangles& finest, const TriangleTree& finestTree,
                         const flt::Vec3d& origin)
{
    const TriangleTree tree = treeOf(level, origin);
    std::vector<std::vector<std::uint32_t>> standsFor(level.triangleCount());
    for (std::uint32_t f = 0; f < finest.size(); ++f)
        standsFor[nearestIn(tree, finest.centroid(f), origin)].push_back(f);
    SupportedLevel out{level, {}};
    std::size_t i = 0;
    for (const flt::Part& part : level.parts) {
        SupportedLevel::Support& support = out.support.emplace_back();
        for (const flt::Triangle& t : part.triangles) {
            std::vector<std::uint32_t>& own = standsFor[i++];
            if (own.empty())
                own.push_back(nearestIn(finestTree, centroidOf(part, t), origin));
            support.finest.insert(support.finest.end(), own.begin(), own.end());
            support.start.push_back(std::uint32_t(support.finest.size()));
        }
    }
    return out;
}

std::vector<SupportedLevel> supported(const std::vector<flt::Level>& levels, const FinestTriangles& finest)
{
    const flt::Vec3d origin = boxOf(levels.front()).center();
    const TriangleTree finestTree = treeOf(levels.front(), origin);
    std::vector<SupportedLevel> out;
    SupportedLevel& first = out.emplace_back(SupportedLevel{levels.front(), {}});
    std::uint32_t next = 0;
    for (const flt::Part& part : levels.front().parts) {
        SupportedLevel::Support& support = first.support.emplace_back();
        for (std::size_t t = 0; t < part.triangles.size(); ++t) {
            support.finest.push_back(next++);
            support.start.push_back(std::uint32_t(support.finest.size()));
        }
    }
    for (std::size_t k = 1; k < levels.size(); ++k)
        out.push_back(supportOf(levels[k], finest, finestTree, origin));
    return out;
}

// A grid over a node's box. A finest triangle goes to the cell of its centroid, unless it is
// longer than a cell along a cut axis: whichever cell took it would widen its chunk's reach,
// and so the distance that whole chunk waits before it coarsens. CAD tessellations hold such
// triangles (a face's slivers, a plate's two triangles) beside many small ones; they go to
// the long cell, a chunk of its own that coarsens late but holds few triangles. A coarse
// triangle goes to every cell of the finest triangles it stands for: a chunk's coarse level
// then covers each finest triangle it held, at its centroid, within the level's error, so
// chunks at different levels overlap where the triangle is drawn twice, and leave no holes.
class ChunkGrid {
public:
    static constexpr int kLongCell = -1;

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

    // The cell of finest triangle `i`.
    int cellOf(const FinestTriangles& finest, std::uint32_t i) const
    {
        int cell = 0;
        for (int a = 0; a < 3; ++a) {
            if (cells_[a] > 1 && finest.extent(i)[a] > size_[a] / cells_[a])
                return kLongCell;
            const int c = std::clamp(int((finest.centroid(i)[a] - box_.lo[a]) / size_[a] * cells_[a]), 0, cells_[a] - 1);
            cell = cell * perAxis_ + c;
        }
        return cell;
    }

private:
    Box3 box_;
    int perAxis_ = 1;
    std::array<double, 3> size_{};
    std::array<int, 3> cells_{};
};

// Appends triangle `t` of `part` to `piece`, whose vertex pool `remap` maps part's into.
void appendTriangle(const flt::Part& part, std::size_t t, std::vector<std::uint32_t>& remap, flt::Part& piece)
{
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

// A level's triangles in each cell they go to, every part with its own vertex pool.
std::map<int, SupportedLevel> splitLevel(const SupportedLevel& in, const ChunkGrid& grid, const FinestTriangles& finest)
{
    std::map<int, SupportedLevel> cells;
    std::vector<int> to;
    for (std::size_t p = 0; p < in.level.parts.size(); ++p) {
        const flt::Part& part = in.level.parts[p];
        const SupportedLevel::Support& support = in.support[p];
        std::map<int, std::vector<std::uint32_t>> remaps;
        for (std::size_t t = 0; t < part.triangles.size(); ++t) {
            to.clear();
            for (std::uint32_t s = support.start[t]; s < support.start[t + 1]; ++s)
                to.push_back(grid.cellOf(finest, support.finest[s]));
            std::sort(to.begin(), to.end());
            to.erase(std::unique(to.begin(), to.end()), to.end());
            for (int cell : to) {
                SupportedLevel& out = cells[cell];
                std::vector<std::uint32_t>& remap = remaps[cell];
                if (remap.empty()) {
                    remap.assign(part.positions.size(), std::numeric_limits<std::uint32_t>::max());
                    flt::Part copy;
                    static_cast<PartIdentity&>(copy) = part;
                    out.level.parts.push_back(std::move(copy));
                    out.support.emplace_back();
                }
                appendTriangle(part, t, remap, out.level.parts.back());
                SupportedLevel::Support& kept = out.support.back();
                kept.finest.insert(kept.finest.end(), support.finest.begin() + support.start[t],
                                   support.finest.begin() + support.start[t + 1]);
                kept.start.push_back(std::uint32_t(kept.finest.size()));
            }
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

std::vector<flt::PartChunk> cut(const FinestTriangles& finest, const std::vector<SupportedLevel>& levels,
                                const Box3& box, const Cut& how, const std::string& name, const flt::Vec3d& ownerCentre,
                                double drawnTo);

// One cell's share of the chain (switches as at the centre), drawn while the eye is nearer
// than `drawnTo` to `ownerCentre`: each level from where it holds at the chunk's nearest
// point, up to the last one drawn there; nearer than its first simplified level, its own
// pieces where they could coarsen sooner.
flt::PartChunk makeChunk(const FinestTriangles& finest, std::vector<SupportedLevel> chain, const std::string& name,
                         const flt::Vec3d& ownerCentre, double drawnTo)
{
    // Centred on what it draws nearest the viewer: a coarse level's few long triangles, drawn
    // only from farther, would move its centre and widen its finest level's reach.
    Box3 box = boxOf(chain.front().level);
    if (chain.front().level.triangleCount() == 0)
        for (const SupportedLevel& s : chain)
            box.add(boxOf(s.level));
    const flt::Vec3d centre = box.center();
    std::vector<flt::Level> levels;
    std::vector<double> reach;
    for (std::size_t k = 0; k < chain.size(); ++k) {
        flt::Level& level = chain[k].level;
        level.center = centre;
        level.name = name + " LOD" + std::to_string(k);
        reach.push_back(level.reachFrom(centre));
        levels.push_back(level);
    }
    std::vector<flt::Level> held = levels;
    holdAtNearestPoint(held, reach);
    const double farthest = drawnTo + distance(centre, ownerCentre);
    flt::PartChunk chunk;
    if (held.size() > 1 && held[1].switchOut < farthest && coarsensLate(levels, reach.front()))
        chunk.children = cut(finest, chain, box, kSubchunkCut, name, centre, held[1].switchOut);
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
std::vector<flt::PartChunk> cut(const FinestTriangles& finest, const std::vector<SupportedLevel>& levels,
                                const Box3& box, const Cut& how, const std::string& name, const flt::Vec3d& ownerCentre,
                                double drawnTo)
{
    const ChunkGrid grid(box, how.perAxis);
    std::vector<std::map<int, SupportedLevel>> split;
    std::map<int, bool> cells;
    for (const SupportedLevel& level : levels) {
        split.push_back(splitLevel(level, grid, finest));
        for (const auto& entry : split.back())
            cells[entry.first] = true;
    }
    const double pieces = double(split.front().size());
    if (pieces < 2 || double(levels.front().level.triangleCount()) < how.leastEach * pieces)
        return {};
    std::vector<flt::PartChunk> chunks;
    for (const auto& entry : cells) {
        std::vector<SupportedLevel> chain;
        for (std::size_t k = 0; k < levels.size(); ++k) {
            const auto found = split[k].find(entry.first);
            SupportedLevel l = found != split[k].end() ? std::move(found->second) : SupportedLevel{};
            l.level.switchIn = levels[k].level.switchIn;
            l.level.switchOut = levels[k].level.switchOut;
            chain.push_back(std::move(l));
        }
        const std::string cell = entry.first == ChunkGrid::kLongCell ? "long" : std::to_string(entry.first);
        chunks.push_back(makeChunk(finest, std::move(chain), name + how.separator + cell, ownerCentre, drawnTo));
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
    // A chunk is drawn only while the eye is nearer than drawnTo to the part's centre, so within
    // drawnTo + radius of its own: the levels switched in only farther are never its.
    std::vector<flt::Level> drawable;
    for (const flt::Level& level : levels)
        if (drawable.size() < 2 || level.switchOut < drawnTo + radius)
            drawable.push_back(level);
    const FinestTriangles finest(levels.front());
    return cut(finest, supported(drawable, finest), box, kChunkCut, levels.front().name, levels.front().center,
               drawnTo);
}

std::size_t chunkCount(const std::vector<flt::PartChunk>& chunks)
{
    std::size_t n = chunks.size();
    for (const flt::PartChunk& chunk : chunks)
        n += chunkCount(chunk.children);
    return n;
}

}  // namespace cadlod
