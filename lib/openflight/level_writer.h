// The records of a list of levels: a LOD record per level when asked, an Object per part
// (or one per level), each part's triangles as Mesh records or as Face records on a shared
// Vertex Palette. The model writers (flt_writer.cpp, instanced_writer.cpp) frame them.
#pragma once

#include "openflight/flt_writer.h"

#include <functional>
#include <vector>

namespace cadlod::flt {

// Header, Color Palette and Material Palette: how every database starts.
void writeDatabaseHead(ByteWriter& w, const std::string& name, Units units);
// The root Group, named after the model, with the Push into it; closeRootGroup pops out.
// `origin` nonzero: the Group's Matrix puts the model there.
void openRootGroup(ByteWriter& w, const std::string& name, const Vec3d& origin = {0, 0, 0});
void closeRootGroup(ByteWriter& w);

// Clears `out` and `stats` (or a local one when null), runs `write(w, stats)` into `out` and
// records the bytes written: what every writer of a whole database does around its records.
template <class Stats, class Write>
bool writeDatabase(std::vector<std::uint8_t>& out, Stats* stats, Write&& write)
{
    Stats local;
    Stats& s = stats ? *stats : local;
    s = Stats{};
    out.clear();
    ByteWriter w(out);
    if (!write(w, s))
        return false;
    s.bytes = out.size();
    return true;
}

// `write(bytes, error)` makes the database; it goes to `path` through a temporary file
// renamed into place (atomic_file.h), so an interrupted write never leaves a truncated .flt.
bool writeDatabaseFile(const std::string& path,
                       const std::function<bool(std::vector<std::uint8_t>&, std::string&)>& write, std::string& error);

// LOD records are written when there are several levels or the one level has a range.
bool writesLodRecords(const std::vector<Level>& levels);

class LevelWriter {
public:
    LevelWriter(const WriteOptions& options, ByteWriter& w, WriteStats& stats, std::size_t totalTriangles);

    // Faces only, once, before the hierarchy: every vertex of `levels`, part by part, in the
    // order writeLevels will refer to them.
    void writeSharedVertexPalette(const std::vector<Level>& levels);
    // `reversed`: every triangle turned round, for a mirrored placement to keep its faces out.
    // `first`: the index of levels[0] in its chain, for the names of unnamed levels.
    void writeLevels(const std::vector<Level>& levels, bool lodRecords, bool reversed = false, std::size_t first = 0);
    // One level's Objects, without a LOD record (`reversed` as for writeLevels).
    void writeGeometry(const Level& level, bool reversed = false);

private:
    void writeLevel(const Level& level, std::size_t index, bool lod);
    void beginObject(const std::string& name);
    void writePartGeometry(const Part& part);
    void writeFaces(const Part& part, std::size_t firstOffset);
    void writeMeshPart(const Part& part);
    void writeOneMesh(const Part& part, const Rgba& color);
    void countTriangles(std::size_t n);

    const WriteOptions& options_;
    ByteWriter& w_;
    WriteStats& stats_;
    std::size_t totalTriangles_ = 0;
    std::size_t partCounter_ = 0;
    std::vector<std::size_t> firstVertexOffset_;
    bool reversed_ = false;
};

}  // namespace cadlod::flt
