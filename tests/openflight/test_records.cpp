// Byte layout of every record the writer emits, against design.md §7 and the
// OpenFlight 16.x specification.
#include "byte_access.h"
#include "openflight/flt_writer.h"
#include "model_fixtures.h"
#include "openflight/records.h"

#include <gtest/gtest.h>

using namespace cadlod::flt;
using namespace cadlod::test;

namespace {

template <class F>
Bytes written(F write)
{
    Bytes b;
    ByteWriter w(b);
    write(w);
    return b;
}

}  // namespace

TEST(Records, HeaderLayout)
{
    HeaderFields h;
    h.id = "partdb";
    h.units = Units::Inches;
    const Bytes b = written([&](ByteWriter& w) { writeHeader(w, h); });
    ASSERT_EQ(b.size(), 324u);
    EXPECT_EQ(be16(b, 0), 1);
    EXPECT_EQ(be16(b, 2), 324);
    EXPECT_EQ(cstr(b, 4, 8), "partdb");
    EXPECT_EQ(bei32(b, 12), 1610);
    EXPECT_EQ(bei16(b, 60), 1);  // unit multiplier
    EXPECT_EQ(b[62], 5);         // inches
    EXPECT_EQ(be32(b, 64) & 0x80000000u, 0x80000000u);  // save vertex normals
    EXPECT_EQ(bei16(b, 126), 1);  // double-precision vertices
    EXPECT_EQ(bei32(b, 128), 100);  // OpenFlight origin
}

TEST(Records, ColorPaletteAndMaterialSizes)
{
    const Bytes palette = written([](ByteWriter& w) { writeColorPalette(w); });
    ASSERT_EQ(palette.size(), 4228u);
    EXPECT_EQ(be16(palette, 0), 32);
    EXPECT_EQ(be16(palette, 2), 4228);

    MaterialFields m;
    m.index = 3;
    m.diffuse = {0.5f, 0.25f, 1.0f};
    m.alpha = 0.75f;
    const Bytes mat = written([&](ByteWriter& w) { writeMaterial(w, m); });
    ASSERT_EQ(mat.size(), 84u);
    EXPECT_EQ(be16(mat, 0), 113);
    EXPECT_EQ(bei32(mat, 4), 3);
    EXPECT_EQ(cstr(mat, 8, 12), "default");
    EXPECT_FLOAT_EQ(bef32(mat, 36), 0.5f);  // diffuse
    EXPECT_FLOAT_EQ(bef32(mat, 40), 0.25f);
    EXPECT_FLOAT_EQ(bef32(mat, 76), 0.75f);  // alpha
}

TEST(Records, GroupObjectLodLayouts)
{
    const Bytes group = written([](ByteWriter& w) { writeGroup(w, "root"); });
    ASSERT_EQ(group.size(), 44u);
    EXPECT_EQ(be16(group, 0), 2);
    EXPECT_EQ(cstr(group, 4, 8), "root");

    const Bytes object = written([](ByteWriter& w) { writeObject(w, "a_very_long_name"); });
    ASSERT_EQ(object.size(), 28u);
    EXPECT_EQ(be16(object, 0), 4);
    EXPECT_EQ(cstr(object, 4, 8), "a_very_");  // 7 characters + NUL
    EXPECT_EQ(object[11], 0);

    const Bytes lod = written([](ByteWriter& w) { writeLod(w, "l1", 250.0, 40.0, {1.5, -2.0, 3.25}); });
    ASSERT_EQ(lod.size(), 80u);
    EXPECT_EQ(be16(lod, 0), 73);
    EXPECT_EQ(be16(lod, 2), 80);
    EXPECT_DOUBLE_EQ(bef64(lod, 16), 250.0);  // switch-in: far
    EXPECT_DOUBLE_EQ(bef64(lod, 24), 40.0);   // switch-out: near
    EXPECT_EQ(be32(lod, 36), 0u);             // not "use previous slant range"
    EXPECT_DOUBLE_EQ(bef64(lod, 40), 1.5);
    EXPECT_DOUBLE_EQ(bef64(lod, 48), -2.0);
    EXPECT_DOUBLE_EQ(bef64(lod, 56), 3.25);
}

TEST(Records, FaceAndMeshLayouts)
{
    Appearance a;
    a.drawType = DrawType::TwoSided;
    a.color = {1.0f, 0.5f, 0.0f, 1.0f};
    const Bytes face = written([&](ByteWriter& w) { writeFace(w, a); });
    ASSERT_EQ(face.size(), 80u);
    EXPECT_EQ(be16(face, 0), 5);
    EXPECT_EQ(face[18], 1);                    // draw type two-sided
    EXPECT_EQ(bei16(face, 30), 0);             // material index
    EXPECT_EQ(be16(face, 40), 0);              // opaque
    EXPECT_TRUE(be32(face, 44) & 0x10000000u);  // packed color
    EXPECT_EQ(face[48], 2);                    // lit with face color
    EXPECT_EQ(be32(face, 56), 0xff0080ffu);    // a, b, g, r
    EXPECT_EQ(bei32(face, 68), -1);            // no color index

    a.color[3] = 0.5f;
    const Bytes mesh = written([&](ByteWriter& w) { writeMesh(w, a); });
    ASSERT_EQ(mesh.size(), 84u);
    EXPECT_EQ(be16(mesh, 0), 84);
    EXPECT_EQ(mesh[22], 1);
    EXPECT_NEAR(be16(mesh, 44), 32767.5, 1.0);  // transparency
    EXPECT_TRUE(be32(mesh, 48) & 0x10000000u);
    EXPECT_EQ(mesh[52], 2);
    EXPECT_EQ(be32(mesh, 60), 0x800080ffu);
}

TEST(Records, VertexLayouts)
{
    const Vec3d p{1.0, -2.0, 1e6 + 0.125};
    const Vec3f n{0.0f, 0.6f, 0.8f};
    const Vec2f uv{0.25f, 0.75f};
    const Bytes v69 = written([&](ByteWriter& w) { writeVertex(w, p, &n, nullptr); });
    ASSERT_EQ(v69.size(), 56u);
    EXPECT_EQ(be16(v69, 0), 69);
    EXPECT_DOUBLE_EQ(bef64(v69, 8), 1.0);
    EXPECT_DOUBLE_EQ(bef64(v69, 24), 1e6 + 0.125);
    EXPECT_FLOAT_EQ(bef32(v69, 36), 0.6f);

    const Bytes v70 = written([&](ByteWriter& w) { writeVertex(w, p, &n, &uv); });
    ASSERT_EQ(v70.size(), 64u);
    EXPECT_EQ(be16(v70, 0), 70);
    EXPECT_FLOAT_EQ(bef32(v70, 44), 0.25f);
    EXPECT_FLOAT_EQ(bef32(v70, 48), 0.75f);

    const Bytes v68 = written([&](ByteWriter& w) { writeVertex(w, p, nullptr, nullptr); });
    EXPECT_EQ(v68.size(), 40u);
    EXPECT_EQ(be16(v68, 0), 68);
}

TEST(Records, VertexListSplitsAtTheRecordLimit)
{
    std::vector<std::uint32_t> offsets(20000);
    for (std::size_t i = 0; i < offsets.size(); ++i)
        offsets[i] = std::uint32_t(8 + 56 * i);
    const Bytes b = written([&](ByteWriter& w) { writeVertexList(w, offsets); });
    const auto spans = recordSpans(b);
    ASSERT_EQ(spans.size(), 2u);
    EXPECT_EQ(spans[0].opcode, 72);
    EXPECT_EQ(spans[0].length, 4u + 4u * 16382u);
    EXPECT_EQ(spans[1].length, 4u + 4u * (20000u - 16382u));
    EXPECT_EQ(be32(b, 4), 8u);
    EXPECT_EQ(be32(b, spans[1].offset + 4), 8u + 56u * 16382u);  // continues where the first stopped
    EXPECT_EQ(b.size(), 4u * 20000u + 8u);
}

TEST(Records, LongIdIsNulTerminatedAndPadded)
{
    for (const std::string name : {"abcdefgh", "abcdefghijk", "abcdefghijkl"}) {
        const Bytes b = written([&](ByteWriter& w) { writeLongId(w, name); });
        EXPECT_EQ(be16(b, 0), 33);
        EXPECT_EQ(b.size() % 4, 0u);
        EXPECT_EQ(be16(b, 2), b.size());
        EXPECT_GE(b.size(), 4 + name.size() + 1);
        EXPECT_EQ(cstr(b, 4, b.size() - 4), name);
    }
    EXPECT_FALSE(needsLongId("1234567"));
    EXPECT_TRUE(needsLongId("12345678"));
}

TEST(Records, LongRecordsGoOnInContinuationRecords)
{
    std::vector<std::uint8_t> body(150001);
    for (std::size_t i = 0; i < body.size(); ++i)
        body[i] = std::uint8_t(i * 7);
    const Bytes b = written([&](ByteWriter& w) { writeContinuedRecord(w, 85, body); });
    const auto spans = recordSpans(b);
    ASSERT_EQ(spans.size(), 3u);
    EXPECT_EQ(spans[0].opcode, 85);
    EXPECT_EQ(spans[1].opcode, 23);
    EXPECT_EQ(spans[2].opcode, 23);
    Bytes glued;
    for (const auto& s : spans) {
        EXPECT_EQ(s.length % 4, 0u);
        EXPECT_LE(s.length, 65532u);
        glued.insert(glued.end(), b.begin() + long(s.offset + 4), b.begin() + long(s.offset + s.length));
    }
    ASSERT_GE(glued.size(), body.size());
    EXPECT_TRUE(std::equal(body.begin(), body.end(), glued.begin()));
}

TEST(Records, LocalVertexPoolAndMeshPrimitive)
{
    const std::vector<Vec3d> pos{{1, 2, 3}, {4, 5, 6}};
    const std::vector<Vec3f> nrm{{0, 0, 1}, {0, 1, 0}};
    const Bytes pool = written([&](ByteWriter& w) { writeLocalVertexPool(w, pos, nrm, {}); });
    EXPECT_EQ(be16(pool, 0), 85);
    EXPECT_EQ(be16(pool, 2), 12u + 2u * 36u);
    EXPECT_EQ(be32(pool, 4), 2u);
    EXPECT_EQ(be32(pool, 8), 0x90000000u);  // position + normal
    EXPECT_DOUBLE_EQ(bef64(pool, 12 + 36), 4.0);
    EXPECT_FLOAT_EQ(bef32(pool, 12 + 36 + 24 + 4), 1.0f);

    const Bytes prim = written([&](ByteWriter& w) { writeMeshPrimitive(w, PrimitiveType::TriangleStrip, {0, 1, 2, 2, 3}); });
    EXPECT_EQ(be16(prim, 0), 86);
    EXPECT_EQ(be16(prim, 2), 12u + 12u);  // 5 16-bit indices, padded to 4 bytes
    EXPECT_EQ(bei16(prim, 4), 1);
    EXPECT_EQ(be16(prim, 6), 2);
    EXPECT_EQ(be32(prim, 8), 5u);
    EXPECT_EQ(be16(prim, 12 + 4 * 2), 3u);
    EXPECT_EQ(be16(prim, 12 + 5 * 2), 0u);  // padding

    const Bytes wide = written([&](ByteWriter& w) { writeMeshPrimitive(w, PrimitiveType::TriangleFan, {0, 70000, 1}); });
    EXPECT_EQ(be16(wide, 2), 12u + 3u * 4u);
    EXPECT_EQ(be16(wide, 6), 4);
    EXPECT_EQ(be32(wide, 12 + 4), 70000u);
}

TEST(Records, PushPopAndPackedColors)
{
    const Bytes b = written([](ByteWriter& w) { writePush(w); writePop(w); });
    ASSERT_EQ(b.size(), 8u);
    EXPECT_EQ(be16(b, 0), 10);
    EXPECT_EQ(be16(b, 2), 4);
    EXPECT_EQ(be16(b, 4), 11);
    const Rgba c{0.2f, 0.4f, 0.6f, 1.0f};
    const Rgba back = unpackColor(packColor(c));
    for (int i = 0; i < 4; ++i)
        EXPECT_NEAR(back[i], c[i], 1.0 / 255.0);
}

// Whole files: records tile the file exactly, all multiples of 4, Push/Pop balanced,
// the expected record sequence.
TEST(WriterLayout, FilesAreWellFormedInBothGeometryModes)
{
    for (GeometryRecords mode : {GeometryRecords::Faces, GeometryRecords::Meshes}) {
        WriteOptions o;
        o.geometry = mode;
        Bytes b;
        std::string error;
        WriteStats stats;
        ASSERT_TRUE(writeOpenFlight(threeLevelModel(), o, b, error, &stats)) << error;
        const auto spans = recordSpans(b);
        std::size_t total = 0;
        int depth = 0, lods = 0, objects = 0, longIds = 0;
        for (const auto& s : spans) {
            EXPECT_EQ(s.length % 4, 0u) << "opcode " << s.opcode << " at " << s.offset;
            total += s.length;
            depth += s.opcode == 10 ? 1 : s.opcode == 11 ? -1 : 0;
            EXPECT_GE(depth, 0);
            lods += s.opcode == 73;
            objects += s.opcode == 4;
            longIds += s.opcode == 33;
        }
        EXPECT_EQ(total, b.size());
        EXPECT_EQ(depth, 0);
        EXPECT_EQ(spans[0].opcode, 1);
        EXPECT_EQ(spans[1].opcode, 32);
        EXPECT_EQ(spans[2].opcode, 113);
        EXPECT_EQ(lods, 3);
        EXPECT_EQ(objects, 6);
        EXPECT_EQ(longIds, 3 + 3);  // level names and the long part names
        EXPECT_EQ(stats.triangles, threeLevelModel().triangleCount());
        if (mode == GeometryRecords::Faces) {
            EXPECT_EQ(spans[3].opcode, 67);
            EXPECT_EQ(be32(b, spans[3].offset + 4), 8u + 56u * stats.vertices);
        }
    }
}

TEST(WriterLayout, RejectsBadIndices)
{
    cadlod::flt::LodModel m = singleLevelModel(2);
    m.levels[0].parts[1].triangles.push_back({0, 1, 999});
    Bytes b;
    std::string error;
    EXPECT_FALSE(writeOpenFlight(m, {}, b, error));
    EXPECT_NE(error.find("part 1"), std::string::npos) << error;
    EXPECT_NE(error.find("999"), std::string::npos) << error;
}

TEST(WriterLayout, ProgressRisesToOneHundred)
{
    for (GeometryRecords mode : {GeometryRecords::Faces, GeometryRecords::Meshes}) {
        std::vector<int> seen;
        WriteOptions o;
        o.geometry = mode;
        o.progress = [&seen](int percent) { seen.push_back(percent); };
        Bytes b;
        std::string error;
        ASSERT_TRUE(writeOpenFlight(threeLevelModel(), o, b, error)) << error;
        ASSERT_FALSE(seen.empty());
        EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
        EXPECT_EQ(seen.back(), 100);
    }
}
