// Up axis and units at import (issue 16, item 2): CAD exports are Z up and kept as they
// are by default; Y-up files can be rotated to OpenFlight's Z up; KiCad StepUp files (0.1
// inch) are recognised by their header and scaled to millimetres; what was assumed is
// reported.
#include "vrml/importer.h"

#include <gtest/gtest.h>

#include <cmath>

#include <cstdlib>
#include <filesystem>

using namespace cadlod::vrml;

namespace {

// A triangle with a corner on each axis, 1 unit long, its normal given.
const char* kAxes = R"(#VRML V2.0 utf8
Shape { geometry IndexedFaceSet {
  coord Coordinate { point [ 1 0 0, 0 1 0, 0 0 1 ] } coordIndex [ 0 1 2 ]
  normal Normal { vector [ 0 1 0 ] } normalPerVertex FALSE } }
)";

std::string kicad(const std::string& body)
{
    return "#VRML V2.0 utf8\n#kicad StepUp wrl exported\n\n# Copyright (C) 2017, kicad StepUp\n" + body;
}

void expectPoint(const Part& p, size_t i, double x, double y, double z)
{
    EXPECT_NEAR(p.positions[i][0], x, 1e-5) << "vertex " << i;
    EXPECT_NEAR(p.positions[i][1], y, 1e-5) << "vertex " << i;
    EXPECT_NEAR(p.positions[i][2], z, 1e-5) << "vertex " << i;
}

}  // namespace

TEST(AxesAndUnits, CadExportsKeepTheirAxesByDefault)
{
    const ImportResult r = importVrmlText(kAxes, "axes.wrl");
    ASSERT_TRUE(r.ok()) << r.error;
    ASSERT_EQ(r.scene.parts.size(), 1u);
    expectPoint(r.scene.parts[0], 1, 0, 1, 0);
    EXPECT_EQ(r.assumed.upAxis, UpAxis::Keep);
    EXPECT_FALSE(r.assumed.kicadUnits);
    EXPECT_NE(r.assumed.describe(1.0).find("up axis: kept"), std::string::npos);
    EXPECT_NE(r.assumed.describe(1.0).find("units: as in the file"), std::string::npos);
}

TEST(AxesAndUnits, YUpFilesAreRotatedToZUp)
{
    ImportOptions o;
    o.upAxis = UpAxis::YUpToZUp;
    const ImportResult r = importVrmlText(kAxes, "axes.wrl", o);
    ASSERT_TRUE(r.ok()) << r.error;
    const Part& p = r.scene.parts[0];
    expectPoint(p, 0, 1, 0, 0);   // X stays
    expectPoint(p, 1, 0, 0, 1);   // +Y (up in the file) becomes +Z
    expectPoint(p, 2, 0, -1, 0);  // +Z (towards the viewer) becomes -Y
    ASSERT_FALSE(p.normals.empty());
    for (const auto& n : p.normals) {
        EXPECT_NEAR(n[2], 1.0, 1e-6) << "the normal turns with the geometry";
        EXPECT_NEAR(n[1], 0.0, 1e-6);
    }
    EXPECT_NE(r.assumed.describe(1.0).find("rotated to +Z"), std::string::npos);
}

TEST(AxesAndUnits, KicadStepUpFilesAreScaledFromTenthsOfAnInchToMillimetres)
{
    const ImportResult r = importVrmlText(kicad("Shape { geometry IndexedFaceSet { coord Coordinate { point "
                                                "[ 0 0 0, 0.394 0 0, 0 0.394 0 ] } coordIndex [ 0 1 2 ] } }\n"),
                                          "part.wrl");
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.assumed.kicadUnits);
    expectPoint(r.scene.parts[0], 1, 0.394 * 2.54, 0, 0);  // 1.0 mm
    EXPECT_NE(r.assumed.describe(0.001).find("KiCad StepUp header found, file in 0.1 inch, scaled by 2.54 to mm, "
                                             "then unit scale 0.001"),
              std::string::npos)
        << r.assumed.describe(0.001);

    ImportOptions off;
    off.detectKicadUnits = false;
    const ImportResult raw = importVrmlText(kicad("Shape { geometry IndexedFaceSet { coord Coordinate { point "
                                                  "[ 0 0 0, 0.394 0 0, 0 0.394 0 ] } coordIndex [ 0 1 2 ] } }\n"),
                                            "part.wrl", off);
    ASSERT_TRUE(raw.ok());
    EXPECT_FALSE(raw.assumed.kicadUnits);
    EXPECT_TRUE(raw.assumed.kicadHeader);  // found, not applied: the log can say so
    EXPECT_NE(raw.assumed.describe(1.0).find("its 0.1 inch not applied"), std::string::npos)
        << raw.assumed.describe(1.0);
    expectPoint(raw.scene.parts[0], 1, 0.394, 0, 0);
}

// kicadUnitScale replaces unitScale for KiCad files only: a caller scaling everything to
// metres need not know beforehand which files are KiCad's.
TEST(AxesAndUnits, KicadUnitScaleAppliesToKicadFilesOnly)
{
    const std::string body = "Shape { geometry IndexedFaceSet { coord Coordinate { point "
                             "[ 0 0 0, 0.394 0 0, 0 0.394 0 ] } coordIndex [ 0 1 2 ] } }\n";
    ImportOptions o;
    o.unitScale = 1.0;
    o.kicadUnitScale = 0.001;
    const ImportResult k = importVrmlText(kicad(body), "part.wrl", o);
    ASSERT_TRUE(k.ok()) << k.error;
    expectPoint(k.scene.parts[0], 1, 0.394 * 2.54 * 0.001, 0, 0);
    const ImportResult plain = importVrmlText("#VRML V2.0 utf8\n" + body, "plain.wrl", o);
    ASSERT_TRUE(plain.ok()) << plain.error;
    EXPECT_FALSE(plain.assumed.kicadHeader);
    expectPoint(plain.scene.parts[0], 1, 0.394, 0, 0);
}

// UnitScaling::PowerOfTwo multiplies in the power of two nearest to the unit and leaves the
// rest to the caller: millimetres, tenths of an inch and metres give the same coordinates
// up to a power of two, to the bit, and the rest makes up the unit.
TEST(AxesAndUnits, PowerOfTwoScalingGivesTheSameBitsInEveryUnit)
{
    const std::string text = "#VRML V2.0 utf8\nTransform { rotation 0.3 0.4 0.5 0.7 translation 1.1 -2.3 0.7 children "
                             "Shape { geometry IndexedFaceSet { coord Coordinate { point [ 0.1 0.2 0.3, 7.3 0.01 "
                             "2.9, -1.7 3.3 0.123 ] } coordIndex [ 0 1 2 ] } } }\n";
    ImportOptions unscaled;
    unscaled.unitScaling = UnitScaling::PowerOfTwo;
    const ImportResult reference = importVrmlText(text, "part.wrl", unscaled);
    ASSERT_TRUE(reference.ok()) << reference.error;
    EXPECT_EQ(reference.assumed.remainingScale, 1.0);
    for (const double unit : {0.001, 0.00254, 0.0254, 1000.0}) {
        ImportOptions o = unscaled;
        o.unitScale = unit;
        const ImportResult r = importVrmlText(text, "part.wrl", o);
        ASSERT_TRUE(r.ok()) << r.error;
        const double powerOfTwo = unit / r.assumed.remainingScale;
        EXPECT_EQ(std::exp2(std::round(std::log2(powerOfTwo))), powerOfTwo) << unit;
        EXPECT_GT(r.assumed.remainingScale, 0.7) << unit;
        EXPECT_LT(r.assumed.remainingScale, 1.42) << unit;
        const auto& p = r.scene.parts[0].positions;
        const auto& q = reference.scene.parts[0].positions;
        ASSERT_EQ(p.size(), q.size());
        for (std::size_t i = 0; i < p.size(); ++i)
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_EQ(p[i][axis], float(q[i][axis] * powerOfTwo)) << unit << " vertex " << i;
    }
    ImportOptions exact;
    exact.unitScale = 0.001;
    EXPECT_EQ(importVrmlText(text, "part.wrl", exact).assumed.remainingScale, 1.0);
}

// The header must be KiCad's own comment at the top, not the words anywhere in the file.
TEST(AxesAndUnits, KicadIsOnlyDetectedFromTheHeaderComments)
{
    const ImportResult r = importVrmlText("#VRML V2.0 utf8\nDEF kicad_StepUp_like Shape { geometry IndexedFaceSet { "
                                          "coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] } coordIndex [ 0 1 2 ] } }\n"
                                          "# kicad StepUp wrl exported\n",
                                          "other.wrl");
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE(r.assumed.kicadUnits);
}

// A real KiCad library model: a 2 x 2 mm DFN-8 measures 2 mm once scaled.
TEST(AxesAndUnits, KicadLibraryModelMeasuresInMillimetres)
{
    const std::string path = "/usr/share/kicad/3dmodels/Package_DFN_QFN.3dshapes/DFN-8_2x2mm_P0.5mm.wrl";
    if (!std::filesystem::exists(path))
        GTEST_SKIP() << "kicad-packages3d is not installed";
    const ImportResult r = importVrmlFile(path);
    ASSERT_TRUE(r.ok()) << r.error;
    EXPECT_TRUE(r.assumed.kicadUnits);
    double lo = 1e9, hi = -1e9;
    for (const Part& p : r.scene.parts)
        for (const auto& v : p.positions) {
            lo = std::min(lo, double(v[0]));
            hi = std::max(hi, double(v[0]));
        }
    EXPECT_NEAR(hi - lo, 2.0, 0.01);
}
