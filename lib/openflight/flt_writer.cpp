#include "openflight/flt_writer.h"
#include "openflight/atomic_file.h"

#include "openflight/triangle_strip.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>

namespace cadlod::flt {
namespace {

bool writesLodRecords(const LodModel& model)
{
    return model.levels.size() > 1 || (model.levels.size() == 1 && model.levels[0].hasRange());
}

Appearance appearanceOf(const Part& part, const WriteOptions& options)
{
    Appearance a;
    a.drawType = options.drawType;
    if (part.hasVertexColors())
        a.lightMode = part.hasNormals() ? LightMode::VertexColorLit : LightMode::VertexColor;
    else
        a.lightMode = part.hasNormals() ? LightMode::FaceColorLit : LightMode::FaceColor;
    a.color = part.color;
    return a;
}

std::string levelName(const Level& level, std::size_t index)
{
    return level.name.empty() ? "lod" + std::to_string(index) : level.name;
}

std::string partName(const Part& part, std::size_t index)
{
    return part.name.empty() ? "part" + std::to_string(index) : part.name;
}

// Writes one model; the vertex palette offsets of every part's first vertex are known
// before the hierarchy is written.
class ModelWriter {
public:
    ModelWriter(const LodModel& model, const WriteOptions& options, ByteWriter& w, WriteStats& stats)
        : model_(model), options_(options), w_(w), stats_(stats)
    {
        totalTriangles_ = model.triangleCount();
    }

    void write()
    {
        HeaderFields header;
        header.id = model_.name;
        header.units = model_.units;
        writeHeader(w_, header);
        writeColorPalette(w_);
        writeMaterial(w_, MaterialFields{});
        if (options_.geometry == GeometryRecords::Faces)
            writeSharedVertexPalette();
        writePush(w_);
        writeGroup(w_, model_.name);
        writeLongIdIfNeeded(w_, model_.name);
        writePush(w_);
        for (std::size_t l = 0; l < model_.levels.size(); ++l)
            writeLevel(model_.levels[l], l);
        writePop(w_);
        writePop(w_);
    }

private:
    void writeSharedVertexPalette()
    {
        std::size_t bytes = size::VertexPalette;
        for (const Level& level : model_.levels)
            for (const Part& part : level.parts) {
                firstVertexOffset_.push_back(bytes);
                bytes += part.positions.size() * vertexRecordSize(part.hasNormals(), part.hasUvs());
            }
        writeVertexPalette(w_, static_cast<std::uint32_t>(bytes));
        for (const Level& level : model_.levels)
            for (const Part& part : level.parts)
                for (std::size_t v = 0; v < part.positions.size(); ++v)
                    writeVertex(w_, part.positions[v], part.hasNormals() ? &part.normals[v] : nullptr,
                                part.hasUvs() ? &part.uvs[v] : nullptr,
                                part.hasVertexColors() ? &part.vertexColors[v] : nullptr);
    }

    void writeLevel(const Level& level, std::size_t index)
    {
        const bool lod = writesLodRecords(model_);
        if (lod) {
            const std::string name = levelName(level, index);
            writeLod(w_, name, level.switchIn, level.switchOut, level.center);
            writeLongIdIfNeeded(w_, name);
            writePush(w_);
            ++stats_.lodNodes;
        }
        if (options_.objects == ObjectGrouping::PerLevel) {
            beginObject(levelName(level, index));
            for (const Part& part : level.parts)
                writePartGeometry(part);
            writePop(w_);
        } else {
            for (std::size_t p = 0; p < level.parts.size(); ++p) {
                beginObject(partName(level.parts[p], p));
                writePartGeometry(level.parts[p]);
                writePop(w_);
            }
        }
        if (lod)
            writePop(w_);
    }

    void beginObject(const std::string& name)
    {
        writeObject(w_, name);
        writeLongIdIfNeeded(w_, name);
        writePush(w_);
        ++stats_.objects;
    }

    void writePartGeometry(const Part& part)
    {
        const std::size_t partIndex = partCounter_++;
        stats_.vertices += part.positions.size();
        if (part.triangles.empty())
            return;
        if (options_.geometry == GeometryRecords::Faces)
            writeFaces(part, firstVertexOffset_[partIndex]);
        else
            writeMeshPart(part);
    }

    void writeFaces(const Part& part, std::size_t firstOffset)
    {
        const std::size_t stride = vertexRecordSize(part.hasNormals(), part.hasUvs());
        Appearance appearance = appearanceOf(part, options_);
        std::vector<std::uint32_t> offsets(3);
        for (std::size_t i = 0; i < part.triangles.size(); ++i) {
            const Triangle& t = part.triangles[i];
            appearance.color = part.colorOf(i);
            writeFace(w_, appearance);
            writePush(w_);
            for (int c = 0; c < 3; ++c)
                offsets[c] = static_cast<std::uint32_t>(firstOffset + t[c] * stride);
            writeVertexList(w_, offsets);
            writePop(w_);
            countTriangles(1);
        }
    }

    // A part with per-face colours: one Mesh record per colour (a Mesh has one colour),
    // each with the vertices its triangles use.
    void writeMeshPart(const Part& part)
    {
        std::map<std::uint32_t, std::vector<std::size_t>> byColor;
        if (part.hasTriangleColors())
            for (std::size_t i = 0; i < part.triangles.size(); ++i)
                byColor[packColor(part.triangleColors[i])].push_back(i);
        if (byColor.size() <= 1) {
            writeOneMesh(part, byColor.empty() ? part.color : part.triangleColors.front());
            return;
        }
        for (const auto& [packed, triangles] : byColor) {
            Part sub;
            sub.color = part.triangleColors[triangles.front()];
            std::vector<std::int64_t> local(part.positions.size(), -1);
            for (std::size_t t : triangles) {
                Triangle mapped;
                for (int c = 0; c < 3; ++c) {
                    const std::uint32_t v = part.triangles[t][c];
                    if (local[v] < 0) {
                        local[v] = std::int64_t(sub.positions.size());
                        sub.positions.push_back(part.positions[v]);
                        if (part.hasNormals())
                            sub.normals.push_back(part.normals[v]);
                        if (part.hasUvs())
                            sub.uvs.push_back(part.uvs[v]);
                        if (part.hasVertexColors())
                            sub.vertexColors.push_back(part.vertexColors[v]);
                    }
                    mapped[c] = std::uint32_t(local[v]);
                }
                sub.triangles.push_back(mapped);
            }
            writeOneMesh(sub, sub.color);
        }
    }

    void writeOneMesh(const Part& part, const Rgba& color)
    {
        Appearance appearance = appearanceOf(part, options_);
        appearance.color = color;
        writeMesh(w_, appearance);
        writeLocalVertexPool(w_, part.positions, part.hasNormals() ? part.normals : std::vector<Vec3f>{},
                             part.hasUvs() ? part.uvs : std::vector<Vec2f>{},
                             part.hasVertexColors() ? part.vertexColors : std::vector<Rgba>{});
        writePush(w_);
        writeMeshPrimitive(w_, PrimitiveType::TriangleStrip, stitchedStrip(part.triangles));
        writePop(w_);
        countTriangles(part.triangles.size());
    }

    void countTriangles(std::size_t n)
    {
        stats_.triangles += n;
        if (options_.progress && totalTriangles_ > 0 &&
            (n > 1 || stats_.triangles % 4096 == 0 || stats_.triangles == totalTriangles_))
            options_.progress(int(100.0 * double(stats_.triangles) / double(totalTriangles_)));
    }

    const LodModel& model_;
    const WriteOptions& options_;
    ByteWriter& w_;
    WriteStats& stats_;
    std::size_t totalTriangles_ = 0;
    std::size_t partCounter_ = 0;
    std::vector<std::size_t> firstVertexOffset_;
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

bool validateModel(const LodModel& model, std::string& error)
{
    if (model.levels.empty()) {
        error = "the model has no level";
        return false;
    }
    for (std::size_t l = 0; l < model.levels.size(); ++l)
        for (std::size_t p = 0; p < model.levels[l].parts.size(); ++p)
            if (!validatePart(model.levels[l].parts[p], where(l, p), error))
                return false;
    return true;
}

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
    WriteStats local;
    WriteStats& s = stats ? *stats : local;
    s = WriteStats{};
    out.clear();
    ByteWriter w(out);
    ModelWriter(model, options, w, s).write();
    s.bytes = out.size();
    return true;
}

bool writeOpenFlightFile(const std::string& path, const LodModel& model, const WriteOptions& options,
                         std::string& error, WriteStats* stats)
{
    std::vector<std::uint8_t> bytes;
    if (!writeOpenFlight(model, options, bytes, error, stats)) {
        error = path + ": " + error;
        return false;
    }
    // Through a temporary file renamed into place: never a truncated .flt (atomic_file.h).
    return writeFileAtomically(path, bytes, error);
}

}  // namespace cadlod::flt
