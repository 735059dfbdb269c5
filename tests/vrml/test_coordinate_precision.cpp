// Coordinates too coarse for the geometry they hold (coordinate_precision.h): a part read
// into floats where they are spaced wider than its detail is reported, with the file; the
// same part near the origin, or kept as an instance about its own origin, is not.
#include "vrml/coordinate_precision.h"
#include "vrml/importer.h"

#include <gtest/gtest.h>

#include <string>

namespace cadlod::vrml {
namespace {

// A 2-unit box with a cylinder on it, as a shared DEF used twice, `at` off the origin.
std::string boardsAt(const std::string& at)
{
    return "#VRML V2.0 utf8\nTransform { translation " + at +
           " children [\n"
           "  DEF BOARD Transform { children [ Shape { geometry Box { size 2 2 0.2 } }\n"
           "    Transform { translation 0 0 0.5 children Shape { geometry Cylinder { radius 0.2 height 0.8 } } } ] }\n"
           "  Transform { translation 3 0 0 children USE BOARD }\n"
           "] }\n";
}

const Diagnostic* coarseFinding(const Scene& scene)
{
    for (const Diagnostic& d : scene.diagnostics.kept())
        if (d.kind == "coarse coordinates")
            return &d;
    return nullptr;
}

ImportResult importAs(const std::string& text, Instances instances)
{
    ImportOptions options;
    options.instances = instances;
    ImportResult r = importVrmlText(text, "site.wrl", options);
    EXPECT_TRUE(r.ok()) << r.error;
    return r;
}

TEST(CoordinatePrecision, PartsBakedFarFromTheOriginAreReportedWithTheFile)
{
    // 5e6 units off, floats are 0.5 apart: a quarter of a 2-unit board.
    const ImportResult far = importAs(boardsAt("5e6 2e6 0"), Instances::Expand);
    const Diagnostic* finding = coarseFinding(far.scene);
    ASSERT_NE(finding, nullptr);
    EXPECT_EQ(finding->where, "site.wrl");
    EXPECT_NE(finding->message.find("2 parts"), std::string::npos) << finding->message;
    EXPECT_NE(finding->message.find("BOARD"), std::string::npos) << finding->message;
    EXPECT_FALSE(losesGeometry(finding->kind));
}

TEST(CoordinatePrecision, TheSamePartsNearTheOriginOrKeptAsInstancesAreNot)
{
    EXPECT_EQ(coarseFinding(importAs(boardsAt("0 0 0"), Instances::Expand).scene), nullptr);
    // 5e3 off: floats 5e-4 apart, a four-thousandth of a board.
    EXPECT_EQ(coarseFinding(importAs(boardsAt("5e3 0 0"), Instances::Expand).scene), nullptr);
    // Kept, the board's geometry lies about its own origin; its placements are doubles.
    EXPECT_EQ(coarseFinding(importAs(boardsAt("5e6 2e6 0"), Instances::Keep).scene), nullptr);
}

TEST(CoordinatePrecision, TheLimitIsAShareOfThePartsOwnSize)
{
    Scene scene;
    Part part;
    part.name = "plate";
    part.owner = 0;
    part.positions = {{1024, 0, 0}, {1025, 0, 0}, {1024, 1, 0}};  // floats 1.2e-4 apart there, size 1.4
    part.triangles = {0, 1, 2};
    scene.parts.push_back(part);
    warnOfCoarseCoordinates(scene, "a.wrl");
    EXPECT_EQ(coarseFinding(scene), nullptr);
    for (Vec3f& p : scene.parts.front().positions)
        p[0] += 16384 - 1024;  // floats 2e-3 apart: more than a thousandth of 1.4
    warnOfCoarseCoordinates(scene, "a.wrl");
    EXPECT_NE(coarseFinding(scene), nullptr);
}

// Placements hold their translations as written: a float would round 5080123.4567 to
// 5080123.5. VRML97's Transform (translation; center, about which it scales twice) and
// VRML 1.0's Translation and MatrixTransform alike.
TEST(CoordinatePrecision, PlacementsKeepTheirTranslationsAsWritten)
{
    const std::string part = "DEF P Shape { geometry Box { size 1 1 1 } }";
    const std::string uses = " Transform { translation 2 0 0 children USE P } ] }\n";
    const std::string cube =
        "  DEF P Separator { Cube { width 1 height 1 depth 1 } } Translation { translation 2 0 0 } USE P }\n";
    const struct {
        std::string text;
        double x, y, z;  // the first placement's translation
    } files[] = {
        {"#VRML V2.0 utf8\nTransform { translation 5080123.4567 -2000000.1234 0.3 children [ " + part + uses,
         5080123.4567, -2000000.1234, 0.3},
        {"#VRML V2.0 utf8\nTransform { center 5080123.4567 -2000000.1234 0.3 scale 2 2 2 children [ " + part + uses,
         -5080123.4567, 2000000.1234, -0.3},
        {"#VRML V1.0 ascii\nSeparator { Translation { translation 5080123.4567 -2000000.1234 0.3 }\n" + cube,
         5080123.4567, -2000000.1234, 0.3},
        {"#VRML V1.0 ascii\nSeparator { MatrixTransform { matrix 1 0 0 0 0 1 0 0 0 0 1 0 "
         "5080123.4567 -2000000.1234 0.3 1 }\n" + cube,
         5080123.4567, -2000000.1234, 0.3}};
    for (const auto& file : files) {
        const ImportResult r = importAs(file.text, Instances::Keep);
        std::vector<Placement> placed;
        for (const Placement& p : flattenPlacements(r.scene.assembly, "site"))
            if (!r.scene.assembly.geometries[p.geometry].parts.empty())
                placed.push_back(p);
        ASSERT_EQ(placed.size(), 2u) << file.text;
        EXPECT_NEAR(placed[0].matrix.m[0][3], file.x, 1e-6) << file.text;
        EXPECT_NEAR(placed[0].matrix.m[1][3], file.y, 1e-6) << file.text;
        EXPECT_NEAR(placed[0].matrix.m[2][3], file.z, 1e-9) << file.text;
    }
}

}  // namespace
}  // namespace cadlod::vrml
