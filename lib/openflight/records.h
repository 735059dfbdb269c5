// OpenFlight record writers, one function per record type (design.md §7). Every record
// is big-endian and a multiple of 4 bytes long.
#pragma once

#include "openflight/byte_writer.h"
#include "openflight/lod_model.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cadlod::flt {

namespace opcode {
constexpr std::uint16_t Header = 1, Group = 2, Object = 4, Face = 5, Push = 10, Pop = 11,
                        Continuation = 23, ColorPalette = 32, LongId = 33, VertexPalette = 67,
                        VertexColor = 68, Matrix = 49, InstanceReference = 61, InstanceDefinition = 62, VertexNormal = 69, VertexNormalUv = 70,
                        VertexColorUv = 71, VertexList = 72, Lod = 73, Mesh = 84,
                        LocalVertexPool = 85, MeshPrimitive = 86, Material = 113;
}

// Whether `op` is a primary record the reader does not interpret (a degree-of-freedom, a
// light, an instance, a switch...): it still opens a Push level of its own.
inline bool isPrimaryRecord(std::uint16_t op)
{
    switch (op) {
    case 14: case 60: case 61: case 62: case 63: case 64: case 90: case 91: case 92:
    case 94: case 95: case 96: case 98: case 101: case 111: case 130:
        return true;
    default:
        return false;
    }
}

namespace size {
constexpr std::size_t Header = 324, ColorPalette = 4228, Material = 84, Group = 44, Object = 28, Matrix = 68,
                      Instance = 8,
                      Lod = 80, Face = 80, Mesh = 84, VertexPalette = 8, VertexColor = 40,
                      VertexNormal = 56, VertexNormalUv = 64, VertexColorUv = 48;
// The largest record length that is a multiple of 4.
constexpr std::size_t MaxRecord = 65532;
constexpr std::size_t MaxVertexListEntries = (MaxRecord - 4) / 4;  // 16382
}  // namespace size

constexpr std::int32_t kFormatRevision = 1610;
constexpr std::uint32_t kHeaderSaveNormals = 0x80000000u;
constexpr std::uint32_t kFacePackedColor = 0x10000000u;
constexpr std::uint32_t kFaceNoAltColor = 0x20000000u;
constexpr std::uint16_t kVertexNoColor = 0x2000;
constexpr std::uint16_t kVertexPackedColor = 0x1000;
constexpr std::uint32_t kPoolPosition = 0x80000000u, kPoolRgba = 0x20000000u, kPoolNormal = 0x10000000u,
                        kPoolBaseUv = 0x08000000u;

enum class DrawType : std::uint8_t { SingleSided = 0, TwoSided = 1 };
enum class LightMode : std::uint8_t { FaceColor = 0, VertexColor = 1, FaceColorLit = 2, VertexColorLit = 3 };
enum class PrimitiveType : std::int16_t { TriangleStrip = 1, TriangleFan = 2, QuadStrip = 3, IndexedPolygon = 4 };

// The 8-byte ID field holds 7 characters; longer names also get a Long ID record.
std::string shortId(const std::string& name);
bool needsLongId(const std::string& name);

struct HeaderFields {
    std::string id = "db";
    Units units = Units::Meters;
    bool saveNormals = true;
};

// Appearance shared by Face and Mesh records.
struct Appearance {
    DrawType drawType = DrawType::SingleSided;
    LightMode lightMode = LightMode::FaceColorLit;
    Rgba color{0.8f, 0.8f, 0.8f, 1.0f};
    std::int16_t materialIndex = 0;
};

struct MaterialFields {
    std::int32_t index = 0;
    std::string name = "default";
    Vec3f ambient{0.2f, 0.2f, 0.2f}, diffuse{1, 1, 1}, specular{0, 0, 0}, emissive{0, 0, 0};
    float shininess = 0.0f, alpha = 1.0f;
};

// Packed colour as OpenFlight stores it: bytes a, b, g, r.
std::uint32_t packColor(const Rgba& c);
Rgba unpackColor(std::uint32_t abgr);

void writeHeader(ByteWriter& w, const HeaderFields& h);
void writeColorPalette(ByteWriter& w);
void writeMaterial(ByteWriter& w, const MaterialFields& m);
void writeVertexPalette(ByteWriter& w, std::uint32_t paletteBytes);  // header + all vertex records
// Vertex record for one vertex: 68/69/70/71 depending on the attributes given.
void writeVertex(ByteWriter& w, const Vec3d& p, const Vec3f* normal, const Vec2f* uv, const Rgba* color = nullptr);
std::size_t vertexRecordSize(bool hasNormal, bool hasUv);
void writeGroup(ByteWriter& w, const std::string& name);
void writeLod(ByteWriter& w, const std::string& name, double switchIn, double switchOut, const Vec3d& center);
void writeObject(ByteWriter& w, const std::string& name);
// Ancillary to the record before it. `columns` maps column vectors (p' = M p); OpenFlight
// stores the transpose, for row vectors, in float32.
void writeMatrix(ByteWriter& w, const Mat4d& columns);
// Instance numbers are 16-bit; some readers take them as signed.
constexpr int kMaxInstanceNumber = 32767;
void writeInstanceDefinition(ByteWriter& w, int number);
void writeInstanceReference(ByteWriter& w, int number);
void writeFace(ByteWriter& w, const Appearance& a);
void writeMesh(ByteWriter& w, const Appearance& a);
// Offsets from the start of the Vertex Palette record; split over as many records as needed.
void writeVertexList(ByteWriter& w, const std::vector<std::uint32_t>& offsets);
void writeLongId(ByteWriter& w, const std::string& name);
void writeLongIdIfNeeded(ByteWriter& w, const std::string& name);
void writePush(ByteWriter& w);
void writePop(ByteWriter& w);
// Variable-length records: longer than one record, they go on in Continuation records.
void writeLocalVertexPool(ByteWriter& w, const std::vector<Vec3d>& positions,
                          const std::vector<Vec3f>& normals, const std::vector<Vec2f>& uvs,
                          const std::vector<Rgba>& colors = {});
// 16-bit indices when every index fits, else 32-bit.
void writeMeshPrimitive(ByteWriter& w, PrimitiveType type, const std::vector<std::uint32_t>& indices);
// Body (without the 4-byte header) as `op` plus Continuation records; pads the last one to 4.
void writeContinuedRecord(ByteWriter& w, std::uint16_t op, const std::vector<std::uint8_t>& body);

}  // namespace cadlod::flt
