// File-level behaviour: gzip by magic bytes, gzip bombs and truncation, Inline
// resolution, recursion guard, missing files, EXTERNPROTO.
#include "gzip_text.h"
#include "vrml_test_util.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <unistd.h>

using namespace cadlod::vrml;
using namespace cadlod::vrml::test;
namespace fs = std::filesystem;

namespace {

fs::path tempDir(const std::string& name)
{
    const fs::path dir = fs::temp_directory_path() / ("cadlod_vrml_" + name + "_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir;
}

void write(const fs::path& p, const std::string& text)
{
    fs::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
}

const std::string kBox = "#VRML V2.0 utf8\nShape { geometry Box {} }\n";

}  // namespace

TEST(VrmlFiles, GzipIsRecognisedByMagicBytesWhateverTheName)
{
    const Scene s = load(cadlod::test::gzipText(kBox), {}, "plain-name.wrl");
    EXPECT_EQ(s.triangleCount(), 12u);
}

TEST(VrmlFiles, MissingFileFailsWithItsName)
{
    const ImportResult r = importVrmlFile("/nonexistent/dir/x.wrl");
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("/nonexistent/dir/x.wrl"), std::string::npos);
}

TEST(VrmlFiles, InlinesResolveRelativeToTheIncludingFileAndApplyTheTransform)
{
    const fs::path dir = tempDir("inline");
    write(dir / "asm.wrl", "#VRML V2.0 utf8\nDEF Wheel Transform { translation 10 0 0 children Inline { url \"parts/wheel.wrl\" } }\n"
                           "Inline { url [ \"missing.wrl\" ] }\n");
    write(dir / "parts/wheel.wrl", "#VRML V2.0 utf8\nInline { url \"sub/hub.wrl.gz\" }\n");
    std::ofstream(dir / "parts/sub/hub.wrl.gz", std::ios::binary) << "";
    write(dir / "parts/sub/hub.wrl.gz", cadlod::test::gzipText("#VRML V1.0 ascii\nCube {}\n"));  // VRML 1.0 inside VRML97
    const ImportResult r = importVrmlFile((dir / "asm.wrl").string());
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_EQ(r.scene.triangleCount(), 12u);
    EXPECT_TRUE(hasPoint(r.scene, 11, 1, 1));
    EXPECT_EQ(r.scene.parts.at(0).name, "Wheel");
    EXPECT_EQ(r.scene.stats.inlinesLoaded, 2u);
    EXPECT_EQ(r.scene.diagnostics.count("missing inline"), 1);
    fs::remove_all(dir);
}

TEST(VrmlFiles, RecursiveInlineIsCutWithAWarning)
{
    const fs::path dir = tempDir("recursion");
    write(dir / "a.wrl", "#VRML V2.0 utf8\nShape { geometry Box {} }\nInline { url \"b.wrl\" }\n");
    write(dir / "b.wrl", "#VRML V2.0 utf8\nTransform { translation 3 0 0 children Inline { url \"a.wrl\" } }\n");
    const ImportResult r = importVrmlFile((dir / "a.wrl").string());
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.scene.triangleCount(), 12u);
    EXPECT_EQ(r.scene.diagnostics.count("recursive inline"), 1);
    fs::remove_all(dir);
}

TEST(VrmlFiles, ExternProtoIsFetchedFromItsUrl)
{
    const fs::path dir = tempDir("externproto");
    write(dir / "lib.wrl", "#VRML V2.0 utf8\nPROTO Plate [ field SFVec3f size 1 1 1 ] { Shape { geometry Box { size IS size } } }\n");
    write(dir / "main.wrl", "#VRML V2.0 utf8\nEXTERNPROTO Plate [ field SFVec3f size ] \"lib.wrl#Plate\"\n"
                            "Plate { size 4 2 2 }\nEXTERNPROTO Gone [ ] \"nowhere.wrl\"\nGone {}\n");
    const ImportResult r = importVrmlFile((dir / "main.wrl").string());
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.scene.triangleCount(), 12u);
    EXPECT_TRUE(hasPoint(r.scene, 2, 1, 1));
    EXPECT_EQ(r.scene.diagnostics.count("missing EXTERNPROTO"), 1);
    fs::remove_all(dir);
}
