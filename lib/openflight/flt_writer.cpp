#include "openflight/flt_writer.h"
#include "openflight/atomic_file.h"

#include "openflight/level_writer.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>

namespace cadlod::flt {
namespace {

// Writes one model; the vertex palette offsets of every part's first vertex are known
// before the hierarchy is written.
class ModelWriter {
public:
    ModelWriter(const LodModel& model, const WriteOptions& options, ByteWriter& w, WriteStats& stats)
        : model_(model), options_(options), w_(w), levels_(options, w, stats, model.triangleCount())
    {
    }

    void write()
    {
        writeDatabaseHead(w_, model_.name, model_.units);
        if (options_.geometry == GeometryRecords::Faces)
            levels_.writeSharedVertexPalette(model_.levels);
        openRootGroup(w_, model_.name);
        levels_.writeLevels(model_.levels, writesLodRecords(model_.levels));
        closeRootGroup(w_);
    }

private:
    const LodModel& model_;
    const WriteOptions& options_;
    ByteWriter& w_;
    LevelWriter levels_;
};

std::string where(std::size_t level, std::size_t part)
{
    return "level " + std::to_string(level) + ", part " + std::to_string(part);
}

bool validatePart(const Part& part, const std::string& at, std::string& error)
{
    if (!part.normals.empty() && part.normals.size() != part.positions.size()) {
        error = at + ": " + std::to_string(part.normals.size()) + " normals for " +
                std::to_string(part.positions.size()) + " vertices";
        return false;
    }
    if (!part.uvs.empty() && part.uvs.size() != part.positions.size()) {
        error = at + ": " + std::to_string(part.uvs.size()) + " texture coordinates for " +
                std::to_string(part.positions.size()) + " vertices";
        return false;
    }
    if (!part.vertexColors.empty() && part.vertexColors.size() != part.positions.size()) {
        error = at + ": " + std::to_string(part.vertexColors.size()) + " vertex colours for " +
                std::to_string(part.positions.size()) + " vertices";
        return false;
    }
    if (!part.triangleColors.empty() && part.triangleColors.size() != part.triangles.size()) {
        error = at + ": " + std::to_string(part.triangleColors.size()) + " face colours for " +
                std::to_string(part.triangles.size()) + " triangles";
        return false;
    }
    for (std::size_t t = 0; t < part.triangles.size(); ++t)
        for (std::uint32_t i : part.triangles[t])
            if (i >= part.positions.size()) {
                error = at + ", triangle " + std::to_string(t) + ": vertex index " + std::to_string(i) +
                        " out of range (" + std::to_string(part.positions.size()) + " vertices)";
                return false;
            }
    return true;
}

std::size_t vertexPaletteBytes(const LodModel& model)
{
    std::size_t bytes = size::VertexPalette;
    for (const Level& level : model.levels)
        for (const Part& part : level.parts)
            bytes += part.positions.size() * vertexRecordSize(part.hasNormals(), part.hasUvs());
    return bytes;
}

}  // namespace

bool validateLevels(const std::vector<Level>& levels, std::string& error)
{
    if (levels.empty()) {
        error = "the model has no level";
        return false;
    }
    for (std::size_t l = 0; l < levels.size(); ++l)
        for (std::size_t p = 0; p < levels[l].parts.size(); ++p)
            if (!validatePart(levels[l].parts[p], where(l, p), error))
                return false;
    return true;
}

bool validateModel(const LodModel& model, std::string& error) { return validateLevels(model.levels, error); }

bool writeOpenFlight(const LodModel& model, const WriteOptions& options, std::vector<std::uint8_t>& out,
                     std::string& error, WriteStats* stats)
{
    if (!validateModel(model, error))
        return false;
    if (options.geometry == GeometryRecords::Faces &&
        vertexPaletteBytes(model) > std::numeric_limits<std::uint32_t>::max()) {
        error = "the vertex palette would exceed 4 GiB; use Mesh records";
        return false;
    }
    return writeDatabase(out, stats, [&](ByteWriter& w, WriteStats& s) {
        ModelWriter(model, options, w, s).write();
        return true;
    });
}

bool writeOpenFlightFile(const std::string& path, const LodModel& model, const WriteOptions& options,
                         std::string& error, WriteStats* stats)
{
    return writeDatabaseFile(
        path, [&](std::vector<std::uint8_t>& bytes, std::string& e) { return writeOpenFlight(model, options, bytes, e, stats); },
        error);
}

}  // namespace cadlod::flt
