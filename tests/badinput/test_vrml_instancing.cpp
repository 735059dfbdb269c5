// DEF/USE instancing amplification ("billion laughs"): a few hundred bytes of nested USEs
// describe 10^8 triangles and more. The importer counts a subtree's triangles before it
// expands it and stops with an error naming the USE that crosses the limit; legitimate
// assemblies with many instances still import in full.
#include "vrml/importer.h"
#include "vrml/parser.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace cadlod::vrml;
namespace fs = std::filesystem;

namespace {

// `DEF L0 <leaf>` then `DEF Li <group> { USE Li-1 x10 }` for i = 1..levels, one per line.
std::string nestedUseBomb(const std::string& header, const std::string& leaf, const std::string& groupOpen,
                          const std::string& groupClose, int levels)
{
    std::string text = header + "DEF L0 " + leaf + "\n";
    for (int i = 1; i <= levels; ++i) {
        text += "DEF L" + std::to_string(i) + " " + groupOpen;
        for (int k = 0; k < 10; ++k) text += " USE L" + std::to_string(i - 1);
        text += " " + groupClose + "\n";
    }
    return text;
}

std::string vrml97Bomb(int levels)
{
    return nestedUseBomb("#VRML V2.0 utf8\n", "Shape { geometry Box {} }", "Group { children [", "] }", levels);
}

// `PROTO P0 { Shape }` then `PROTO Pi { Group { Pi-1 {} x10 } }`, and one instance of the last.
std::string nestedProtoBomb(int levels)
{
    std::string text = "#VRML V2.0 utf8\nPROTO P0 [] { Shape { geometry Box {} } }\n";
    for (int i = 1; i <= levels; ++i) {
        text += "PROTO P" + std::to_string(i) + " [] { Group { children [ ";
        for (int k = 0; k < 10; ++k) text += "P" + std::to_string(i - 1) + " {} ";
        text += "] } }\n";
    }
    return text + "P" + std::to_string(levels) + " {}\n";
}

// A fan of `n` triangles around point 0.
std::string fanFaceSet(int n)
{
    std::string points, indices;
    for (int i = 0; i <= n + 1; ++i) points += std::to_string(i) + " " + std::to_string(i % 7) + " 0, ";
    for (int i = 1; i <= n; ++i) indices += "0 " + std::to_string(i) + " " + std::to_string(i + 1) + " -1 ";
    return "IndexedFaceSet { coord Coordinate { point [ " + points + "] } coordIndex [ " + indices + "] }";
}

ImportOptions limitOf(uint64_t triangles)
{
    ImportOptions o;
    o.maxTriangles = triangles;
    o.maxTrianglesPerInputByte = 0;
    return o;
}

}  // namespace

TEST(UseInstancing, SevenLevelBombStopsAtTheUseThatCrossesTheDefaultLimit)
{
    // 749 bytes; L0..L6 emit 13.3 M triangles, so the 4th USE L6 inside L7 (line 9) crosses 50 M.
    const std::string text = vrml97Bomb(7);
    ASSERT_EQ(text.size(), 749u);
    const ImportResult r = importVrmlText(text, "bomb.wrl");
    EXPECT_EQ(r.error, "bomb.wrl:9:48: USE L6 would make the scene exceed 50000000 triangles (instancing limit)");
    EXPECT_TRUE(r.scene.parts.empty());
    EXPECT_EQ(r.scene.stats.shapes, 0u);  // refused before anything was expanded
}

TEST(UseInstancing, TopLevelUsesAreCountedToo)
{
    std::string text = vrml97Bomb(6);  // 13.3 M triangles
    for (int k = 0; k < 4; ++k) text += "USE L6\n";  // each another 12 M
    const ImportResult r = importVrmlText(text, "top.wrl");
    EXPECT_EQ(r.error, "top.wrl:12:1: USE L6 would make the scene exceed 50000000 triangles (instancing limit)");
}

TEST(UseInstancing, Vrml1SeparatorBombStopsAtTheUse)
{
    const std::string text = nestedUseBomb("#VRML V1.0 ascii\n", "Separator { Cube {} }", "Separator {", "}", 7);
    const ImportResult r = importVrmlText(text, "bomb1.wrl");
    EXPECT_EQ(r.error, "bomb1.wrl:9:41: USE L6 would make the scene exceed 50000000 triangles (instancing limit)");
    EXPECT_EQ(r.scene.stats.shapes, 0u);
}

TEST(UseInstancing, ThousandInstancesOfAThousandTrianglePartImportInFull)
{
    std::string text = "#VRML V2.0 utf8\nDEF Bolt Shape { geometry " + fanFaceSet(1000) + " }\n";
    for (int i = 1; i < 1000; ++i)
        text += "Transform { translation " + std::to_string(i) + " 0 0 children USE Bolt }\n";
    const ImportResult r = importVrmlText(text, "assembly.wrl");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene.triangleCount(), 1000000u);
    EXPECT_EQ(r.scene.stats.meshTriangles, 1000000u);
}

TEST(UseInstancing, LowLimitNamesTheUseThatCrossesIt)
{
    const std::string text = "#VRML V2.0 utf8\nDEF Part Shape { geometry " + fanFaceSet(40) +
                             " }\nUSE Part\n  USE Part\n";
    EXPECT_TRUE(importVrmlText(text, "small.wrl", limitOf(120)).ok());
    const ImportResult r = importVrmlText(text, "small.wrl", limitOf(119));
    EXPECT_EQ(r.error, "small.wrl:4:3: USE Part would make the scene exceed 119 triangles (instancing limit)");
    EXPECT_TRUE(r.scene.parts.empty());
}

TEST(UseInstancing, LimitWithoutInstancingNamesTheShape)
{
    const std::string text = "#VRML V2.0 utf8\nGroup { children [\n Shape { geometry " + fanFaceSet(40) + " } ] }\n";
    const ImportResult r = importVrmlText(text, "plain.wrl", limitOf(39));
    EXPECT_EQ(r.error, "plain.wrl:3:2: Shape would make the scene exceed 39 triangles (triangle limit)");
}

TEST(UseInstancing, LimitGrowsWithTheInputSize)
{
    // The limit is max(10, 1 triangle per byte of input); each `USE Part` line adds 9 bytes
    // and 40 triangles, so the file pays for (base - 40) / 31 of them and not one more.
    std::string text = "#VRML V2.0 utf8\nDEF Part Shape { geometry " + fanFaceSet(40) + " }\n";
    const size_t uses = (text.size() - 40) / 31;
    for (size_t i = 0; i < uses; ++i) text += "USE Part\n";
    ImportOptions o;
    o.maxTriangles = 10;
    o.maxTrianglesPerInputByte = 1.0;
    const ImportResult r = importVrmlText(text, "relative.wrl", o);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene.triangleCount(), 40 * (uses + 1));
    text += "USE Part\n";
    const ImportResult over = importVrmlText(text, "relative.wrl", o);
    EXPECT_EQ(over.error, "relative.wrl:" + std::to_string(3 + uses) + ":1: USE Part would make the scene exceed " +
                              std::to_string(text.size()) + " triangles (instancing limit)");
}

TEST(UseInstancing, InlinedGeometryCountsTowardsTheLimit)
{
    const fs::path dir = fs::temp_directory_path() / ("cadlod_inline_budget_" + std::to_string(getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "part.wrl") << "#VRML V2.0 utf8\nShape { geometry " << fanFaceSet(40) << " }\n";
    std::ofstream(dir / "asm.wrl") << "#VRML V2.0 utf8\nInline { url \"part.wrl\" }\nInline { url \"part.wrl\" }\n"
                                   << "Shape { geometry " << fanFaceSet(40) << " }\n";
    const ImportResult fits = importVrmlFile((dir / "asm.wrl").string(), limitOf(120));
    EXPECT_TRUE(fits.ok()) << fits.error;
    const ImportResult inlineOver = importVrmlFile((dir / "asm.wrl").string(), limitOf(79));
    EXPECT_EQ(inlineOver.error,
              (dir / "part.wrl").string() + ":2:1: Shape would make the scene exceed 79 triangles (triangle limit)");
    const ImportResult lastShapeOver = importVrmlFile((dir / "asm.wrl").string(), limitOf(119));
    EXPECT_EQ(lastShapeOver.error,
              (dir / "asm.wrl").string() + ":4:1: Shape would make the scene exceed 119 triangles (triangle limit)");
    fs::remove_all(dir);
}

// PROTO instances are copied at parse time, so nested PROTOs multiply nodes before any
// USE budget could see them: the parser bounds the nodes copied in all.
TEST(ProtoInstancing, NestedProtoBombStopsAtTheInstanceThatCrossesTheCopyLimit)
{
    // Bodies copy 2, 21 and 211 nodes: 20 + 210 + 2110 are copied before the P3 instance.
    const std::string text = nestedProtoBomb(3);
    ParseOptions options;
    options.maxProtoCopies = 2340 + 2111;
    options.maxProtoCopiesPerInputByte = 0;
    Diagnostics diag;
    EXPECT_EQ(parseVrml(text, "p.wrl", diag, options).error, "");
    options.maxProtoCopies -= 1;
    const ParsedFile over = parseVrml(text, "p.wrl", diag, options);
    EXPECT_EQ(over.error,
              "p.wrl:6:1: PROTO P3 instance would make the PROTO copies exceed 4450 nodes (instancing limit)");
}

TEST(ProtoInstancing, CopyLimitGrowsWithTheInputSize)
{
    const std::string text = nestedProtoBomb(3);  // 4451 nodes copied
    ParseOptions options;
    options.maxProtoCopies = 10;
    options.maxProtoCopiesPerInputByte = 4451.0 / double(text.size());
    Diagnostics diag;
    EXPECT_EQ(parseVrml(text, "p.wrl", diag, options).error, "");
    options.maxProtoCopiesPerInputByte = 4450.0 / double(text.size());
    EXPECT_NE(parseVrml(text, "p.wrl", diag, options).error, "");
}

TEST(ProtoInstancing, SevenLevelProtoBombFailsWithTheDefaultLimit)
{
    const ImportResult r = importVrmlText(nestedProtoBomb(7), "proto.wrl");
    EXPECT_EQ(r.error, "proto.wrl:8:52: PROTO P5 instance would make the PROTO copies exceed 1000000 nodes "
                       "(instancing limit)");
    EXPECT_TRUE(r.scene.parts.empty());
}
