// Instances kept: shared nodes (USE'd DEFs, Inline files) become one geometry each, read once
// in its own frame, and placements whose matrices put every use where expanding puts it.
#include "vrml_test_util.h"

#include "vrml/assembly.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include <unistd.h>

using namespace cadlod::vrml;
using namespace cadlod::vrml::test;
namespace fs = std::filesystem;

namespace {

ImportOptions keeping(double unitScale = 1.0)
{
    ImportOptions o;
    o.instances = Instances::Keep;
    o.unitScale = unitScale;
    return o;
}

// Every placed triangle in world coordinates, as the expanded scene has them: a mirrored
// placement's triangles turn round, as the OpenFlight writer turns them.
std::multiset<std::array<long, 9>> placedCorners(const Scene& s, const std::string& rootName = "test.wrl")
{
    std::multiset<std::array<long, 9>> out;
    auto key = [](const Vec3& p, int c) { return std::lround((c == 0 ? p.x : c == 1 ? p.y : p.z) * 1e4); };
    for (const Placement& placement : flattenPlacements(s.assembly, rootName))
        for (const Part& part : s.assembly.geometries[placement.geometry].parts)
            for (size_t t = 0; t < part.triangleCount(); ++t) {
                std::array<long, 9> corners{};
                const std::array<size_t, 3> order = placement.mirrored() ? std::array<size_t, 3>{0, 2, 1}
                                                                         : std::array<size_t, 3>{0, 1, 2};
                for (int k = 0; k < 3; ++k) {
                    const Vec3f& v = part.positions[part.triangles[3 * t + order[size_t(k)]]];
                    const Vec3 w = placement.matrix.transformPoint({v[0], v[1], v[2]});
                    for (int c = 0; c < 3; ++c) corners[size_t(3 * k + c)] = key(w, c);
                }
                out.insert(corners);
            }
    return out;
}

std::multiset<std::array<long, 9>> expandedCorners(const Scene& s)
{
    std::multiset<std::array<long, 9>> out;
    for (const auto& t : triangles(s)) {
        std::array<long, 9> corners{};
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) corners[size_t(3 * k + c)] = std::lround(double(t[size_t(k)][size_t(c)]) * 1e4);
        out.insert(corners);
    }
    return out;
}

const std::string kCabinet = R"(#VRML V2.0 utf8
DEF CAP Shape { geometry Box { size 1 2 3 } }
DEF BOARD Group { children [
  Shape { geometry Box { size 10 10 1 } }
  DEF C1 Transform { translation 2 0 1 children USE CAP }
  DEF C2 Transform { translation -2 0 1 rotation 0 0 1 1.5708 children USE CAP }
] }
DEF Board_1 Transform { translation 0 0 20 children USE BOARD }
DEF Board_2 Transform { translation 0 0 40 scale 2 2 2 children USE BOARD }
)";

}  // namespace

TEST(VrmlAssembly, SharedNodesAreReadOncePlacedWhereExpandingPutsThem)
{
    const Scene kept = load(kCabinet, keeping());
    const Scene expanded = load(kCabinet);
    ASSERT_FALSE(kept.assembly.empty());
    EXPECT_TRUE(kept.parts.empty());
    EXPECT_TRUE(kept.assembly.sharesGeometry());
    // The root, CAP and BOARD.
    EXPECT_EQ(kept.assembly.geometries.size(), 3u);
    EXPECT_EQ(kept.stats.meshTriangles, 24u);  // each box read once
    EXPECT_EQ(expanded.triangleCount(), 12u * 10);
    EXPECT_EQ(expanded.stats.expandedCopies, 8u) << "CAP placed 7 times, BOARD 3 times";
    EXPECT_EQ(placedCorners(kept), expandedCorners(expanded));
}

TEST(VrmlAssembly, PlacementsAreNamedByTheirPathAndNeverMerged)
{
    const Scene kept = load(kCabinet, keeping());
    const std::vector<Placement> placements = flattenPlacements(kept.assembly, "test.wrl");
    std::vector<std::string> paths;
    for (const Placement& p : placements) paths.push_back(p.path);
    // CAP and BOARD are placed where they are DEF'd, too.
    const std::vector<std::string> expected{"CAP",     "BOARD",      "BOARD/C1",   "BOARD/C2",   "Board_1",
                                            "Board_1/C1", "Board_1/C2", "Board_2", "Board_2/C1", "Board_2/C2"};
    EXPECT_EQ(placements.size(), 10u);
    const std::set<std::string> unique(paths.begin(), paths.end());
    EXPECT_EQ(unique.size(), paths.size()) << "every placement is a part of its own";
    for (const std::string& e : expected) EXPECT_EQ(unique.count(e), 1u) << e;
}

TEST(VrmlAssembly, ScaledPlacementsKeepTheirScaleAndMirrorsAreFlagged)
{
    const std::string text = "#VRML V2.0 utf8\nDEF P Shape { geometry Box {} }\n"
                             "Transform { scale -1 1 1 children USE P }\nTransform { scale 3 3 3 children USE P }\n";
    const Scene kept = load(text, keeping());
    const std::vector<Placement> placements = flattenPlacements(kept.assembly, "test.wrl");
    ASSERT_EQ(placements.size(), 3u);
    EXPECT_FALSE(placements[0].mirrored());
    EXPECT_TRUE(placements[1].mirrored());
    EXPECT_NEAR(placements[2].largestScale(), 3.0, 1e-12);
    EXPECT_EQ(placedCorners(kept), expandedCorners(load(text)));
}

TEST(VrmlAssembly, TheUnitScaleGoesIntoTheGeometryNotTheMatrices)
{
    const Scene kept = load(kCabinet, keeping(0.001));
    for (const Placement& p : flattenPlacements(kept.assembly, "test.wrl"))
        EXPECT_NEAR(p.largestScale(), p.path.rfind("Board_2", 0) == 0 ? 2.0 : 1.0, 1e-12) << p.path;
    EXPECT_EQ(placedCorners(kept), expandedCorners(load(kCabinet, [] {
                  ImportOptions o;
                  o.unitScale = 0.001;
                  return o;
              }())));
}

TEST(VrmlAssembly, AFileThatSharesNothingIsReadAsExpanding)
{
    const std::string text = "#VRML V2.0 utf8\nDEF A Transform { children Shape { geometry Box {} } }\n"
                             "DEF M Material {}\nShape { appearance Appearance { material USE M } geometry Box {} }\n";
    const Scene kept = load(text, keeping());
    const Scene expanded = load(text);
    EXPECT_TRUE(kept.assembly.empty());
    ASSERT_EQ(kept.parts.size(), expanded.parts.size());
    for (size_t i = 0; i < kept.parts.size(); ++i) {
        EXPECT_EQ(kept.parts[i].name, expanded.parts[i].name);
        EXPECT_EQ(kept.parts[i].positions, expanded.parts[i].positions);
        EXPECT_EQ(kept.parts[i].triangles, expanded.parts[i].triangles);
    }
    EXPECT_EQ(kept.stats.meshTriangles, expanded.stats.meshTriangles);
    EXPECT_EQ(kept.diagnostics.total(), expanded.diagnostics.total());
}

// A file that shares nothing, as its parts placed once: each DEF'd part (its colours
// together) a geometry of its own, a name given twice two parts, the shapes no DEF names
// in the root; every triangle where expanding puts it.
TEST(VrmlAssembly, AFileThatSharesNothingBecomesItsNamedPartsPlacedOnce)
{
    const std::string text =
        "#VRML V2.0 utf8\n"
        "DEF A Transform { translation 1 0 0 children [ Shape { geometry Box {} }\n"
        "  Shape { appearance Appearance { material Material { diffuseColor 1 0 0 } } geometry Sphere {} } ] }\n"
        "DEF B Transform { translation 0 4 0 children Shape { geometry Cone {} } }\n"
        "DEF A Transform { translation 0 0 9 children Shape { geometry Box {} } }\n"
        "Transform { translation 5 5 5 children Shape { geometry Box { size 1 2 3 } } }\n";
    Scene scene = load(text);
    EXPECT_EQ(namedParts(scene.parts), 3u);
    const auto expanded = expandedCorners(scene);
    scene.assembly = partsPlacedOnce(std::move(scene.parts));
    ASSERT_EQ(scene.assembly.geometries.size(), 4u);
    EXPECT_EQ(scene.assembly.geometries[0].parts.size(), 1u);  // the unnamed box
    EXPECT_EQ(scene.assembly.geometries[1].parts.size(), 2u);  // A's two colours
    const std::vector<Placement> placements = flattenPlacements(scene.assembly, "test.wrl");
    std::set<std::string> paths;
    for (const Placement& p : placements) paths.insert(p.path);
    EXPECT_EQ(paths, (std::set<std::string>{"test.wrl", "A", "A[2]", "B"}));
    EXPECT_FALSE(scene.assembly.sharesGeometry());
    EXPECT_EQ(placedCorners(scene), expanded);

    EXPECT_EQ(namedParts(load("#VRML V2.0 utf8\nShape { geometry Box {} }\nTransform { children Shape { "
                              "geometry Sphere {} } }\n").parts),
              0u);
}

TEST(VrmlAssembly, InlineFilesAreOneGeometryEachAndVrml1SeparatorsToo)
{
    const fs::path dir = fs::temp_directory_path() / ("cadlod_assembly_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "part.wrl") << "#VRML V1.0 ascii\nSeparator { DEF S Separator { Cube {} } "
                                       "Translation { translation 5 0 0 } USE S }\n";
    std::ofstream(dir / "asm.wrl") << "#VRML V2.0 utf8\n"
                                      "DEF A Transform { translation 0 10 0 children Inline { url \"part.wrl\" } }\n"
                                      "DEF B Transform { translation 0 20 0 children Inline { url \"part.wrl\" } }\n";
    const ImportResult kept = importVrmlFile((dir / "asm.wrl").string(), keeping());
    const ImportResult expanded = importVrmlFile((dir / "asm.wrl").string());
    ASSERT_TRUE(kept.ok()) << kept.error;
    // The root (empty), the part file and its shared Separator.
    EXPECT_EQ(kept.scene.assembly.geometries.size(), 3u);
    EXPECT_EQ(kept.scene.stats.meshTriangles, 12u);
    EXPECT_EQ(placedCorners(kept.scene, "asm.wrl"), expandedCorners(expanded.scene));
    std::set<std::string> paths;
    for (const Placement& p : flattenPlacements(kept.scene.assembly, "asm.wrl")) paths.insert(p.path);
    EXPECT_EQ(paths, (std::set<std::string>{"A/S", "A/S[2]", "B/S", "B/S[2]"}));
    fs::remove_all(dir);
}

TEST(VrmlAssembly, PlacementsBeyondTheLimitFailBeforeAnythingIsExpanded)
{
    std::string text = "#VRML V2.0 utf8\nDEF L0 Shape { geometry Box {} }\n";
    for (int level = 1; level <= 8; ++level) {
        text += "DEF L" + std::to_string(level) + " Group { children [";
        for (int k = 0; k < 10; ++k) text += " USE L" + std::to_string(level - 1);
        text += " ] }\n";
    }
    ImportOptions o = keeping();
    o.maxPlacements = 1'000'000;
    const ImportResult r = importVrmlText(text, "bomb.wrl", o);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.error.find("more than the limit"), std::string::npos) << r.error;
    EXPECT_EQ(r.scene.stats.meshTriangles, 12u) << "the box is read once";
}
