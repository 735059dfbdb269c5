#include "openflight/flt_reader.h"

#include "openflight/record_stream.h"

#include "openflight/byte_reader.h"
#include "openflight/records.h"
#include "openflight/triangle_strip.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <unordered_map>

namespace cadlod::flt {
namespace {

struct PoolVertex {
    Vec3d position{0, 0, 0};
    Vec3f normal{0, 0, 0};
    Vec2f uv{0, 0};
    Rgba color{1, 1, 1, 1};
    bool hasNormal = false;
    bool hasUv = false;
    bool hasColor = false;
};

enum class Node { None, Group, Lod, Object, Face, Mesh, Other };

Mat4d identityMatrix() { return {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}; }

bool isIdentity(const Mat4d& m) { return m == identityMatrix(); }


// What a Push opens: the primary record just before it, and where its geometry goes.
struct Frame {
    Node kind = Node::None;
    int level = -1;
    int part = -1;
    Mat4d toModel = identityMatrix();  // this frame's coordinates -> the model's
    int lodChildren = 0;               // LOD records met directly below: their ranks
    Rgba color{1, 1, 1, 1};
    std::vector<std::uint32_t> faceOffsets;  // Face: vertex palette offsets
    std::vector<PoolVertex> pool;            // Mesh: local vertex pool
    std::vector<std::int64_t> poolToPart;    // Mesh: pool index -> part vertex, -1 = not yet
};

struct LastPrimary {
    Node kind = Node::None;
    int level = -1;
    int part = -1;
    bool rootGroup = false;
    Rgba color{1, 1, 1, 1};
    bool hasMatrix = false;
    Mat4d matrix = identityMatrix();  // an ancillary Matrix record after it
};

// An Instance Definition's records, replayed at each Instance Reference.
struct RecordRange {
    std::size_t begin = 0, end = 0;
};

std::string hex32(std::uint32_t v)
{
    char text[11];
    std::snprintf(text, sizeof text, "0x%08x", unsigned(v));
    return text;
}

// Instances inside instances deeper than this are refused (a hostile file could nest many).
constexpr int kMaxInstanceNesting = 32;

class Reader {
public:
    Reader(const std::uint8_t* data, std::size_t size, LodModel& model, ReadStats& stats,
           const ReadOptions& options)
        : records_(data, size), size_(size), model_(model), stats_(stats), options_(options)
    {
        palette_.fill({1, 1, 1, 1});
        stack_.emplace_back();
    }

    bool run(std::string& error)
    {
        if (!readRange(0, size_, error))
            return false;
        if (size_ == 0) {
            error = "empty file: no OpenFlight Header record";
            return false;
        }
        if (!sawPush_) {
            error = "no geometry hierarchy: the file ends at offset " + std::to_string(size_) +
                    " without a Push record";
            return false;
        }
        if (stack_.size() != 1) {
            error = "unbalanced hierarchy: " + std::to_string(stack_.size() - 1) +
                    " Push record(s) without a Pop at the end of the file (offset " + std::to_string(size_) + ")";
            return false;
        }
        if (definition_.open) {
            error = "Instance Definition " + std::to_string(definition_.number) + " at offset " +
                    std::to_string(definition_.at) + " is not closed by the end of the file";
            return false;
        }
        mergeOutsideLodsIntoFinest();
        dropEmptyParts();
        return true;
    }

private:
    // The records in [begin, end): the whole file, or an Instance Definition replayed.
    bool readRange(std::size_t begin, std::size_t end, std::string& error)
    {
        std::size_t pos = begin, nextProgress = begin;
        while (pos < end) {
            std::uint16_t op = 0;
            std::size_t next = 0;
            std::vector<std::uint8_t> body;
            std::size_t continuations = 0;
            const bool read = records_.next(pos, op, body, next, continuations, error);
            stats_.records += continuations;
            if (!read)
                return false;
            if (pos == 0 && op != opcode::Header) {
                error = "not an OpenFlight file: the first record (offset 0) has " + opcodeText(op) +
                        ", expected a Header (1)";
                return false;
            }
            if (!defineOrHandle(op, body, pos, next, error))
                return false;
            ++stats_.records;
            pos = next;
            if (options_.progress && replayDepth_ == 0 && pos >= nextProgress) {
                options_.progress(int(100.0 * double(pos) / double(size_)));
                nextProgress = pos + (1u << 20);
            }
        }
        return true;
    }

    bool defineOrHandle(std::uint16_t op, const std::vector<std::uint8_t>& body, std::size_t pos, std::size_t next,
                        std::string& error)
    {
        if (definition_.open && keepInDefinition(op, pos, next))
            return true;
        try {
            return handle(op, body, pos, next, error);
        } catch (const ShortRecord& e) {
            error = "record at offset " + std::to_string(pos) + " (" + opcodeText(op) + ") is too short: " + e.what();
            return false;
        }
    }

    // An Instance Definition's records are kept to be read at each reference: its ancillary
    // records (a Matrix), then its Push ... Pop.
    // False for the record after a definition that has no Push: it is read as usual.
    bool keepInDefinition(std::uint16_t op, std::size_t pos, std::size_t next)
    {
        const bool primary = op != opcode::Push && op != opcode::Pop && op != opcode::LongId && op != opcode::Matrix &&
                             op != opcode::Continuation;
        if (definition_.depth == 0 && primary) {
            definitions_[definition_.number] = {definition_.begin, pos};
            definition_.open = false;
            return false;
        }
        if (op == opcode::Push)
            ++definition_.depth;
        else if (op == opcode::Pop && --definition_.depth == 0) {
            definitions_[definition_.number] = {definition_.begin, next};
            definition_.open = false;
        }
        return true;
    }

    void beginDefinition(ByteReader& in, std::size_t pos, std::size_t next)
    {
        in.skip(2);
        definition_ = OpenDefinition{true, int(in.u16()), 0, next, pos};
        ++stats_.instanceDefinitions;
    }

    bool readReference(ByteReader& in, std::size_t pos, std::string& error)
    {
        in.skip(2);
        const int number = in.u16();
        const auto it = definitions_.find(number);
        if (it == definitions_.end()) {
            error = "Instance Reference at offset " + std::to_string(pos) + " refers to definition " +
                    std::to_string(number) + ", which no Instance Definition before it defines";
            return false;
        }
        if (replayDepth_ >= kMaxInstanceNesting) {
            error = "Instance Reference at offset " + std::to_string(pos) + ": instances nested deeper than " +
                    std::to_string(kMaxInstanceNesting);
            return false;
        }
        ++stats_.instanceReferences;
        last_ = LastPrimary{Node::Other, stack_.back().level, stack_.back().part};
        ++replayDepth_;
        const bool ok = readRange(it->second.begin, it->second.end, error);
        --replayDepth_;
        last_ = LastPrimary{Node::Other, stack_.back().level, stack_.back().part};
        return ok;
    }

    // Ancillary to the record before it; OpenFlight's row-vector matrix, turned to columns.
    void readMatrix(ByteReader& in)
    {
        Mat4d m{};
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 4; ++col)
                m[col][row] = in.f32();
        last_.hasMatrix = true;
        last_.matrix = m;
    }

private:
    bool handle(std::uint16_t op, const std::vector<std::uint8_t>& body, std::size_t pos, std::size_t next,
                std::string& error)
    {
        ByteReader in(body.data(), body.size());
        switch (op) {
        case opcode::Header: return readHeader(in, pos, error);
        case opcode::ColorPalette: readColorPalette(in); return true;
        case opcode::VertexPalette: paletteStart_ = pos; havePalette_ = true; return true;
        case opcode::VertexColor:
        case opcode::VertexNormal:
        case opcode::VertexNormalUv:
        case opcode::VertexColorUv: readPaletteVertex(op, in, pos); return true;
        case opcode::Push: push(); sawPush_ = true; return true;
        case opcode::Pop: return pop(pos, error);
        case opcode::Group: readGroup(); return true;
        case opcode::Matrix: readMatrix(in); return true;
        case opcode::InstanceDefinition: beginDefinition(in, pos, next); return true;
        case opcode::InstanceReference: return readReference(in, pos, error);
        case opcode::Lod: readLod(in); return true;
        case opcode::Object: readObject(in); return true;
        case opcode::LongId: readLongId(in); return true;
        case opcode::Face: readFace(in); return true;
        case opcode::Mesh: readMesh(in); return true;
        case opcode::VertexList: readVertexList(in); return true;
        case opcode::LocalVertexPool: return readLocalVertexPool(in, pos, error);
        case opcode::MeshPrimitive: return readMeshPrimitive(in, pos, error);
        case opcode::Continuation:
            error = "misplaced Continuation record at offset " + std::to_string(pos);
            return false;
        default:
            if (isPrimaryRecord(op))
                last_ = LastPrimary{Node::Other, stack_.back().level, stack_.back().part};
            ++stats_.unknownRecords;
            return true;
        }
    }

    bool readHeader(ByteReader& in, std::size_t pos, std::string& error)
    {
        in.skip(8);
        stats_.formatRevision = in.i32();
        in.seek(58);
        const int unitCode = in.u8();
        if (!unitsFromCode(unitCode, model_.units)) {
            error = "Header at offset " + std::to_string(pos) + ": unknown vertex coordinate units code " +
                    std::to_string(unitCode);
            return false;
        }
        return true;
    }

    void readColorPalette(ByteReader& in)
    {
        in.skip(128);
        for (Rgba& c : palette_) {
            if (in.remaining() < 4)
                break;
            c = unpackColor(in.u32());
            c[3] = 1.0f;
        }
    }

    void readPaletteVertex(std::uint16_t op, ByteReader& in, std::size_t pos)
    {
        if (!havePalette_) {
            ++stats_.unknownRecords;
            return;
        }
        PoolVertex v;
        in.skip(2);  // color name index
        const std::uint16_t flags = in.u16();
        for (double& x : v.position)
            x = in.f64();
        if (op == opcode::VertexNormal || op == opcode::VertexNormalUv) {
            for (float& x : v.normal)
                x = in.f32();
            v.hasNormal = true;
        }
        if (op == opcode::VertexNormalUv || op == opcode::VertexColorUv) {
            v.uv = {in.f32(), in.f32()};
            v.hasUv = true;
        }
        const std::uint32_t packed = in.u32();
        if ((flags & kVertexPackedColor) && !(flags & kVertexNoColor)) {
            v.color = unpackColor(packed);
            v.hasColor = true;
        }
        paletteVertices_[static_cast<std::uint32_t>(pos - paletteStart_)] = v;
    }

    void push()
    {
        if (last_.kind == Node::Face || last_.kind == Node::Mesh)
            ensurePart(stack_.back());
        const Frame& outer = stack_.back();
        Frame f;
        f.kind = last_.kind;
        f.level = last_.kind == Node::Lod ? last_.level : outer.level;
        f.part = last_.kind == Node::Object ? last_.part : last_.kind == Node::Lod ? -1 : outer.part;
        f.color = last_.color;
        f.toModel = last_.hasMatrix ? multiply(outer.toModel, last_.matrix) : outer.toModel;
        if (last_.kind == Node::Mesh) {
            f.pool = std::move(pendingPool_);
            f.poolToPart.assign(f.pool.size(), -1);
        }
        pendingPool_.clear();
        stack_.push_back(std::move(f));
        last_ = LastPrimary{};
    }

    bool pop(std::size_t pos, std::string& error)
    {
        if (stack_.size() <= 1) {
            error = "unbalanced hierarchy: Pop record at offset " + std::to_string(pos) + " without a Push";
            return false;
        }
        Frame& f = stack_.back();
        if (f.kind == Node::Face)
            finishFace(f);
        last_ = LastPrimary{f.kind, f.level, f.part};
        stack_.pop_back();
        return true;
    }

    void readGroup()
    {
        last_ = LastPrimary{Node::Group, stack_.back().level, stack_.back().part};
        last_.rootGroup = !sawGroup_;
        sawGroup_ = true;
    }

    // Sibling LOD records are the levels of one node: the k-th of each node (each part of an
    // assembly, each placement of an instance) goes to level k.
    void readLod(ByteReader& in)
    {
        Level level;
        level.name = in.string(8);
        in.skip(4);
        level.switchIn = in.f64();
        level.switchOut = in.f64();
        in.skip(8);
        for (double& x : level.center)
            x = in.f64();
        const std::size_t rank = std::size_t(stack_.back().lodChildren++);
        if (rank >= levelOfRank_.size()) {
            model_.levels.push_back(std::move(level));
            levelOfRank_.push_back(int(model_.levels.size()) - 1);
        } else {
            severalLodNodes_ = true;
        }
        last_ = LastPrimary{Node::Lod, levelOfRank_[rank], -1};
    }

    // In a file of several LOD nodes, what no LOD holds is drawn at every distance: it
    // belongs with the finest level.
    void mergeOutsideLodsIntoFinest()
    {
        if (!severalLodNodes_ || defaultLevel_ < 0 || levelOfRank_.empty())
            return;
        auto& outside = model_.levels[std::size_t(defaultLevel_)].parts;
        auto& finest = model_.levels[std::size_t(levelOfRank_[0])].parts;
        finest.insert(finest.end(), std::make_move_iterator(outside.begin()), std::make_move_iterator(outside.end()));
        model_.levels.erase(model_.levels.begin() + defaultLevel_);
    }

    int currentLevel()
    {
        Frame& ctx = stack_.back();
        if (ctx.level < 0) {
            if (defaultLevel_ < 0) {
                model_.levels.emplace_back();
                defaultLevel_ = int(model_.levels.size()) - 1;
            }
            ctx.level = defaultLevel_;
        }
        return ctx.level;
    }

    int newPart(int level, const std::string& name)
    {
        auto& parts = model_.levels[std::size_t(level)].parts;
        parts.emplace_back();
        parts.back().name = name;
        return int(parts.size()) - 1;
    }

    void readObject(ByteReader& in)
    {
        const int level = currentLevel();
        last_ = LastPrimary{Node::Object, level, newPart(level, in.string(8))};
    }

    void readLongId(ByteReader& in)
    {
        const std::string name = in.string(in.remaining());
        if (name.empty())
            return;  // keeps the record's own 8-character name
        if (last_.kind == Node::Lod)
            model_.levels[std::size_t(last_.level)].name = name;
        else if (last_.kind == Node::Object)
            partOf(last_.level, last_.part).name = name;
        else if (last_.kind == Node::Group && last_.rootGroup)
            model_.name = name;
    }

    Part& partOf(int level, int part) { return model_.levels[std::size_t(level)].parts[std::size_t(part)]; }

    // Geometry outside any Object goes to one implicit part per depth.
    void ensurePart(Frame& ctx)
    {
        if (ctx.part >= 0)
            return;
        const int level = currentLevel();
        ctx.part = newPart(level, std::string());
    }

    // Face and Mesh share the appearance fields; the Mesh's are 4 bytes further on.
    // Offsets below are record offsets; the body starts after the 4-byte header.
    Rgba appearanceColor(ByteReader& in, std::size_t shift)
    {
        auto field = [&in, shift](std::size_t recordOffset) { in.seek(recordOffset - 4 + shift); };
        field(40);
        const std::uint16_t transparency = in.u16();
        field(44);
        const std::uint32_t flags = in.u32();
        field(56);
        const std::uint32_t packed = in.u32();
        field(68);
        const std::int32_t index = in.i32();
        Rgba c{1, 1, 1, 1};
        if (flags & kFacePackedColor) {
            c = unpackColor(packed);
        } else if (index >= 0) {
            const Rgba& base = palette_[std::size_t(index / 128) % palette_.size()];
            const float intensity = float(index % 128) / 127.0f;
            c = {base[0] * intensity, base[1] * intensity, base[2] * intensity, 1.0f};
        }
        c[3] = 1.0f - float(transparency) / 65535.0f;
        return c;
    }

    void readFace(ByteReader& in)
    {
        last_ = LastPrimary{Node::Face, stack_.back().level, stack_.back().part};
        last_.color = appearanceColor(in, 0);
        ++stats_.faces;
    }

    void readMesh(ByteReader& in)
    {
        last_ = LastPrimary{Node::Mesh, stack_.back().level, stack_.back().part};
        last_.color = appearanceColor(in, 4);
        pendingPool_.clear();
    }

    void readVertexList(ByteReader& in)
    {
        Frame& f = stack_.back();
        if (f.kind != Node::Face)
            return;
        while (in.remaining() >= 4)
            f.faceOffsets.push_back(in.u32());
    }

    void setPartColorOnce(int level, int part, const Rgba& color)
    {
        if (coloredParts_.emplace(level, part).second)
            partOf(level, part).color = color;
    }

    void finishFace(Frame& f)
    {
        const int level = f.level, part = f.part;
        Part& p = partOf(level, part);
        auto& index = faceVertexIndex_[{level, part}];
        std::vector<std::uint32_t> corners;
        const bool moved = !isIdentity(f.toModel);
        for (std::uint32_t offset : f.faceOffsets) {
            const auto v = paletteVertices_.find(offset);
            if (v == paletteVertices_.end() || !isFinite(v->second.position))
                continue;
            if (moved) {  // a palette vertex stands elsewhere in each placement
                corners.push_back(std::uint32_t(p.positions.size()));
                appendVertex(p, v->second, f.toModel);
                continue;
            }
            const auto [it, added] = index.emplace(offset, std::uint32_t(p.positions.size()));
            if (added)
                appendVertex(p, v->second);
            corners.push_back(it->second);
        }

        if (corners.size() < 3) {
            ++stats_.skippedFaces;
            return;
        }
        setPartColorOnce(level, part, f.color);
        for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
            p.triangles.push_back({corners[0], corners[i], corners[i + 1]});
            p.triangleColors.push_back(f.color);
        }
    }

    // NaN or infinite coordinates cannot be placed: their faces are skipped and counted.
    static bool isFinite(const Vec3d& position)
    {
        return std::isfinite(position[0]) && std::isfinite(position[1]) && std::isfinite(position[2]);
    }

    static Vec3d transformed(const Mat4d& m, const Vec3d& p, double w)
    {
        Vec3d out{};
        for (int r = 0; r < 3; ++r)
            out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + m[r][3] * w;
        return out;
    }

    // A vertex in the model's coordinates: moved by the frame's matrices (instances, groups).
    void appendVertex(Part& p, const PoolVertex& v, const Mat4d& toModel)
    {
        if (isIdentity(toModel)) {
            appendVertex(p, v);
            return;
        }
        PoolVertex moved = v;
        moved.position = transformed(toModel, v.position, 1.0);
        const Vec3d n = transformed(toModel, {v.normal[0], v.normal[1], v.normal[2]}, 0.0);
        const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (length > 0)
            moved.normal = {float(n[0] / length), float(n[1] / length), float(n[2] / length)};
        appendVertex(p, moved);
    }

    void appendVertex(Part& p, const PoolVertex& v)
    {
        if (v.hasNormal && p.normals.size() == p.positions.size())
            p.normals.push_back(v.normal);
        if (v.hasUv && p.uvs.size() == p.positions.size())
            p.uvs.push_back(v.uv);
        if (v.hasColor && p.vertexColors.size() == p.positions.size())
            p.vertexColors.push_back(v.color);
        p.positions.push_back(v.position);
        // A part whose vertices disagree on attributes keeps none of that attribute.
        if (p.normals.size() != p.positions.size())
            p.normals.clear();
        if (p.uvs.size() != p.positions.size())
            p.uvs.clear();
        if (p.vertexColors.size() != p.positions.size())
            p.vertexColors.clear();
    }

    bool readLocalVertexPool(ByteReader& in, std::size_t pos, std::string& error)
    {
        const std::uint32_t count = in.u32();
        const std::uint32_t mask = in.u32();
        std::size_t stride = (mask & kPoolPosition ? 24 : 0) + (mask & 0x40000000u ? 4 : 0) +
                             (mask & 0x20000000u ? 4 : 0) + (mask & kPoolNormal ? 12 : 0);
        for (int layer = 0; layer < 8; ++layer)
            if (mask & (kPoolBaseUv >> layer))
                stride += 8;
        // Every vertex must take bytes in the record, so a pool never costs more memory than
        // a fixed multiple of the file (a zero stride used to allocate up to ~177 GB).
        if (stride == 0 && count > 0) {
            error = "Local Vertex Pool at offset " + std::to_string(pos) + ": " + std::to_string(count) +
                    " vertices announced with no known attribute in the mask " + hex32(mask);
            return false;
        }
        if (stride > 0 && in.remaining() / stride < count) {
            error = "Local Vertex Pool at offset " + std::to_string(pos) + ": " + std::to_string(count) +
                    " vertices announced, the record holds " + std::to_string(in.remaining() / stride);
            return false;
        }
        pendingPool_.assign(count, PoolVertex{});
        for (PoolVertex& v : pendingPool_) {
            if (mask & kPoolPosition)
                for (double& x : v.position)
                    x = in.f64();
            if (mask & 0x40000000u)
                in.skip(4);  // color index
            if (mask & kPoolRgba) {
                v.color = unpackColor(in.u32());
                v.hasColor = true;
            }
            if (mask & kPoolNormal) {
                for (float& x : v.normal)
                    x = in.f32();
                v.hasNormal = true;
            }
            if (mask & kPoolBaseUv) {
                v.uv = {in.f32(), in.f32()};
                v.hasUv = true;
            }
            for (int layer = 1; layer < 8; ++layer)
                if (mask & (kPoolBaseUv >> layer))
                    in.skip(8);
        }
        return true;
    }

    bool readIndices(ByteReader& in, std::size_t pos, std::vector<std::uint32_t>& indices, std::string& error)
    {
        const std::uint16_t indexSize = in.u16();
        const std::uint32_t count = in.u32();
        if (indexSize != 1 && indexSize != 2 && indexSize != 4) {
            error = "Mesh Primitive at offset " + std::to_string(pos) + ": index size " +
                    std::to_string(indexSize) + " (expected 1, 2 or 4)";
            return false;
        }
        if (in.remaining() / indexSize < count) {
            error = "Mesh Primitive at offset " + std::to_string(pos) + ": " + std::to_string(count) +
                    " indices announced, the record holds " + std::to_string(in.remaining() / indexSize);
            return false;
        }
        indices.resize(count);
        for (std::uint32_t& i : indices)
            i = indexSize == 1 ? in.u8() : indexSize == 2 ? in.u16() : in.u32();
        return true;
    }

    bool readMeshPrimitive(ByteReader& in, std::size_t pos, std::string& error)
    {
        Frame& f = stack_.back();
        if (f.kind != Node::Mesh) {
            ++stats_.unknownRecords;
            return true;
        }
        const std::int16_t type = in.i16();
        std::vector<std::uint32_t> indices;
        if (!readIndices(in, pos, indices, error))
            return false;
        ++stats_.faces;
        const int level = f.level, part = f.part;
        Part& p = partOf(level, part);
        setPartColorOnce(level, part, f.color);
        std::size_t valid = 0;
        for (const Triangle& t : primitiveTriangles(type, indices)) {
            Triangle mapped;
            bool ok = true;
            for (int c = 0; c < 3 && ok; ++c) {
                ok = t[c] < f.pool.size() && isFinite(f.pool[t[c]].position);
                if (!ok)
                    break;
                std::int64_t& target = f.poolToPart[t[c]];
                if (target < 0) {
                    target = std::int64_t(p.positions.size());
                    appendVertex(p, f.pool[t[c]], f.toModel);
                }
                mapped[c] = std::uint32_t(target);
            }
            if (!ok) {
                ++stats_.skippedFaces;
                continue;
            }

            p.triangles.push_back(mapped);
            p.triangleColors.push_back(f.color);
            ++valid;
        }
        if (valid == 0)
            ++stats_.skippedFaces;
        return true;
    }

    // Also drops the per-triangle colours of a part whose faces all have the part's colour.
    void dropEmptyParts()
    {
        for (Level& level : model_.levels) {
            std::vector<Part> kept;
            for (Part& p : level.parts) {
                const bool uniform = std::all_of(p.triangleColors.begin(), p.triangleColors.end(),
                                                 [&](const Rgba& c) { return c == p.color; });
                if (uniform)
                    p.triangleColors.clear();
                if (!p.triangles.empty())
                    kept.push_back(std::move(p));
            }
            level.parts = std::move(kept);
        }
    }

    RecordStream records_;
    std::size_t size_;
    LodModel& model_;
    ReadStats& stats_;
    const ReadOptions& options_;
    std::array<Rgba, 1024> palette_{};
    std::vector<Frame> stack_;
    LastPrimary last_;
    bool havePalette_ = false;
    bool sawGroup_ = false;
    bool sawPush_ = false;
    std::size_t paletteStart_ = 0;
    int defaultLevel_ = -1;
    std::unordered_map<std::uint32_t, PoolVertex> paletteVertices_;
    std::vector<PoolVertex> pendingPool_;
    std::map<std::pair<int, int>, std::unordered_map<std::uint32_t, std::uint32_t>> faceVertexIndex_;
    std::set<std::pair<int, int>> coloredParts_;
    std::vector<int> levelOfRank_;
    bool severalLodNodes_ = false;
    struct OpenDefinition {
        bool open = false;
        int number = 0;
        int depth = 0;
        std::size_t begin = 0, at = 0;
    } definition_;
    std::map<int, RecordRange> definitions_;
    int replayDepth_ = 0;
};

}  // namespace

bool readOpenFlight(const std::uint8_t* data, std::size_t size, LodModel& model, std::string& error,
                    ReadStats* stats, const ReadOptions& options)
{
    ReadStats local;
    ReadStats& s = stats ? *stats : local;
    s = ReadStats{};
    model = LodModel{};
    model.name.clear();
    return Reader(data, size, model, s, options).run(error);
}

bool readOpenFlightFile(const std::string& path, LodModel& model, std::string& error, ReadStats* stats,
                        const ReadOptions& options)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = path + ": cannot open the file";
        return false;
    }
    const std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (!readOpenFlight(bytes.data(), bytes.size(), model, error, stats, options)) {
        error = path + ": " + error;
        return false;
    }
    return true;
}

std::size_t finestLevel(const LodModel& model)
{
    std::size_t best = 0;
    for (std::size_t i = 1; i < model.levels.size(); ++i)
        if (model.levels[i].switchOut < model.levels[best].switchOut)
            best = i;
    return best;
}

}  // namespace cadlod::flt
