// Bad VRML input: each case asserts the exact error (file unreadable) or warning (file read,
// the bad part skipped) and that nothing crashes. Cases already pinned by tests/vrml are
// listed in docs/reliability.md instead of repeated here.
#include "vrml/importer.h"
#include "vrml/source_text.h"
#include "gzip_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <string>

using namespace cadlod::vrml;
namespace fs = std::filesystem;

namespace {

const std::string kHeader = "#VRML V2.0 utf8\n";
const std::string kNotVrml =
    "bad.wrl:1:1: not a VRML file (expected a '#VRML V2.0 utf8' or '#VRML V1.0 ascii' header)";

ImportResult import(const std::string& text, const ImportOptions& options = {})
{
    return importVrmlText(text, "bad.wrl", options);
}

// The only warning of the import, as "kind|where|message".
std::string onlyWarning(const ImportResult& r)
{
    if (r.scene.diagnostics.kept().size() != 1) return "expected one warning, got " +
                                                       std::to_string(r.scene.diagnostics.kept().size());
    const Diagnostic& d = r.scene.diagnostics.kept()[0];
    return d.kind + "|" + d.where + "|" + d.message;
}

std::string warning(const ImportResult& r, size_t i)
{
    const Diagnostic& d = r.scene.diagnostics.kept().at(i);
    return d.kind + "|" + d.where + "|" + d.message;
}

std::string faceSet(const std::string& points, const std::string& indices)
{
    return kHeader + "Shape { geometry IndexedFaceSet { coord Coordinate { point [ " + points +
           " ] } coordIndex [ " + indices + " ] } }\n";
}

bool allPointsFinite(const Scene& s)
{
    for (const Part& p : s.parts)
        for (const Vec3f& v : p.positions)
            if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) return false;
    return true;
}

}  // namespace

TEST(BadVrml, TruncatedTextKeepsWhatWasReadAndSaysWhere)
{
    const ImportResult r = import(kHeader + "Shape { geometry Box {} }\n"
                                            "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene.triangleCount(), 12u);
    EXPECT_EQ(onlyWarning(r), "syntax error|bad.wrl:3:72|unexpected end of file (truncated?) in the value of point; "
                              "the rest of the file is ignored");
}

TEST(BadVrml, TruncatedGzipIsAnError)
{
    std::string gz = cadlod::test::gzipText(kHeader + "Shape { geometry Box {} }\n" + std::string(5000, '#'));
    gz.resize(gz.size() / 2);
    const ImportResult r = importVrmlText(gz, "cut.wrz");
    const std::string prefix = "cut.wrz: truncated gzip file (stream ends after ";
    EXPECT_EQ(r.error.substr(0, prefix.size()), prefix) << r.error;
    EXPECT_EQ(r.error.substr(r.error.size() - 16), " inflated bytes)") << r.error;
}

TEST(BadVrml, BinaryGarbageIsNotAVrmlFile)
{
    std::string garbage;
    for (int i = 0; i < 4096; ++i) garbage.push_back(char((i * 131 + 7) & 0xff));
    EXPECT_EQ(import(garbage).error, kNotVrml);
    EXPECT_EQ(import(std::string("\0\0\0\0", 4)).error, kNotVrml);
}

TEST(BadVrml, WrongHeaderIsNotAVrmlFile)
{
    EXPECT_EQ(import("#VRML V3.0 utf8\nShape { geometry Box {} }\n").error, kNotVrml);
    EXPECT_EQ(import("solid cube\nfacet normal 0 0 1\n").error, kNotVrml);
    EXPECT_EQ(import("<?xml version=\"1.0\"?>\n<X3D/>\n").error, kNotVrml);
}

TEST(BadVrml, ExtraClosingBraceStopsWithLocationKeepingEarlierShapes)
{
    const ImportResult r =
        import(kHeader + "Group { children [ Shape { geometry Box {} } ] } }\nShape { geometry Box {} }\n");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene.triangleCount(), 12u);
    EXPECT_EQ(onlyWarning(r), "syntax error|bad.wrl:2:50|expected a node, found '}'; the rest of the file is ignored");
}

TEST(BadVrml, MissingClosingBracketStopsWithLocation)
{
    const ImportResult r = import(kHeader + "Group { children [ Shape { geometry Box {} } }\n");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(onlyWarning(r),
              "syntax error|bad.wrl:2:46|unexpected '}' in the value of children; the rest of the file is ignored");
}

TEST(BadVrml, IndicesOutOfRangeAndNegativeSkipTheirFaces)
{
    const ImportResult r = import(faceSet("0 0 0, 1 0 0, 0 1 0", "0 1 2 -1 0 1 99 -1 0 -5 2 -1"));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene.triangleCount(), 1u);
    EXPECT_EQ(r.scene.stats.skippedFaces, 2u);
    ASSERT_EQ(r.scene.diagnostics.kept().size(), 2u);
    EXPECT_EQ(warning(r, 0), "bad index|bad.wrl:2:18|face 1 skipped: coordIndex[6] = 99 out of range");
    EXPECT_EQ(warning(r, 1), "bad index|bad.wrl:2:18|face 2 skipped: coordIndex[9] = -5 out of range");
}

TEST(BadVrml, HugeIndexIsOutOfRangeNotAnOverflow)
{
    const ImportResult r = import(faceSet("0 0 0, 1 0 0, 0 1 0", "0 1 99999999999 -1"));
    EXPECT_EQ(r.scene.triangleCount(), 0u);
    EXPECT_EQ(onlyWarning(r), "bad index|bad.wrl:2:18|face 0 skipped: coordIndex[2] = -2147483648 out of range");
}

// Regression: "nan"/"inf" words used to be dropped from the point list, shifting every
// later coordinate (a silently wrong mesh).
TEST(BadVrml, NanAndInfWordsKeepTheirPlaceAndSkipTheirFaces)
{
    const ImportResult r = import(faceSet("0 0 0, 1 0 0, 0 1 0, nan 0 0, 0 -inf 0, 1 1 0",
                                          "0 1 2 -1 3 1 2 -1 0 4 2 -1 1 5 2 -1"));
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene.triangleCount(), 2u);
    EXPECT_EQ(r.scene.stats.skippedFaces, 2u);
    EXPECT_TRUE(allPointsFinite(r.scene));
    ASSERT_EQ(r.scene.diagnostics.kept().size(), 4u);
    EXPECT_EQ(warning(r, 0), "bad number|bad.wrl:2:83|'nan' in the value of point is not a finite number");
    EXPECT_EQ(warning(r, 1), "bad number|bad.wrl:2:94|'-inf' in the value of point is not a finite number");
    EXPECT_EQ(warning(r, 2), "bad coordinate|bad.wrl:2:18|face 1 skipped: point 3 is NaN, infinite or beyond float range");
    EXPECT_EQ(warning(r, 3), "bad coordinate|bad.wrl:2:18|face 2 skipped: point 4 is NaN, infinite or beyond float range");
}

// Regression: numbers beyond float range used to repeat the previous value silently.
TEST(BadVrml, NumbersBeyondFloatRangeAreRefusedAndTinyOnesAreZero)
{
    const ImportResult r = import(faceSet("0 0 0, 1 0 1e-50, 0 1 0, 1e39 0 0", "0 1 2 -1 3 1 2 -1"));
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.scene.triangleCount(), 1u);
    EXPECT_EQ(r.scene.parts.at(0).positions.at(1)[2], 0.0f);
    EXPECT_EQ(onlyWarning(r), "bad coordinate|bad.wrl:2:18|face 1 skipped: point 3 is NaN, infinite or beyond float range");
}

TEST(BadVrml, TransformOverflowingFloatSkipsTheFaces)
{
    const ImportResult r = import(kHeader + "Transform { scale 1e30 1e30 1e30 children Shape { geometry "
                                            "IndexedFaceSet { coord Coordinate { point [ 0 0 0, 1e20 0 0, 0 1 0 ] } "
                                            "coordIndex [ 0 1 2 ] } } }\n");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene.triangleCount(), 0u);
    EXPECT_TRUE(allPointsFinite(r.scene));
    EXPECT_EQ(r.scene.stats.skippedFaces, 1u);
}

TEST(BadVrml, MillionDeepGroupsStopAtTheNestingLimit)
{
    std::string text = kHeader;
    for (int i = 0; i < 1000000; ++i) text += "Group { children [ ";
    const ImportResult r = import(text);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(onlyWarning(r), "syntax error|bad.wrl:2:7601|nesting deeper than 400 levels; the rest of the file is ignored");
}

TEST(BadVrml, MillionDeepVrml1SeparatorsStopAtTheNestingLimit)
{
    std::string text = "#VRML V1.0 ascii\n";
    for (int i = 0; i < 1000000; ++i) text += "Separator { ";
    const ImportResult r = import(text);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(onlyWarning(r), "syntax error|bad.wrl:2:4801|nesting deeper than 400 levels; the rest of the file is ignored");
}

TEST(BadVrml, MillionDeepProtoBodiesStopAtTheNestingLimit)
{
    std::string text = kHeader;
    for (int i = 0; i < 1000000; ++i) text += "PROTO P [] { ";
    const ImportResult r = import(text);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(onlyWarning(r), "syntax error|bad.wrl:2:5212|nesting deeper than 400 levels; the rest of the file is ignored");
}

TEST(BadVrml, MillionDeepBracketsAreASyntaxError)
{
    std::string text = kHeader + "Shape { geometry IndexedFaceSet { coordIndex ";
    for (int i = 0; i < 1000000; ++i) text += "[ ";
    const ImportResult r = import(text);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(onlyWarning(r),
              "syntax error|bad.wrl:2:48|unexpected '[' in the value of coordIndex; the rest of the file is ignored");
}

TEST(BadVrml, SelfReferencingUseAndProtoAreNotFollowed)
{
    const ImportResult use = import(kHeader + "DEF G Group { children [ Shape { geometry Box {} } USE G ] }\n");
    EXPECT_EQ(use.scene.triangleCount(), 12u);
    EXPECT_EQ(onlyWarning(use), "undefined USE|bad.wrl:2:56|USE G has no DEF before it");
    const ImportResult proto = import(kHeader + "PROTO A [] { A {} }\nA {}\n");
    EXPECT_EQ(proto.scene.triangleCount(), 0u);
    EXPECT_EQ(onlyWarning(proto), "unknown node|bad.wrl:3:1|node A ignored");
}

TEST(BadVrml, InlineOfItselfIsSkippedWithAWarning)
{
    const fs::path dir = fs::temp_directory_path() / ("cadlod_badinput_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "self.wrl") << kHeader << "Shape { geometry Box {} }\nInline { url \"self.wrl\" }\n";
    const ImportResult r = importVrmlFile((dir / "self.wrl").string());
    fs::remove_all(dir);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene.triangleCount(), 12u);
    ASSERT_EQ(r.scene.diagnostics.kept().size(), 1u);
    EXPECT_EQ(r.scene.diagnostics.kept()[0].kind, "recursive inline");
    EXPECT_EQ(r.scene.diagnostics.kept()[0].message, "Inline self.wrl includes itself; skipped");
}

TEST(BadVrml, GzipBombIsRefusedAtTheBound)
{
    ImportOptions options;
    options.maxInflatedBytes = 1 << 20;
    const std::string bomb = cadlod::test::gzipText(kHeader + std::string(64 << 20, ' '));
    ASSERT_LT(bomb.size(), 128u * 1024u);
    const ImportResult r = importVrmlText(bomb, "bomb.wrz", options);
    EXPECT_EQ(r.error, "bomb.wrz: gzip data inflates beyond 1 MB; refusing (gzip bomb?)");
}

// With the default bound a bomb is refused at kMaxInflationRatio times its compressed
// size, not at the absolute 8 GiB: memory follows the file size.
TEST(BadVrml, GzipBombIsRefusedAtItsRatioWithTheDefaultBound)
{
    const std::string bomb = cadlod::test::gzipText(kHeader + std::string(80 << 20, ' '));
    const std::size_t bound = bomb.size() * kMaxInflationRatio;
    ASSERT_GT(bound, kInflationFloorBytes);  // the ratio binds, not the floor
    const ImportResult r = importVrmlText(bomb, "bomb.wrz");
    EXPECT_EQ(r.error, "bomb.wrz: gzip data inflates beyond " + std::to_string(bound >> 20) + " MB from " +
                           std::to_string(bomb.size()) +
                           " compressed bytes (at most 256 times the compressed size, or 16 MB); refusing (gzip bomb?)");
}

TEST(BadVrml, SmallGzipBombIsRefusedAtTheFloor)
{
    const std::string bomb = cadlod::test::gzipText(kHeader + std::string(20 << 20, ' '));
    ASSERT_LT(bomb.size() * kMaxInflationRatio, kInflationFloorBytes);
    const ImportResult r = importVrmlText(bomb, "small.wrz");
    EXPECT_EQ(r.error, "small.wrz: gzip data inflates beyond 16 MB from " + std::to_string(bomb.size()) +
                           " compressed bytes (at most 256 times the compressed size, or 16 MB); refusing (gzip bomb?)");
}

TEST(BadVrml, InflatedSizeBoundIsRelativeWithAFloorAndTheAbsoluteCap)
{
    const std::size_t MiB = std::size_t(1) << 20;
    EXPECT_EQ(inflatedSizeBound(0), 16 * MiB);
    EXPECT_EQ(inflatedSizeBound(MiB / 64), 16 * MiB);  // 256 x 16 KiB = 4 MiB: the floor
    EXPECT_EQ(inflatedSizeBound(MiB), 256 * MiB);
    EXPECT_EQ(inflatedSizeBound(64 * MiB), kDefaultMaxInflatedBytes);  // 16 GiB relative: capped at 8 GiB
    EXPECT_EQ(inflatedSizeBound(SIZE_MAX / 2), kDefaultMaxInflatedBytes);  // no overflow
    EXPECT_EQ(inflatedSizeBound(MiB, MiB), MiB);  // an explicit cap below the floor wins
}

TEST(BadVrml, NonUtf8NamesAreKeptByteForByte)
{
    const ImportResult r = import(kHeader + "DEF Bad\xff\xfe\x80Name Shape { geometry Box {} }\n");
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.scene.parts.size(), 1u);
    EXPECT_EQ(r.scene.parts[0].name, "Bad\xff\xfe\x80Name");
    EXPECT_EQ(r.scene.diagnostics.total(), 0);
}
