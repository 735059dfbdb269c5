#include "openflight/records.h"

#include <algorithm>
#include <cmath>

namespace cadlod::flt {
namespace {

constexpr std::size_t kIdWidth = 8;

void recordHeader(ByteWriter& w, std::uint16_t op, std::size_t length)
{
    w.u16(op);
    w.u16(static_cast<std::uint16_t>(length));
}

std::uint8_t toByte(float v)
{
    return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

std::uint16_t transparency(const Rgba& c)
{
    return static_cast<std::uint16_t>(std::lround((1.0f - std::clamp(c[3], 0.0f, 1.0f)) * 65535.0f));
}

void vec3(ByteWriter& w, const Vec3f& v)
{
    for (float x : v)
        w.f32(x);
}

// Face and Mesh share this layout after the ID (the Mesh has 4 reserved bytes more).
void appearanceFields(ByteWriter& w, const Appearance& a)
{
    w.i32(0);                                   // IR color code
    w.i16(0);                                   // relative priority
    w.u8(static_cast<std::uint8_t>(a.drawType));
    w.u8(0);                                    // texture white
    w.i16(-1);                                  // color name index
    w.i16(-1);                                  // alternate color name index
    w.u8(0);                                    // reserved
    w.u8(a.color[3] < 1.0f ? 1 : 0);            // template: fixed, alpha blending if translucent
    w.i16(-1);                                  // detail texture
    w.i16(-1);                                  // texture
    w.i16(a.materialIndex);
    w.i16(0);                                   // surface material code
    w.i16(0);                                   // feature ID
    w.i32(0);                                   // IR material code
    w.u16(transparency(a.color));
    w.u8(0);                                    // LOD generation control
    w.u8(0);                                    // line style
    w.u32(kFacePackedColor | kFaceNoAltColor);
    w.u8(static_cast<std::uint8_t>(a.lightMode));
    w.zeros(7);
    w.u32(packColor(a.color));                  // packed primary color
    w.u32(0);                                   // packed alternate color
    w.i16(-1);                                  // texture mapping
    w.i16(0);
    w.i32(-1);                                  // primary color index
    w.i32(-1);                                  // alternate color index
    w.i16(0);
    w.i16(-1);                                  // shader
}

}  // namespace

std::string shortId(const std::string& name) { return name.substr(0, kIdWidth - 1); }
bool needsLongId(const std::string& name) { return name.size() > kIdWidth - 1; }

std::uint32_t packColor(const Rgba& c)
{
    return std::uint32_t(toByte(c[3])) << 24 | std::uint32_t(toByte(c[2])) << 16 |
           std::uint32_t(toByte(c[1])) << 8 | toByte(c[0]);
}

Rgba unpackColor(std::uint32_t abgr)
{
    auto channel = [abgr](int shift) { return float((abgr >> shift) & 0xff) / 255.0f; };
    return {channel(0), channel(8), channel(16), channel(24)};
}

void writeHeader(ByteWriter& w, const HeaderFields& h)
{
    const std::size_t start = w.size();
    recordHeader(w, opcode::Header, size::Header);
    w.fixedString(h.id, kIdWidth);
    w.i32(kFormatRevision);
    w.i32(0);                   // edit revision
    w.fixedString("", 32);      // date and time of last revision
    w.zeros(8);                 // next group, LOD, object, face node IDs
    w.i16(1);                   // unit multiplier
    w.u8(static_cast<std::uint8_t>(h.units));
    w.u8(0);                    // texwhite
    w.u32(h.saveNormals ? kHeaderSaveNormals : 0);
    w.zeros(24);                // reserved
    w.i32(0);                   // projection: flat earth
    w.zeros(28);                // reserved
    w.i16(0);                   // next DOF ID
    w.i16(1);                   // vertex storage: double precision
    w.i32(100);                 // database origin: OpenFlight
    w.zeros(size::Header - (w.size() - start));  // extents, lat/long, ellipsoid, next IDs
}

void writeColorPalette(ByteWriter& w)
{
    recordHeader(w, opcode::ColorPalette, size::ColorPalette);
    w.zeros(128);
    for (int i = 0; i < 1024; ++i)
        w.u32(0xffffffffu);  // white; faces use packed colors
}

void writeMaterial(ByteWriter& w, const MaterialFields& m)
{
    recordHeader(w, opcode::Material, size::Material);
    w.i32(m.index);
    w.fixedString(m.name, 12);
    w.u32(0x80000000u);  // flags: materials used
    vec3(w, m.ambient);
    vec3(w, m.diffuse);
    vec3(w, m.specular);
    vec3(w, m.emissive);
    w.f32(m.shininess);
    w.f32(m.alpha);
    w.i32(0);
}

void writeVertexPalette(ByteWriter& w, std::uint32_t paletteBytes)
{
    recordHeader(w, opcode::VertexPalette, size::VertexPalette);
    w.u32(paletteBytes);
}

std::size_t vertexRecordSize(bool hasNormal, bool hasUv)
{
    if (hasNormal)
        return hasUv ? size::VertexNormalUv : size::VertexNormal;
    return hasUv ? size::VertexColorUv : size::VertexColor;
}

void writeVertex(ByteWriter& w, const Vec3d& p, const Vec3f* normal, const Vec2f* uv, const Rgba* color)
{
    const std::uint16_t op = normal ? (uv ? opcode::VertexNormalUv : opcode::VertexNormal)
                                    : (uv ? opcode::VertexColorUv : opcode::VertexColor);
    recordHeader(w, op, vertexRecordSize(normal != nullptr, uv != nullptr));
    w.u16(0);  // color name index
    w.u16(color ? kVertexPackedColor : kVertexNoColor);
    for (double x : p)
        w.f64(x);
    if (normal)
        vec3(w, *normal);
    if (uv) {
        w.f32((*uv)[0]);
        w.f32((*uv)[1]);
    }
    w.u32(color ? packColor(*color) : 0);  // packed color
    w.i32(-1);                            // color index
    if (normal)
        w.i32(0);
}

void writeGroup(ByteWriter& w, const std::string& name)
{
    recordHeader(w, opcode::Group, size::Group);
    w.fixedString(shortId(name), kIdWidth);
    w.zeros(size::Group - 12);  // priority, flags, effects, significance, layer, loop: none
}

void writeLod(ByteWriter& w, const std::string& name, double switchIn, double switchOut, const Vec3d& center)
{
    recordHeader(w, opcode::Lod, size::Lod);
    w.fixedString(shortId(name), kIdWidth);
    w.i32(0);
    w.f64(switchIn);
    w.f64(switchOut);
    w.i16(0);  // special effect IDs
    w.i16(0);
    w.u32(0);  // flags: no "use previous slant range", no freeze center
    for (double x : center)
        w.f64(x);
    w.f64(0);  // transition range
    w.f64(0);  // significant size
}

void writeMatrix(ByteWriter& w, const Mat4d& columns)
{
    recordHeader(w, opcode::Matrix, size::Matrix);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col)
            w.f32(static_cast<float>(columns[col][row]));
}

void writeInstanceDefinition(ByteWriter& w, int number)
{
    recordHeader(w, opcode::InstanceDefinition, size::Instance);
    w.u16(0);
    w.u16(static_cast<std::uint16_t>(number));
}

void writeInstanceReference(ByteWriter& w, int number)
{
    recordHeader(w, opcode::InstanceReference, size::Instance);
    w.u16(0);
    w.u16(static_cast<std::uint16_t>(number));
}

void writeObject(ByteWriter& w, const std::string& name)
{
    recordHeader(w, opcode::Object, size::Object);
    w.fixedString(shortId(name), kIdWidth);
    w.zeros(size::Object - 12);  // flags, priority, transparency, effects, significance
}

void writeFace(ByteWriter& w, const Appearance& a)
{
    recordHeader(w, opcode::Face, size::Face);
    w.fixedString("", kIdWidth);
    appearanceFields(w, a);
}

void writeMesh(ByteWriter& w, const Appearance& a)
{
    recordHeader(w, opcode::Mesh, size::Mesh);
    w.fixedString("", kIdWidth);
    w.i32(0);
    appearanceFields(w, a);
}

void writeVertexList(ByteWriter& w, const std::vector<std::uint32_t>& offsets)
{
    for (std::size_t first = 0; first < offsets.size(); first += size::MaxVertexListEntries) {
        const std::size_t n = std::min(size::MaxVertexListEntries, offsets.size() - first);
        recordHeader(w, opcode::VertexList, 4 + 4 * n);
        for (std::size_t i = first; i < first + n; ++i)
            w.u32(offsets[i]);
    }
}

void writeLongId(ByteWriter& w, const std::string& name)
{
    const std::string text = name.substr(0, size::MaxRecord - 5);
    const std::size_t length = (4 + text.size() + 1 + 3) / 4 * 4;  // NUL-terminated, padded
    recordHeader(w, opcode::LongId, length);
    w.fixedString(text, length - 4);
}

void writeLongIdIfNeeded(ByteWriter& w, const std::string& name)
{
    if (needsLongId(name))
        writeLongId(w, name);
}

void writePush(ByteWriter& w) { recordHeader(w, opcode::Push, 4); }
void writePop(ByteWriter& w) { recordHeader(w, opcode::Pop, 4); }

void writeContinuedRecord(ByteWriter& w, std::uint16_t op, const std::vector<std::uint8_t>& body)
{
    constexpr std::size_t chunk = size::MaxRecord - 4;
    std::size_t done = 0;
    do {
        const std::size_t n = std::min(chunk, body.size() - done);
        const std::size_t padded = (n + 3) / 4 * 4;
        recordHeader(w, done == 0 ? op : opcode::Continuation, 4 + padded);
        w.bytes(body.data() + done, n);
        w.zeros(padded - n);
        done += n;
    } while (done < body.size());
}

void writeLocalVertexPool(ByteWriter& w, const std::vector<Vec3d>& positions,
                          const std::vector<Vec3f>& normals, const std::vector<Vec2f>& uvs,
                          const std::vector<Rgba>& colors)
{
    const bool hasNormals = !normals.empty(), hasUvs = !uvs.empty(), hasColors = !colors.empty();
    std::vector<std::uint8_t> body;
    body.reserve(8 + positions.size() * (24 + (hasNormals ? 12 : 0) + (hasUvs ? 8 : 0)));
    ByteWriter b(body);
    b.u32(static_cast<std::uint32_t>(positions.size()));
    b.u32(kPoolPosition | (hasColors ? kPoolRgba : 0) | (hasNormals ? kPoolNormal : 0) | (hasUvs ? kPoolBaseUv : 0));
    for (std::size_t i = 0; i < positions.size(); ++i) {
        for (double x : positions[i])
            b.f64(x);
        if (hasColors)
            b.u32(packColor(colors[i]));
        if (hasNormals)
            vec3(b, normals[i]);
        if (hasUvs) {
            b.f32(uvs[i][0]);
            b.f32(uvs[i][1]);
        }
    }
    writeContinuedRecord(w, opcode::LocalVertexPool, body);
}

void writeMeshPrimitive(ByteWriter& w, PrimitiveType type, const std::vector<std::uint32_t>& indices)
{
    const bool narrow = indices.empty() || *std::max_element(indices.begin(), indices.end()) <= 0xffff;
    const std::uint16_t indexSize = narrow ? 2 : 4;
    std::vector<std::uint8_t> body;
    body.reserve(8 + indexSize * indices.size());
    ByteWriter b(body);
    b.i16(static_cast<std::int16_t>(type));
    b.u16(indexSize);
    b.u32(static_cast<std::uint32_t>(indices.size()));
    for (std::uint32_t i : indices) {
        if (narrow)
            b.u16(static_cast<std::uint16_t>(i));
        else
            b.u32(i);
    }
    writeContinuedRecord(w, opcode::MeshPrimitive, body);
}

}  // namespace cadlod::flt
