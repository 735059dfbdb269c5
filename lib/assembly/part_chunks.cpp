#include "assembly/part_chunks.h"

#include "assembly/box_clip.h"
#include "assembly/finest_support.h"
#include "assembly/hierarchical_lod.h"  // kDrawCallTriangles
#include "lod/cluster_tree.h"           // Box3
#include "lod/nearest_point.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace cadlod {
namespace {

// A coarse level is cut to a chunk's box grown by its error times this (the error is
// measured from samples, which may miss its largest distance by a few percent)...
constexpr double kClipErrorSlack = 1.5;
// ...and by this share of the box's half-diagonal, for coordinates rounded to single precision.
constexpr double kClipRounding = 1e-4;

Box3 boxOf(const flt::Level& level)
{
    Box3 b;
    for (const flt::Part& part : level.parts)
        for (const flt::Vec3d& p : part.positions)
            b.add(p);
    return b;
}

// A grid over a node's box. A finest triangle goes to the cell of its centroid, unless it is
// longer than a cell along a cut axis: whichever cell took it would widen its chunk's reach,
// and so the distance that whole chunk waits before it coarsens. CAD tessellations hold such
// triangles (a face's slivers, a plate's two triangles) beside many small ones; they go to a
// long cell, which spans the box along the axes they are long on and is a cell of the grid
// along the others: a cylinder's slivers, long along its axis, go to a column of cells each,
// by where they lie around it. A coarse triangle goes to every cell of the finest triangles
// it stands for (finest_support.h), cut to the cell's box (splitCoarse): a chunk's coarse
// level then covers each finest triangle it held within the level's error, so chunks at
// different levels overlap, and leave no holes.
class ChunkGrid {
public:
    static constexpr int kOutside = -1;

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

    // The cell of finest triangle `i`; kOutside where its centroid is off the box (another
    // node's triangle, which a coarse triangle of this node also stands for).
    int cellOf(const FinestTriangles& finest, std::uint32_t i) const
    {
        for (int a = 0; a < 3; ++a) {
            const double slack = 1e-9 * size_[a];  // a centroid on the box's side, rounded
            if (finest.centroid(i)[a] < box_.lo[a] - slack || finest.centroid(i)[a] > box_.hi[a] + slack)
                return kOutside;
        }
        int cell = 0, longAxes = 0;
        for (int a = 0; a < 3; ++a) {
            int c = std::clamp(int((finest.centroid(i)[a] - box_.lo[a]) / size_[a] * cells_[a]), 0, cells_[a] - 1);
            if (cells_[a] > 1 && finest.extent(i)[a] > size_[a] / cells_[a]) {
                longAxes |= 1 << a;
                c = 0;
            }
            cell = cell * perAxis_ + c;
        }
        return longAxes * cellsPerMask() + cell;
    }

    // How a cell is named: its number in the grid, or for a long cell the axes it spans and
    // the number of its first cell.
    std::string nameOf(int cell) const
    {
        const int longAxes = cell / cellsPerMask();
        if (longAxes == 0)
            return std::to_string(cell);
        std::string name = "long ";
        for (int a = 0; a < 3; ++a)
            if (longAxes & (1 << a))
                name += "xyz"[a];
        return name + " " + std::to_string(cell % cellsPerMask());
    }

private:
    int cellsPerMask() const { return perAxis_ * perAxis_ * perAxis_; }

    Box3 box_;
    int perAxis_ = 1;
    std::array<double, 3> size_{};
    std::array<int, 3> cells_{};
};

// Appends triangle `t` of `part` to `piece`, whose vertex pool `remap` maps part's into.
void appendTriangle(const flt::Part& part, std::size_t t, std::vector<std::uint32_t>& remap, flt::Part& piece)
{
    flt::Triangle tri{};
    for (int k = 0; k < 3; ++k)
        tri[k] = flt::copiedVertex(part, part.triangles[t][k], remap, piece);
    piece.triangles.push_back(tri);
    if (part.hasTriangleColors())
        piece.triangleColors.push_back(part.triangleColors[t]);
}

// One cell's triangles of a level being split, every part with its own vertex pool.
class CellLevel {
public:
    SupportedLevel level;

    // Appends triangle `t` of part `p` of `from`, clipped to `box` unless null, standing for
    // the finest triangles [support, supportEnd).
    void append(const SupportedLevel& from, std::size_t p, std::size_t t, const Box3* box,
                const std::uint32_t* support, const std::uint32_t* supportEnd)
    {
        const flt::Part& part = from.level.parts[p];
        if (p != lastPart_) {
            lastPart_ = p;
            remap_.assign(part.positions.size(), flt::kNotCopied);
            flt::Part copy;
            static_cast<PartIdentity&>(copy) = part;
            level.level.parts.push_back(std::move(copy));
            level.support.emplace_back();
        }
        flt::Part& piece = level.level.parts.back();
        const std::size_t before = piece.triangles.size();
        if (box)
            appendClippedTriangle(part, t, *box, piece);
        else
            appendTriangle(part, t, remap_, piece);
        SupportedLevel::Support& kept = level.support.back();
        for (std::size_t i = before; i < piece.triangles.size(); ++i) {
            kept.finest.insert(kept.finest.end(), support, supportEnd);
            kept.start.push_back(std::uint32_t(kept.finest.size()));
        }
    }

private:
    std::size_t lastPart_ = std::numeric_limits<std::size_t>::max();
    std::vector<std::uint32_t> remap_;
};

Box3 boxOf(const flt::Part& part, const flt::Triangle& t)
{
    Box3 b;
    for (int k = 0; k < 3; ++k)
        b.add(part.positions[t[k]]);
    return b;
}

bool holds(const Box3& outer, const Box3& inner)
{
    for (int i = 0; i < 3; ++i)
        if (inner.lo[i] < outer.lo[i] || inner.hi[i] > outer.hi[i])
            return false;
    return true;
}

// The finest level's triangles in their cells.
std::map<int, SupportedLevel> splitFinest(const SupportedLevel& finestLevel, const ChunkGrid& grid,
                                          const FinestTriangles& finest)
{
    std::map<int, CellLevel> cells;
    for (std::size_t p = 0; p < finestLevel.level.parts.size(); ++p) {
        const SupportedLevel::Support& support = finestLevel.support[p];
        for (std::size_t t = 0; t + 1 < support.start.size(); ++t) {
            const std::uint32_t* own = support.finest.data() + support.start[t];
            cells[grid.cellOf(finest, *own)].append(finestLevel, p, t, nullptr, own, own + 1);
        }
    }
    std::map<int, SupportedLevel> out;
    for (auto& entry : cells)
        out[entry.first] = std::move(entry.second.level);
    return out;
}

// `box` grown by `error` on every side, and by a hair for the rounding of coordinates: the
// coarse surface of a face on the box's side may stand that far out of it.
Box3 grown(Box3 box, double error)
{
    const double margin = kClipErrorSlack * error + kClipRounding * box.halfDiagonal();
    for (int a = 0; a < 3; ++a) {
        box.lo[a] -= margin;
        box.hi[a] += margin;
    }
    return box;
}

// A coarse level's triangles in the cells of the finest triangles each stands for, standing
// there for those alone, cut to the box of the cell's finest triangles (`finestBoxes`) grown
// by the level's error, so that the cell's coarse level covers its finest level's surface and
// reaches no farther.
std::map<int, SupportedLevel> splitCoarse(const SupportedLevel& coarse, const ChunkGrid& grid,
                                          const FinestTriangles& finest, const std::map<int, Box3>& finestBoxes)
{
    std::map<int, Box3> clipBoxes;
    for (const auto& [cell, box] : finestBoxes)
        clipBoxes[cell] = grown(box, coarse.error);
    std::map<int, CellLevel> cells;
    std::vector<std::pair<int, std::uint32_t>> byCell;  // (cell, finest triangle)
    std::vector<std::uint32_t> standsFor;
    for (std::size_t p = 0; p < coarse.level.parts.size(); ++p) {
        const flt::Part& part = coarse.level.parts[p];
        const SupportedLevel::Support& support = coarse.support[p];
        for (std::size_t t = 0; t < part.triangles.size(); ++t) {
            byCell.clear();
            for (std::uint32_t s = support.start[t]; s < support.start[t + 1]; ++s) {
                const int cell = grid.cellOf(finest, support.finest[s]);
                if (clipBoxes.count(cell))  // not kOutside
                    byCell.emplace_back(cell, support.finest[s]);
            }
            std::sort(byCell.begin(), byCell.end());
            const Box3 box = boxOf(part, part.triangles[t]);
            for (std::size_t i = 0; i < byCell.size();) {
                const int cell = byCell[i].first;
                standsFor.clear();
                for (; i < byCell.size() && byCell[i].first == cell; ++i)
                    standsFor.push_back(byCell[i].second);
                const Box3& cellBox = clipBoxes.at(cell);
                cells[cell].append(coarse, p, t, holds(cellBox, box) ? nullptr : &cellBox, standsFor.data(),
                                   standsFor.data() + standsFor.size());
            }
        }
    }
    std::map<int, SupportedLevel> out;
    for (auto& entry : cells)
        out[entry.first] = std::move(entry.second.level);
    return out;
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
inline constexpr Cut kHalvesCut{kSubchunksPerAxis};
inline constexpr Cut kSubchunkCut{kSubchunksPerAxis, kDrawCallTriangles, "."};

std::vector<flt::PartChunk> cut(const FinestTriangles& finest, const std::vector<SupportedLevel>& levels,
                                const Box3& box, const Cut& how, const std::string& name, const flt::Vec3d& ownerCentre,
                                double drawnTo);

// One cell's share of the chain (switches as at the centre), drawn while the eye is nearer
// than `drawnTo` to `ownerCentre`: each level from where it holds at the chunk's nearest
// point, up to the last one drawn there; nearer than its first simplified level, its own
// pieces where they could coarsen sooner.
// `box` bounds its finest level: it is centred on what it draws nearest the viewer.
flt::PartChunk makeChunk(const FinestTriangles& finest, std::vector<SupportedLevel> chain, const Box3& box,
                         const std::string& name, const flt::Vec3d& ownerCentre, double drawnTo)
{
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
    const double farthest = drawnTo + flt::distance(centre, ownerCentre);
    flt::PartChunk chunk;
    chunk.name = name;
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
    std::vector<std::map<int, SupportedLevel>> split{splitFinest(levels.front(), grid, finest)};
    std::map<int, Box3> finestBoxes;
    for (const auto& entry : split.front())
        finestBoxes[entry.first] = boxOf(entry.second.level);
    const double pieces = double(finestBoxes.size());
    if (pieces < 2 || double(levels.front().level.triangleCount()) < how.leastEach * pieces)
        return {};
    for (std::size_t k = 1; k < levels.size(); ++k)
        split.push_back(splitCoarse(levels[k], grid, finest, finestBoxes));
    // Every chunk is a cell of the finest level: the coarse levels go only to those.
    std::vector<flt::PartChunk> chunks;
    for (const auto& entry : finestBoxes) {
        std::vector<SupportedLevel> chain;
        for (std::size_t k = 0; k < levels.size(); ++k) {
            const auto found = split[k].find(entry.first);
            SupportedLevel l = found != split[k].end() ? std::move(found->second) : SupportedLevel{};
            l.error = levels[k].error;
            l.level.switchIn = levels[k].level.switchIn;
            l.level.switchOut = levels[k].level.switchOut;
            chain.push_back(std::move(l));
        }
        const std::string chunkName = name + how.separator + grid.nameOf(entry.first);
        chunks.push_back(makeChunk(finest, std::move(chain), entry.second, chunkName, ownerCentre, drawnTo));
    }
    return chunks;
}

}  // namespace

std::vector<flt::PartChunk> chunkLevels(const std::string& partName, const std::vector<flt::Level>& levels,
                                        const std::vector<double>& errors, double smallestRadius, double drawnTo)
{
    if (errors.size() != levels.size())
        throw std::logic_error("chunkLevels: one error per level");
    if (levels.size() < 2)
        return {};
    const Box3 box = boxOf(levels.front());
    const double radius = levels.front().reachFrom(box.center());
    if (radius < smallestRadius || !coarsensLate(levels, radius))
        return {};
    // A chunk is drawn only while the eye is nearer than drawnTo to the part's centre, so within
    // drawnTo + radius of its own: the levels switched in only farther are never its.
    std::vector<flt::Level> drawable;
    for (const flt::Level& level : levels) {
        if (drawable.size() >= 2 && level.switchOut >= drawnTo + radius)
            break;
        drawable.push_back(level);
    }
    const FinestTriangles finest(levels.front());
    const std::vector<SupportedLevel> chain = supported(drawable, errors, finest);
    std::vector<flt::PartChunk> chunks = cut(finest, chain, box, kChunkCut, partName, levels.front().center, drawnTo);
    if (chunks.empty())  // too few triangles for a chunk a cell: maybe enough for halves
        chunks = cut(finest, chain, box, kHalvesCut, partName, levels.front().center, drawnTo);
    return chunks;
}

std::size_t chunkCount(const std::vector<flt::PartChunk>& chunks)
{
    std::size_t n = chunks.size();
    for (const flt::PartChunk& chunk : chunks)
        n += chunkCount(chunk.children);
    return n;
}

}  // namespace cadlod
