#include "openflight/level_writer.h"

#include "openflight/atomic_file.h"
#include "openflight/triangle_strip.h"

#include <map>
#include <utility>

namespace cadlod::flt {
namespace {

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

// The part seen in a mirror: the same vertices, each triangle's winding reversed.
Part turnedRound(const Part& part)
{
    Part turned = part;
    for (Triangle& t : turned.triangles)
        std::swap(t[1], t[2]);
    return turned;
}

}  // namespace

void writeDatabaseHead(ByteWriter& w, const std::string& name, Units units)
{
    HeaderFields header;
    header.id = name;
    header.units = units;
    writeHeader(w, header);
    writeColorPalette(w);
    writeMaterial(w, MaterialFields{});
}

void openRootGroup(ByteWriter& w, const std::string& name, const Vec3d& origin)
{
    writePush(w);
    writeGroup(w, name);
    writeLongIdIfNeeded(w, name);
    if (origin != Vec3d{0, 0, 0})
        writeMatrix(w, translationMatrix(origin));
    writePush(w);
}

void closeRootGroup(ByteWriter& w)
{
    writePop(w);
    writePop(w);
}

bool writeDatabaseFile(const std::string& path,
                       const std::function<bool(std::vector<std::uint8_t>&, std::string&)>& write, std::string& error)
{
    std::vector<std::uint8_t> bytes;
    if (!write(bytes, error)) {
        error = path + ": " + error;
        return false;
    }
    return writeFileAtomically(path, bytes, error);
}

bool writesLodRecords(const std::vector<Level>& levels)
{
    return levels.size() > 1 || (levels.size() == 1 && levels[0].hasRange());
}

LevelWriter::LevelWriter(const WriteOptions& options, ByteWriter& w, WriteStats& stats, std::size_t totalTriangles)
    : options_(options), w_(w), stats_(stats), totalTriangles_(totalTriangles)
{
}

void LevelWriter::writeSharedVertexPalette(const std::vector<Level>& levels)
{
    std::size_t bytes = size::VertexPalette;
    for (const Level& level : levels)
        for (const Part& part : level.parts) {
            firstVertexOffset_.push_back(bytes);
            bytes += part.positions.size() * vertexRecordSize(part.hasNormals(), part.hasUvs());
        }
    writeVertexPalette(w_, static_cast<std::uint32_t>(bytes));
    for (const Level& level : levels)
        for (const Part& part : level.parts)
            for (std::size_t v = 0; v < part.positions.size(); ++v)
                writeVertex(w_, part.positions[v], part.hasNormals() ? &part.normals[v] : nullptr,
                            part.hasUvs() ? &part.uvs[v] : nullptr,
                            part.hasVertexColors() ? &part.vertexColors[v] : nullptr);
}

void LevelWriter::writeLevels(const std::vector<Level>& levels, bool lodRecords, bool reversed, std::size_t first)
{
    reversed_ = reversed;
    for (std::size_t l = 0; l < levels.size(); ++l)
        writeLevel(levels[l], first + l, lodRecords);
}

void LevelWriter::writeGeometry(const Level& level, bool reversed)
{
    reversed_ = reversed;
    writeLevel(level, 0, false);
}

void LevelWriter::writeLevel(const Level& level, std::size_t index, bool lod)
{
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

void LevelWriter::beginObject(const std::string& name)
{
    writeObject(w_, name);
    writeLongIdIfNeeded(w_, name);
    writePush(w_);
    ++stats_.objects;
}

void LevelWriter::writePartGeometry(const Part& part)
{
    const std::size_t partIndex = partCounter_++;
    stats_.vertices += part.positions.size();
    if (part.triangles.empty())
        return;
    if (options_.geometry == GeometryRecords::Faces)
        writeFaces(part, firstVertexOffset_[partIndex]);
    else if (reversed_)
        writeMeshPart(turnedRound(part));
    else
        writeMeshPart(part);
}

void LevelWriter::writeFaces(const Part& part, std::size_t firstOffset)
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
void LevelWriter::writeMeshPart(const Part& part)
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
        std::vector<std::uint32_t> copied(part.positions.size(), kNotCopied);
        for (std::size_t t : triangles) {
            Triangle mapped;
            for (int c = 0; c < 3; ++c)
                mapped[c] = copiedVertex(part, part.triangles[t][c], copied, sub);
            sub.triangles.push_back(mapped);
        }
        writeOneMesh(sub, sub.color);
    }
}

void LevelWriter::writeOneMesh(const Part& part, const Rgba& color)
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

void LevelWriter::countTriangles(std::size_t n)
{
    stats_.triangles += n;
    if (options_.progress && totalTriangles_ > 0 &&
        (n > 1 || stats_.triangles % 4096 == 0 || stats_.triangles == totalTriangles_))
        options_.progress(int(100.0 * double(stats_.triangles) / double(totalTriangles_)));
}

}  // namespace cadlod::flt
