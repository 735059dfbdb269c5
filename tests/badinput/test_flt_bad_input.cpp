// Bad OpenFlight input: corrupt record lengths, wrong header, garbage, unbalanced Push/Pop,
// non-finite coordinates; each asserts the exact error naming the record offset. Every
// truncation, random corruption, zero-length records and out-of-palette faces are already
// covered by tests/openflight/test_reader.cpp (docs/reliability.md).
#include "byte_access.h"
#include "openflight/flt_reader.h"
#include "openflight/flt_writer.h"
#include "model_fixtures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

using namespace cadlod;
using namespace cadlod::flt;
using cadlod::test::Bytes;

namespace {

Bytes written(GeometryRecords geometry = GeometryRecords::Faces)
{
    WriteOptions options;
    options.geometry = geometry;
    Bytes bytes;
    std::string error;
    EXPECT_TRUE(writeOpenFlight(test::singleLevelModel(1), options, bytes, error)) << error;
    return bytes;
}

std::string readError(const Bytes& b)
{
    LodModel model;
    std::string error;
    EXPECT_FALSE(readOpenFlight(b.data(), b.size(), model, error)) << "read as a valid file";
    return error;
}

const test::RecordSpan& firstRecord(const std::vector<test::RecordSpan>& spans, std::uint16_t opcode)
{
    for (const auto& s : spans)
        if (s.opcode == opcode) return s;
    throw std::runtime_error("no record with opcode " + std::to_string(opcode));
}

void setLength(Bytes& b, std::size_t recordOffset, std::uint16_t length)
{
    b[recordOffset + 2] = std::uint8_t(length >> 8);
    b[recordOffset + 3] = std::uint8_t(length & 0xff);
}

void setU32(Bytes& b, std::size_t at, std::uint32_t v)
{
    for (int k = 0; k < 4; ++k) b[at + std::size_t(k)] = std::uint8_t(v >> (24 - 8 * k));
}

constexpr std::uint16_t kVertexPalette = 67, kPop = 11, kVertexWithNormal = 69, kLocalVertexPool = 85;

}  // namespace

TEST(BadFlt, RecordLengthZeroOrTwoIsShorterThanTheHeader)
{
    for (std::uint16_t length : {0, 2}) {
        Bytes b = written();
        const std::size_t at = firstRecord(test::recordSpans(b), kVertexPalette).offset;
        setLength(b, at, length);
        EXPECT_EQ(readError(b), "corrupt record at offset " + std::to_string(at) + " (opcode 67): length " +
                                    std::to_string(length) + " is shorter than the 4-byte record header");
    }
}

TEST(BadFlt, RecordLengthPastTheEndOfFile)
{
    Bytes b = written();
    const std::size_t at = firstRecord(test::recordSpans(b), kVertexPalette).offset;
    setLength(b, at, 0xfff0);
    EXPECT_EQ(readError(b), "truncated record at offset " + std::to_string(at) + " (opcode 67): 65520 bytes announced, " +
                                std::to_string(b.size() - at) + " left in the file");
}

TEST(BadFlt, FileCutInsideARecordNamesIt)
{
    Bytes b = written();
    const test::RecordSpan pop = test::recordSpans(b).back();
    ASSERT_EQ(pop.opcode, kPop);
    b.resize(b.size() - 2);
    EXPECT_EQ(readError(b), "truncated file: 2 byte(s) left at offset " + std::to_string(pop.offset) +
                                ", a record header needs 4");
}

TEST(BadFlt, WrongHeaderOpcode)
{
    Bytes b = written();
    b[1] = 2;  // a Group record first
    EXPECT_EQ(readError(b), "not an OpenFlight file: the first record (offset 0) has opcode 2, expected a Header (1)");
}

TEST(BadFlt, BinaryGarbage)
{
    Bytes garbage(300);
    for (std::size_t i = 0; i < garbage.size(); ++i) garbage[i] = std::uint8_t(i * 131 + 7);
    EXPECT_EQ(readError(garbage), "truncated record at offset 0 (opcode 1930): 3472 bytes announced, 300 left in the file");
}

TEST(BadFlt, UnbalancedPushPop)
{
    const Bytes b = written();
    Bytes extraPop = b;
    extraPop.insert(extraPop.end(), {0, 11, 0, 4});
    EXPECT_EQ(readError(extraPop), "unbalanced hierarchy: Pop record at offset " + std::to_string(b.size()) + " without a Push");
    Bytes missingPop = b;
    missingPop.resize(missingPop.size() - 4);
    EXPECT_EQ(readError(missingPop), "unbalanced hierarchy: 1 Push record(s) without a Pop at the end of the file "
                                     "(offset " + std::to_string(missingPop.size()) + ")");
}

// Regression: NaN coordinates used to reach the model (a silently wrong mesh).
TEST(BadFlt, NonFiniteVertexSkipsItsFaces)
{
    for (auto geometry : {GeometryRecords::Faces, GeometryRecords::Meshes}) {
        Bytes b = written(geometry);
        const auto spans = test::recordSpans(b);
        std::size_t xAt = 0;
        if (geometry == GeometryRecords::Faces) xAt = firstRecord(spans, kVertexWithNormal).offset + 8;
        else xAt = firstRecord(spans, 85).offset + 12;  // Local Vertex Pool: first vertex
        const double nan = std::numeric_limits<double>::quiet_NaN();
        std::uint64_t bits;
        std::memcpy(&bits, &nan, 8);
        for (int k = 0; k < 8; ++k) b[xAt + std::size_t(k)] = std::uint8_t(bits >> (56 - 8 * k));
        LodModel model;
        std::string error;
        ReadStats stats;
        ASSERT_TRUE(readOpenFlight(b.data(), b.size(), model, error, &stats)) << error;
        EXPECT_GT(stats.skippedFaces, 0u);
        EXPECT_EQ(model.triangleCount(), 2u);  // of 4: two use the first vertex
        for (const Level& level : model.levels)
            for (const Part& part : level.parts)
                for (const Vec3d& p : part.positions)
                    EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
    }
}

// Regression (fuzz_flt_reader slow units): a Local Vertex Pool whose mask names no attribute
// the reader knows takes 0 bytes a vertex, so its count was never checked against the record
// and 11-16 million vertices (0.3-0.9 GB) were allocated from an 11 KB file.
TEST(BadFlt, VertexPoolWithoutKnownAttributesIsAnError)
{
    for (std::uint32_t mask : {0x00000000u, 0x00002e00u}) {
        Bytes b = written(GeometryRecords::Meshes);
        const std::size_t at = firstRecord(test::recordSpans(b), kLocalVertexPool).offset;
        setU32(b, at + 4, 0x00aaaaaau);  // vertex count
        setU32(b, at + 8, mask);
        char maskText[11];
        std::snprintf(maskText, sizeof maskText, "0x%08x", mask);
        EXPECT_EQ(readError(b), "Local Vertex Pool at offset " + std::to_string(at) +
                                    ": 11184810 vertices announced with no known attribute in the mask " + maskText);
    }
}

TEST(BadFlt, VertexPoolCountBeyondItsRecordIsAnError)
{
    Bytes b = written(GeometryRecords::Meshes);
    const std::size_t at = firstRecord(test::recordSpans(b), kLocalVertexPool).offset;
    const std::uint32_t written = std::uint32_t(b[at + 4]) << 24 | std::uint32_t(b[at + 5]) << 16 |
                                  std::uint32_t(b[at + 6]) << 8 | b[at + 7];
    ASSERT_GT(written, 0u);
    setU32(b, at + 4, 0x00aaaaaau);
    EXPECT_EQ(readError(b), "Local Vertex Pool at offset " + std::to_string(at) +
                                ": 11184810 vertices announced, the record holds " + std::to_string(written));
}

// Found by fuzzing: a Long ID record with no body read its name through a null pointer
// (UBSan). An empty Long ID now leaves the Object's own name.
TEST(BadFlt, EmptyLongIdKeepsTheObjectName)
{
    constexpr std::uint16_t kObject = 4, kLongId = 33;
    const Bytes plain = written();
    LodModel before;
    std::string error;
    ASSERT_TRUE(readOpenFlight(plain.data(), plain.size(), before, error)) << error;
    ASSERT_FALSE(before.levels.empty());
    ASSERT_FALSE(before.levels[0].parts.empty());

    // After the Object and after the Long ID the writer may have put behind it.
    const std::vector<test::RecordSpan> spans = test::recordSpans(plain);
    std::size_t k = 0;
    while (spans[k].opcode != kObject)
        ++k;
    if (k + 1 < spans.size() && spans[k + 1].opcode == kLongId)
        ++k;
    Bytes b = plain;
    const Bytes emptyLongId = {0, std::uint8_t(kLongId), 0, 4};
    b.insert(b.begin() + std::ptrdiff_t(spans[k].offset + spans[k].length), emptyLongId.begin(), emptyLongId.end());
    LodModel after;
    ASSERT_TRUE(readOpenFlight(b.data(), b.size(), after, error)) << error;
    ASSERT_FALSE(after.levels.empty());
    ASSERT_FALSE(after.levels[0].parts.empty());
    EXPECT_FALSE(after.levels[0].parts[0].name.empty());
    EXPECT_EQ(after.levels[0].parts[0].name, before.levels[0].parts[0].name);
}
