// cadlod convert --hlod auto on an assembly of many placements, read back with
// OpenSceneGraph and drawn from eye points inside it, along it and far from it (design.md
// §8): no drawable shows more than the bound a viewer reads off its switch distance and its
// nearest vertex; every placement is drawn exactly once, by itself or by one cluster proxy;
// every LOD node's ranges are contiguous; far off, a few proxies replace the parts.
#include "cli_runner.h"
#include "flt_bytes.h"
#include "osg_view_probe.h"

#include "assembly/hierarchical_lod.h"
#include "assembly/level_store.h"

#include "convert/lod_model_to_mesh.h"
#include "lod/lod_chain.h"
#include "lod/nearest_point.h"
#include "measure/hausdorff.h"
#include "vrml/importer.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

namespace cadlod::test {
namespace {

constexpr int kColumns = 8, kRows = 8, kLayers = 2;

// A knob: a sphere and a red pin `pin` ("x y") off its centre, DEF'd as KNOB.
std::string knobDefinition(const char* pin)
{
    return std::string("DEF KNOB Group { children [ Shape { geometry Sphere { radius 0.012 } }\n"
                       "  Transform { translation ") +
           pin +
           " 0.015 children Shape { appearance Appearance { material Material { diffuseColor 1 0 0 } } "
           "geometry Cylinder { radius 0.003 height 0.03 } } } ] }";
}

// A knob (a sphere and a red pin) DEF'd once and USE'd on an 8 x 8 x 2 grid, 0.6 m wide.
std::string writeGrid(const std::string& dir)
{
    std::ostringstream text;
    text << "#VRML V2.0 utf8\n";
    int n = 0;
    for (int z = 0; z < kLayers; ++z)
        for (int y = 0; y < kRows; ++y)
            for (int x = 0; x < kColumns; ++x, ++n) {
                text << "DEF P" << n << " Transform { translation " << 0.08 * x << ' ' << 0.08 * y << ' ' << 0.1 * z
                     << " children ";
                text << (n == 0 ? knobDefinition("0 0") : "USE KNOB");
                text << " }\n";
            }
    const std::string path = dir + "/grid.wrl";
    std::ofstream(path) << text.str();
    return path;
}

// A row of 8 knobs, their pins off centre, DEF'd once and USE'd 8 times 0.6 m apart (so
// that each row is a cluster); every other row moved `shift` along x and turned about z by
// `turn` (radians, as written), as racks facing across an aisle (a half turn) or set
// askew, or seen in a mirror (`turn` "mirror": x -> -x).
std::string writeTurnedRows(const std::string& dir, const std::string& shift, const std::string& turn)
{
    std::ostringstream text;
    text << "#VRML V2.0 utf8\n";
    for (int y = 0; y < 8; ++y) {
        text << "Transform { translation " << (y % 2 ? shift : "0") << ' ' << 0.6 * y << " 0"
             << (y % 2 ? (turn == "mirror" ? " scale -1 1 1" : " rotation 0 0 1 " + turn) : "")
             << " children ";
        if (y > 0) {
            text << "USE ROW }\n";
            continue;
        }
        text << "DEF ROW Group { children [\n";
        for (int x = 0; x < 8; ++x)
            text << " Transform { translation " << 0.08 * x << " 0 0 children "
                 << (x == 0 ? knobDefinition("0.008 0.005") : "USE KNOB")
                 << " }\n";
        text << "] } }\n";
    }
    const std::string path = dir + "/turned_rows.wrl";
    std::ofstream(path) << text.str();
    return path;
}

// Twelve stations along a beam, each a plate and six knobs DEF'd once and USE'd: placed in
// a zigzag 0.3 m apart, each station's box overlaps its neighbours' along the line, so no
// gap parts them; the plate is placed as the station itself, the knobs under it.
std::string writeStations(const std::string& dir)
{
    std::ostringstream text;
    text << "#VRML V2.0 utf8\n"
            "DEF Beam Shape { geometry Box { size 4 0.02 0.02 } }\n";
    for (int k = 0; k < 12; ++k) {
        text << "DEF Station_" << k << " Transform { translation " << 0.3 * k - 1.65 << ' ' << 0.15 * (k % 2)
             << " 0.03 children ";
        if (k > 0) {
            text << "USE STATION }\n";
            continue;
        }
        text << "DEF STATION Group { children [ Shape { geometry Box { size 0.4 0.1 0.01 } }\n";
        for (int i = 0; i < 6; ++i)
            text << " DEF K" << i << " Transform { translation " << 0.07 * i - 0.175 << " 0 0.012 children "
                 << (i == 0 ? knobDefinition("0.004 0") : "USE KNOB")
                 << " }\n";
        text << "] } }\n";
    }
    const std::string path = dir + "/stations.wrl";
    std::ofstream(path) << text.str();
    return path;
}

// The same knobs on a 4 x 4 x 2 grid, each written out in full: a file that shares nothing,
// as CAD systems export an assembly into one file, each part under its own DEF name.
std::string writeUnsharedGrid(const std::string& dir)
{
    std::ostringstream text;
    text << "#VRML V2.0 utf8\n";
    for (int z = 0, n = 0; z < 2; ++z)
        for (int y = 0; y < 4; ++y)
            for (int x = 0; x < 4; ++x, ++n)
                text << "DEF P" << n << " Transform { translation " << 0.08 * x << ' ' << 0.08 * y << ' ' << 0.1 * z
                     << " children [ Shape { geometry Sphere { radius 0.012 } }\n"
                        "  Transform { translation 0 0 0.015 children Shape { appearance Appearance { material "
                        "Material { diffuseColor 1 0 0 } } geometry Cylinder { radius 0.003 height 0.03 } } } ] }\n";
    const std::string path = dir + "/unshared.wrl";
    std::ofstream(path) << text.str();
    return path;
}

// Knobs on a 4 x 4 grid, DEF'd once and USE'd, placed plain, stretched three times along z
// (a knob drawn tall) or along x, in turn.
std::string writeStretchedKnobs(const std::string& dir)
{
    const char* scales[] = {"1 1 1", "1 1 3", "3 1 1"};
    std::ostringstream text;
    text << "#VRML V2.0 utf8\n";
    for (int n = 0; n < 16; ++n)
        text << "DEF P" << n << " Transform { translation " << 0.12 * (n % 4) << ' ' << 0.12 * (n / 4)
             << " 0 scale " << scales[n % 3] << " children " << (n == 0 ? knobDefinition("0 0") : "USE KNOB")
             << " }\n";
    const std::string path = dir + "/stretched.wrl";
    std::ofstream(path) << text.str();
    return path;
}

std::vector<Point3> eyePoints(const std::array<Point3, 2>& box)
{
    const Point3 &lo = box[0], &hi = box[1];
    const Point3 size{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    const double diagonal = std::sqrt(size[0] * size[0] + size[1] * size[1] + size[2] * size[2]);
    std::vector<Point3> eyes;
    for (int i = 0; i < 4; ++i)  // inside
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 2; ++k)
                eyes.push_back({lo[0] + size[0] * (i + 0.5) / 4, lo[1] + size[1] * (j + 0.5) / 4,
                                lo[2] + size[2] * (k + 0.5) / 2});
    for (int i = 0; i < 20; ++i)  // walking along, 5 % of the diagonal off its side
        eyes.push_back({lo[0] + size[0] * (i + 0.5) / 20, lo[1] - 0.05 * diagonal, 0.5 * (lo[2] + hi[2])});
    for (int i = 0; i < 12; ++i) {  // backing away, from 1x the diagonal to 1000x
        const double d = diagonal * std::pow(1000.0, i / 11.0);
        eyes.push_back({0.5 * (lo[0] + hi[0]) - 0.3 * d, 0.5 * (lo[1] + hi[1]) - 0.9 * d,
                        0.5 * (lo[2] + hi[2]) + 0.3 * d});
    }
    return eyes;
}

// Points of the finest level of `osg`, to ask for the gaps on screen the tests allow: none
// wider than the error bound (5 % slack for the samples), in pixels of the default view.
struct HoleCheck {
    explicit HoleCheck(const OsgViewProbe& osg) : samples(osg.finestSamples(20000))
    {
        const ViewParams defaults;
        query = {&samples, 2 * std::tan(defaults.fovYDegrees * M_PI / 360) / defaults.viewportHeightPx,
                 kApparentErrorBound * 1.05};
    }
    std::vector<Point3> samples;
    OsgGapQuery query;
};

// `view`, drawn from `eye` with a HoleCheck's query, within the bound and without a hole:
// where neighbouring nodes show different levels, none leaves one.
void expectWithinTheBoundWithoutHoles(const OsgView& view, const Point3& eye)
{
    EXPECT_LE(view.worstApparentPx, kApparentErrorBound * (1 + 1e-9));
    EXPECT_EQ(view.gaps.wider, 0u) << "widest gap " << view.gaps.widestPx << " px from " << eye[0] << " " << eye[1]
                                   << " " << eye[2];
}

// Seen from `eye`, every placement of the grid is drawn exactly once (by itself or by a
// proxy), and no drawn level shows more than the bound.
void expectEveryPlacementOnceWithinTheBound(const OsgView& view, const Point3& eye)
{
    const std::string at = "eye " + std::to_string(eye[0]) + " " + std::to_string(eye[1]) + " " + std::to_string(eye[2]);
    EXPECT_LE(view.worstApparentPx, kApparentErrorBound * (1 + 1e-9)) << at;
    ASSERT_EQ(view.drawnPlacements.size(), std::size_t(kColumns * kRows * kLayers)) << at;
    for (const auto& [name, times] : view.drawnPlacements)
        EXPECT_EQ(times, 1u) << name << " from " << at;
}

// `path` read back with OSG and drawn from eyePoints: no drawn level shows more than the bound,
// and `placements` placements are drawn from every eye.
void expectTheBoundWithEveryPlacementDrawn(const std::string& path, const std::string& modelName,
                                           std::size_t placements)
{
    const OsgViewProbe osg(path, modelName);
    ASSERT_TRUE(osg.loaded()) << path;
    for (const Point3& eye : eyePoints(osg.bounds())) {
        const OsgView view = osg.drawFrom(eye);
        EXPECT_LE(view.worstApparentPx, kApparentErrorBound * (1 + 1e-9)) << path;
        EXPECT_EQ(view.drawnPlacements.size(), placements) << path;
    }
}

}  // namespace

TEST(CliHierarchicalLod, HoldsTheErrorBoundAndDrawsEveryPlacementOnceWhereverTheEyeIs)
{
    const std::string dir = freshDirectory("hlod");
    const std::string input = writeGrid(dir);
    const CliRun run = runCadlod({"convert", input, "-o", dir + "/grid.flt", "--cluster-parts", "16", "--report", dir + "/grid.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/grid.json"));
    const nlohmann::json& hlod = report.at("hlod");
    EXPECT_GE(hlod.at("clusters").get<int>(), 9);  // 128 placements, at most 16 to a leaf
    EXPECT_GE(hlod.at("withProxies").get<int>(), 2);
    // The clusters that are copies of others draw those ones' proxies: each written once, as
    // an Instance Definition, and referenced beside the placements' references.
    EXPECT_GE(hlod.at("copiedClusters").get<int>(), 4);
    EXPECT_LT(hlod.at("proxyShapes").get<int>(), hlod.at("proxyLevels").get<int>());
    const nlohmann::json& output = report.at("output");
    EXPECT_GT(output.at("instanceDefinitions").get<int>(), report.at("input").at("parts").get<int>());
    EXPECT_GT(output.at("instanceReferences").get<int>(), output.at("placements").get<int>());

    const OsgViewProbe osg(dir + "/grid.flt", "grid");
    ASSERT_TRUE(osg.loaded());
    for (const OsgLodRanges& node : osg.lodNodes()) {
        std::vector<std::pair<double, double>> r = node.ranges;
        std::sort(r.begin(), r.end());
        ASSERT_FALSE(r.empty());
        EXPECT_EQ(r.front().first, 0.0);
        EXPECT_GE(r.back().second, 1e29);
        for (std::size_t i = 0; i + 1 < r.size(); ++i) {
            EXPECT_LT(r[i].first, r[i].second);
            EXPECT_NEAR(r[i].second, r[i + 1].first, 1e-6 * r[i].second);
        }
    }
    std::size_t farDrawables = 0, nearDrawables = 0;
    const std::vector<Point3> eyes = eyePoints(osg.bounds());
    for (const Point3& eye : eyes) {
        const OsgView view = osg.drawFrom(eye);
        expectEveryPlacementOnceWithinTheBound(view, eye);
        if (&eye == &eyes.back())  // 1000x the diagonal off
            farDrawables = view.drawables;
        nearDrawables = std::max(nearDrawables, view.drawables);
    }
    // Far off, the proxies stand for the 128 knobs (two colours each).
    EXPECT_GE(nearDrawables, std::size_t(kColumns * kRows));
    EXPECT_LE(farDrawables, 4u);
}

TEST(CliHierarchicalLod, TheClusterFanoutShapesTheTree)
{
    const std::string dir = freshDirectory("hlod_fanout");
    const std::string input = writeGrid(dir);
    EXPECT_EQ(runCadlod({"convert", input, "-o", dir + "/bad.flt", "--cluster-fanout", "1"}).exitCode, 2);
    EXPECT_FALSE(fileExists(dir + "/bad.flt"));

    const CliRun run = runCadlod({"convert", input, "-o", dir + "/grid.flt", "--cluster-parts", "16",
                                  "--cluster-fanout", "2", "--report", dir + "/grid.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_NE(run.stderrText.find("(2 per node)"), std::string::npos) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/grid.json"));
    EXPECT_EQ(report.at("hlod").at("fanout").get<int>(), 2);
    // 128 placements halved down to leaves of 16: 1 + 2 + 4 + 8 clusters.
    EXPECT_EQ(report.at("hlod").at("clusters").get<int>(), 15);

    const OsgViewProbe osg(dir + "/grid.flt", "grid");
    ASSERT_TRUE(osg.loaded());
    for (const Point3& eye : eyePoints(osg.bounds()))
        expectEveryPlacementOnceWithinTheBound(osg.drawFrom(eye), eye);
}

// --hlod calls: leaves of two placements, every cluster also drawn as its parts merged
// unchanged; the bound holds and every placement is drawn once, with fewer draw calls near
// and inside the grid than the default's.
TEST(CliHierarchicalLod, TheFewestCallsModeDrawsFewerNearTheEye)
{
    const std::string dir = freshDirectory("hlod_calls");
    const std::string input = writeGrid(dir);
    const CliRun calls = runCadlod({"convert", input, "-o", dir + "/calls.flt", "--hlod", "calls", "--report",
                                    dir + "/calls.json"});
    ASSERT_EQ(calls.exitCode, 0) << calls.stderrText;
    ASSERT_EQ(runCadlod({"convert", input, "-o", dir + "/auto.flt"}).exitCode, 0);
    const nlohmann::json hlod = nlohmann::json::parse(readFile(dir + "/calls.json")).at("hlod");
    EXPECT_EQ(hlod.at("mode"), "calls");
    EXPECT_EQ(hlod.at("clusterParts").get<int>(), 2);
    EXPECT_EQ(hlod.at("fanout").get<int>(), 2);
    EXPECT_EQ(hlod.at("clusters").get<int>(), 127);  // 128 placements halved down to pairs

    const OsgViewProbe fewest(dir + "/calls.flt", "calls"), standard(dir + "/auto.flt", "auto");
    ASSERT_TRUE(fewest.loaded() && standard.loaded());
    std::size_t fewestNear = 0, standardNear = 0;
    const std::vector<Point3> eyes = eyePoints(fewest.bounds());
    constexpr std::size_t kInsideAndWalking = 4 * 4 * 2 + 20;  // eyePoints' first
    for (std::size_t i = 0; i < eyes.size(); ++i) {
        const OsgView view = fewest.drawFrom(eyes[i]);
        expectEveryPlacementOnceWithinTheBound(view, eyes[i]);
        if (i < kInsideAndWalking) {
            fewestNear += view.drawables;
            standardNear += standard.drawFrom(eyes[i]).drawables;
        }
    }
    ASSERT_GT(standardNear, 0u);
    EXPECT_LT(4 * fewestNear, 3 * standardNear) << fewestNear << " drawables against " << standardNear;
}

}  // namespace cadlod::test

namespace cadlod::test {

// A file that shares nothing but holds many parts gets the same hierarchy: each part placed
// once, in clusters with proxies, the bound held from inside; --hlod off keeps one LOD node.
TEST(CliHierarchicalLod, AFileThatSharesNothingIsClusteredByItsParts)
{
    const std::string dir = freshDirectory("hlod_unshared");
    const std::string input = writeUnsharedGrid(dir);
    const CliRun run = runCadlod({"convert", input, "-o", dir + "/parts.flt", "--cluster-parts", "4", "--report",
                                  dir + "/parts.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/parts.json"));
    EXPECT_EQ(report.at("output").at("placements"), 32);
    EXPECT_EQ(report.at("parts").size(), 32u);
    EXPECT_EQ(report.at("output").at("instanceDefinitions"), 0);  // each part placed once
    EXPECT_GE(report.at("hlod").at("clusters").get<int>(), 8);
    EXPECT_GE(report.at("hlod").at("withProxies").get<int>(), 1);

    const OsgViewProbe osg(dir + "/parts.flt", "parts");
    ASSERT_TRUE(osg.loaded());
    std::size_t farDrawables = 0;
    const HoleCheck holes(osg);
    ASSERT_GT(holes.samples.size(), 10000u);
    for (const Point3& eye : eyePoints(osg.bounds())) {
        const OsgView view = osg.drawFrom(eye, &holes.query);
        expectWithinTheBoundWithoutHoles(view, eye);
        EXPECT_EQ(view.drawnPlacements.size(), 32u);
        farDrawables = view.drawables;
    }
    EXPECT_LE(farDrawables, 2u);  // one proxy, its colours in one Mesh

    const CliRun off = runCadlod({"convert", input, "-o", dir + "/one.flt", "--hlod", "off", "--report",
                                  dir + "/one.json"});
    ASSERT_EQ(off.exitCode, 0) << off.stderrText;
    const nlohmann::json one = nlohmann::json::parse(readFile(dir + "/one.json"));
    EXPECT_FALSE(one.contains("parts"));
    EXPECT_EQ(one.at("output").at("lodNodes"), one.at("levels").size());  // one chain: a record per level
}

// A part placed stretched shows its levels' errors stretched: it is simplified stretched, a
// part of its own per stretch, so that the bound holds where it stands, clustered or not.
TEST(CliHierarchicalLod, AStretchedPlacementHoldsTheBoundAsItIsSeen)
{
    const std::string dir = freshDirectory("hlod_stretched");
    const std::string input = writeStretchedKnobs(dir);
    for (const char* mode : {"auto", "off"}) {
        const std::string out = dir + "/" + mode;
        const CliRun run = runCadlod({"convert", input, "-o", out + ".flt", "--hlod", mode, "--cluster-parts", "4",
                                      "--report", out + ".json"});
        ASSERT_EQ(run.exitCode, 0) << run.stderrText;
        EXPECT_NE(run.stderrText.find("10 placements scale their part unevenly"), std::string::npos) << run.stderrText;
        const nlohmann::json report = nlohmann::json::parse(readFile(out + ".json"));
        EXPECT_EQ(report.at("input").at("stretchedPlacements"), 10);
        EXPECT_EQ(report.at("input").at("parts"), 3);  // the knob, tall and wide
        expectTheBoundWithEveryPlacementDrawn(out + ".flt", mode, 16);
    }
}

// Creo and SolidWorks write a file per part and place each by Inline, no DEF naming it, or all
// of them under one DEF'd root: with every part placed once, the file shares nothing, and each
// Inline file is a part placed once (named by its file, or after the root and its file), in
// clusters with proxies as named parts are.
TEST(CliHierarchicalLod, PartsPlacedOnceByInlineAreClusteredByTheirFiles)
{
    const std::string dir = freshDirectory("hlod_inline_once");
    std::ostringstream text;
    for (int n = 0; n < 16; ++n) {
        std::ofstream(dir + "/part" + std::to_string(n) + ".wrl")
            << "#VRML V2.0 utf8\nShape { geometry Sphere { radius 0.012 } }\n"
               "Transform { translation 0 0 0.015 children Shape { appearance Appearance { material Material { "
               "diffuseColor 1 0 0 } } geometry Cylinder { radius 0.003 height 0.03 } } }\n";
        text << "Transform { translation " << 0.08 * (n % 4) << ' ' << 0.08 * (n / 4)
             << " 0 children Inline { url \"part" << n << ".wrl\" } }\n";
    }
    std::ofstream(dir + "/assembly.wrl") << "#VRML V2.0 utf8\n" << text.str();
    std::ofstream(dir + "/rooted.wrl") << "#VRML V2.0 utf8\nDEF ASSEMBLY Transform { children [\n"
                                       << text.str() << "] }\n";
    for (const std::string name : {"assembly", "rooted"}) {
        const CliRun run = runCadlod({"convert", dir + "/" + name + ".wrl", "-o", dir + "/" + name + ".flt",
                                      "--cluster-parts", "4", "--report", dir + "/" + name + ".json"});
        ASSERT_EQ(run.exitCode, 0) << run.stderrText;
        const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/" + name + ".json"));
        ASSERT_TRUE(report.contains("parts")) << name << " converted as one node";
        EXPECT_EQ(report.at("parts").size(), 16u) << name;
        EXPECT_EQ(report.at("parts").at(1).at("name"), name == "rooted" ? "ASSEMBLY/part1" : "part1");
        EXPECT_GE(report.at("hlod").at("clusters").get<int>(), 4) << name;

        expectTheBoundWithEveryPlacementDrawn(dir + "/" + name + ".flt", name, 16);
    }
}

namespace {

// A sheet 2 m by 0.25 m of 256 x 32 quads, bent in gentle waves 3 cm high, and a red box on
// it: two Shapes, which no DEF names.
std::string writeWavySheet(const std::string& dir)
{
    std::ostringstream text;
    text << "#VRML V2.0 utf8\nShape { geometry IndexedFaceSet { coord Coordinate { point [\n";
    constexpr int kAlong = 256, kAcross = 32;
    for (int j = 0; j <= kAcross; ++j)
        for (int i = 0; i <= kAlong; ++i)
            text << 2.0 * i / kAlong << ' ' << 0.25 * j / kAcross << ' '
                 << 0.03 * std::sin(12.0 * i / kAlong) * std::cos(4.0 * j / kAcross) << ",\n";
    text << "] } coordIndex [\n";
    for (int j = 0; j < kAcross; ++j)
        for (int i = 0; i < kAlong; ++i) {
            const int a = j * (kAlong + 1) + i;
            text << a << ' ' << a + 1 << ' ' << a + kAlong + 2 << ' ' << a + kAlong + 1 << " -1\n";
        }
    text << "] } }\n";
    text << "Transform { translation 1 0.125 0.05 children Shape { appearance Appearance { material Material { "
            "diffuseColor 1 0 0 } } geometry Box { size 0.1 0.1 0.1 } } }\n";
    const std::string path = dir + "/sheet.wrl";
    std::ofstream(path) << text.str();
    return path;
}

}  // namespace

// A file of one part, or of shapes no DEF names, is one part placed once: its levels switch
// where they hold at its nearest point, and a large one is drawn in chunks near the eye, cut
// again nearer still, so that the bound holds inside and along it as it does on an assembly; far off, the part's
// own levels draw it in one call, not a call per chunk. Chunks at different levels leave no
// hole between them. With --hlod off it is one LOD node
// switched by its centre, which shows more than the bound from beside it.
TEST(CliHierarchicalLod, AFileOfOnePartHoldsTheBoundNearItAndIsOneDrawableFarOff)
{
    const std::string dir = freshDirectory("hlod_one_part");
    const std::string input = writeWavySheet(dir);
    const CliRun run = runCadlod({"convert", input, "-o", dir + "/sheet.flt", "--report", dir + "/sheet.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    EXPECT_NE(run.stderrText.find("chunks, each switched by its own centre"), std::string::npos) << run.stderrText;
    // Each of them would hold its finest level to six of its radii: cut again, nearer still.
    std::size_t top = 0, all = 0;
    const std::size_t at = run.stderrText.find("drawn in ");
    ASSERT_NE(at, std::string::npos);
    ASSERT_EQ(std::sscanf(run.stderrText.c_str() + at, "drawn in %zu chunks, each switched by its own centre and cut "
                                                          "again nearer still (%zu chunks in all)", &top, &all), 2)
        << run.stderrText;
    EXPECT_GT(all, 2 * top);
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/sheet.json"));
    EXPECT_EQ(report.at("hlod").at("chunkedParts"), 1);
    EXPECT_EQ(report.at("hlod").at("chunks"), all);
    EXPECT_GE(report.at("levels").size(), 3u);
    EXPECT_EQ(report.at("input").at("placements"), 1);

    const OsgViewProbe osg(dir + "/sheet.flt", "sheet");
    ASSERT_TRUE(osg.loaded());
    for (const OsgLodRanges& node : osg.lodNodes()) {
        std::vector<std::pair<double, double>> r = node.ranges;
        std::sort(r.begin(), r.end());
        for (std::size_t i = 0; i + 1 < r.size(); ++i)
            EXPECT_NEAR(r[i].second, r[i + 1].first, 1e-6 * r[i].second);
    }
    const HoleCheck holes(osg);
    ASSERT_GT(holes.samples.size(), 10000u);
    const std::vector<Point3> eyes = eyePoints(osg.bounds());
    for (const Point3& eye : eyes) {
        const OsgView view = osg.drawFrom(eye, &holes.query);
        expectWithinTheBoundWithoutHoles(view, eye);
        EXPECT_GE(view.triangles, 1u);  // drawn from every eye
        const std::size_t i = std::size_t(&eye - &eyes.front());
        if (i < 52) {  // inside and walking: its chunks
            EXPECT_GT(view.drawables, 1u);
        } else if (i >= 56) {  // from 12 times the diagonal on: its own levels, both colours in one call
            EXPECT_EQ(view.drawables, 1u);
        }
    }

    const CliRun off = runCadlod({"convert", input, "-o", dir + "/one_node.flt", "--hlod", "off"});
    ASSERT_EQ(off.exitCode, 0) << off.stderrText;
    const OsgViewProbe oneNode(dir + "/one_node.flt", "one_node");
    double worst = 0;
    for (const Point3& eye : eyePoints(oneNode.bounds()))
        worst = std::max(worst, oneNode.drawFrom(eye).worstApparentPx);
    EXPECT_GT(worst, kApparentErrorBound);
}

// The bundled sample: CAD parts whose faces are triangulated as slivers across their width,
// a plate of 12 triangles in one part with a finely tessellated shaft. Their long triangles
// are chunks of their own, and wherever the eye is, the chunks leave no hole and no drawn
// level shows more than the bound.
TEST(CliHierarchicalLod, TheSamplesChunksLeaveNoHoleWhereverTheEyeIs)
{
    const std::string dir = freshDirectory("hlod_sample");
    const std::string output = dir + "/sample.flt";
    const CliRun run = runCadlod({"convert", std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz", "-o",
                                  output, "--unit", "mm", "--report", dir + "/sample.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/sample.json"));
    EXPECT_GE(report.at("hlod").at("chunkedParts").get<int>(), 2);
    EXPECT_NE(readFile(output).find("HOUSING chunk long"), std::string::npos);
    const OsgViewProbe osg(output, "sample");
    ASSERT_TRUE(osg.loaded());
    const HoleCheck holes(osg);
    ASSERT_GT(holes.samples.size(), 10000u);
    for (const Point3& eye : eyePoints(osg.bounds()))
        expectWithinTheBoundWithoutHoles(osg.drawFrom(eye, &holes.query), eye);
}

// The parts' chains and the clusters' proxies run at once on several threads; what they make
// does not depend on how many, nor on which ran first: the same file and the same chains as
// on one thread. 32 distinct parts with creases, so that the simplifications overlap.
TEST(CliHierarchicalLod, TheSameFileOnOneThreadOrTwo)
{
    const std::string dir = freshDirectory("hlod_threads");
    const std::string input = writeUnsharedGrid(dir);
    for (const char* threads : {"1", "2"}) {
        const std::string name = freshDirectory(std::string("hlod_threads/on") + threads) + "/assembly";  // one name
        const CliRun run = runCadlod({"convert", input, "-o", name + ".flt", "--cluster-parts", "4", "--threads",
                                      threads, "--report", name + ".json"});
        ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    }
    const std::string one = afterHeader(readFile(dir + "/on1/assembly.flt"));
    const std::string two = afterHeader(readFile(dir + "/on2/assembly.flt"));
    ASSERT_GT(one.size(), 1000u);
    EXPECT_TRUE(one == two) << one.size() << " bytes on one thread, " << two.size() << " on two";
    const nlohmann::json parts1 = nlohmann::json::parse(readFile(dir + "/on1/assembly.json")).at("parts");
    const nlohmann::json parts2 = nlohmann::json::parse(readFile(dir + "/on2/assembly.json")).at("parts");
    ASSERT_EQ(parts1.size(), 32u);
    ASSERT_EQ(parts2.size(), 32u);
    int featureBreaks = 0;
    for (std::size_t p = 0; p < parts1.size(); ++p) {
        const nlohmann::json &levels1 = parts1[p].at("levels"), &levels2 = parts2[p].at("levels");
        ASSERT_EQ(levels1.size(), levels2.size()) << parts1[p].at("name");
        for (std::size_t k = 1; k < levels1.size(); ++k) {
            const nlohmann::json &a = levels1[k].at("simplification"), &b = levels2[k].at("simplification");
            EXPECT_EQ(a.at("featureBreaks"), b.at("featureBreaks")) << parts1[p].at("name") << " level " << k;
            featureBreaks += a.at("featureBreaks").get<int>();
        }
    }
    EXPECT_GT(featureBreaks, 0);  // the creases were marked, on every thread
}

}  // namespace cadlod::test

namespace cadlod::test {
namespace {

using flt::Vec3d;

// A level where a matrix puts it.
flt::Level moved(flt::Level level, const flt::Mat4d& m)
{
    for (flt::Part& part : level.parts)
        for (Vec3d& v : part.positions) {
            Vec3d w{};
            for (int r = 0; r < 3; ++r)
                w[r] = m[r][0] * v[0] + m[r][1] * v[1] + m[r][2] * v[2] + m[r][3];
            v = w;
        }
    return level;
}

// A part's finest level where a placement puts it.
flt::Level placedLevel(const flt::InstancedModel& model, const flt::PartPlacement& p)
{
    flt::Level level = moved(model.definitions[p.definition].levels.front(), p.matrix);
    for (flt::Part& part : level.parts)
        if (p.mirrored())
            for (flt::Triangle& t : part.triangles)
                std::swap(t[1], t[2]);
    return level;
}

// The finest levels of every placement cluster n stands for, its own and its children's.
void addPlacedParts(const flt::InstancedModel& model, std::size_t n, CoreMesh& m)
{
    const flt::PlacementCluster& cluster = model.clusters[n];
    for (std::size_t p : cluster.placements)
        mesh_io::levelToMesh(placedLevel(model, model.placements[p]), m);
    for (std::size_t child : cluster.clusters)
        addPlacedParts(model, child, m);
}

void readyForMeasure(CoreMesh& m)
{
    vcg::tri::UpdateNormal<CoreMesh>::PerFaceNormalized(m);
    vcg::tri::UpdateBounding<CoreMesh>::Box(m);
}

LodSetResult chainFrom(CoreMesh& m, LevelStore& store, const ProxyRange& range, vcg::CallBackPos* = nullptr)
{
    LodChainOptions o;
    o.nearestDistance = range.nearest;
    o.farthestDistance = range.farthest;
    CoreMesh scratch;
    return buildLodChain<CoreMesh>(m, scratch, o, [&](int) -> CoreMesh& { return store.add(); });
}

// Every proxy measured against the parts it replaces, at their finest: its symmetric
// Hausdorff distance to them is within what it may show where it is switched in, one pixel
// at the cluster's nearest point (switchAtNearestPoint), with 5 % sampling slack. Returns
// how many proxies were measured.
std::size_t expectEveryProxyWithinItsError(const flt::InstancedModel& model, const ViewParams& view)
{
    const double pixelAtOne = 1.0 / projectedErrorDistance(1.0, view);
    std::size_t measured = 0;
    for (std::size_t n = 0; n < model.clusters.size(); ++n) {
        const flt::PlacementCluster& cluster = model.clusters[n];
        if (cluster.proxies.empty())
            continue;
        CoreMesh parts;
        addPlacedParts(model, n, parts);
        readyForMeasure(parts);
        for (std::size_t i = 0; i < cluster.proxies.size(); ++i) {
            const flt::Level& proxy = cluster.proxies[i];
            const flt::Level shape = moved(model.proxyShapes.at(cluster.shapes.at(i)), cluster.move);
            CoreMesh drawn;
            mesh_io::levelToMesh(shape, drawn);
            readyForMeasure(drawn);
            const double error = symmetricHausdorff(parts, drawn, 20000).max();
            const double reach = shape.reachFrom(cluster.center);
            EXPECT_LE(error, 1.05 * (proxy.switchOut - reach) * pixelAtOne) << proxy.name;
            ++measured;
        }
    }
    return measured;
}

AssemblyConversion convertFile(const std::string& path)
{
    vrml::ImportOptions keep;
    keep.instances = vrml::Instances::Keep;
    vrml::ImportResult imported = vrml::importVrmlFile(path, keep);
    if (!imported.ok())
        throw std::runtime_error(imported.error);
    return convertAssembly(
        imported.scene, "grid", PartWelding{},
        [](CoreMesh& m, LevelStore& store, vcg::CallBackPos*) { return chainFrom(m, store, {}); }, true);
}

AssemblyConversion convertGrid(const std::string& dir)
{
    return convertFile(writeGrid(dir));
}

}  // namespace

TEST(CliHierarchicalLod, EveryProxyIsWithinItsErrorOfThePartsItReplaces)
{
    AssemblyConversion c = convertGrid(freshDirectory("hlod_proxies"));
    HierarchyOptions options;
    options.tree.leafItems = 16;
    const HierarchyStats stats = buildHierarchy(c, options, PartWelding{}, chainFrom);
    ASSERT_GE(stats.proxyLevels, 2u);
    // The grid's clusters repeat each other: most get their proxies moved from a copy's, and
    // are measured where they stand, against their own parts.
    EXPECT_GE(stats.copied, 4u);
    EXPECT_EQ(expectEveryProxyWithinItsError(c.model, options.view), stats.proxyLevels);
}

// More stations than a node has children, their boxes overlapping: the tree groups whole
// stations, each plate with its knobs, so every station is a cluster and all but the first
// are its copies.
TEST(CliHierarchicalLod, StationsAlongABeamAreClustersOfTheirOwnAndCopies)
{
    AssemblyConversion c = convertFile(writeStations(freshDirectory("hlod_stations")));
    HierarchyOptions options;
    options.tree.leafItems = 8;
    const HierarchyStats stats = buildHierarchy(c, options, PartWelding{}, chainFrom);
    std::map<std::string, std::set<std::size_t>> leavesOfStation;
    for (std::size_t k = 0; k < c.model.clusters.size(); ++k)
        if (c.model.clusters[k].clusters.empty())
            for (std::size_t p : c.model.clusters[k].placements) {
                const std::string& name = c.model.placements[p].name;
                leavesOfStation[name.substr(0, name.find('/'))].insert(k);
            }
    for (int k = 0; k < 12; ++k)
        EXPECT_EQ(leavesOfStation["Station_" + std::to_string(k)].size(), 1u) << "station " << k << " is cut";
    EXPECT_GE(stats.copied, 11u);
    EXPECT_EQ(expectEveryProxyWithinItsError(c.model, options.view), stats.proxyLevels);
}

// Rows turned half round, written with 8 decimals, or by 30 degrees, are copies of the
// first row turned: their proxies are the first row's, turned and moved, drawn from its
// centre moved. Measured where they stand against their own parts, whose pins point
// another way, they hold their error.
TEST(CliHierarchicalLod, ProxiesOfTurnedCopiesAreWithinTheirErrorWhereTheyStand)
{
    for (const auto& [shift, turn] : {std::pair<std::string, std::string>{"0.56", "3.14159265"}, {"0", "0.52359878"}}) {
        AssemblyConversion c = convertFile(writeTurnedRows(freshDirectory("hlod_turned"), shift, turn));
        HierarchyOptions options;
        options.tree.leafItems = 8;
        const HierarchyStats stats = buildHierarchy(c, options, PartWelding{}, chainFrom);
        ASSERT_GE(stats.proxyLevels, 2u) << turn;
        EXPECT_GE(stats.turned, 3u) << turn;
        EXPECT_GE(stats.copied, stats.turned + 3) << turn;
        EXPECT_EQ(expectEveryProxyWithinItsError(c.model, options.view), stats.proxyLevels) << turn;
    }
}

// Rows seen in a mirror are copies of the first row by a mirror (the pins, off centre along
// both axes, tell a mirror from a half turn): their proxies are the first row's mirrored,
// and hold their error where they stand.
TEST(CliHierarchicalLod, ProxiesOfMirroredCopiesAreWithinTheirErrorWhereTheyStand)
{
    AssemblyConversion c = convertFile(writeTurnedRows(freshDirectory("hlod_mirrored"), "0.56", "mirror"));
    HierarchyOptions options;
    options.tree.leafItems = 8;
    const HierarchyStats stats = buildHierarchy(c, options, PartWelding{}, chainFrom);
    ASSERT_GE(stats.proxyLevels, 2u);
    EXPECT_GE(stats.mirrored, 3u);
    EXPECT_EQ(stats.turned, 0u);
    EXPECT_GE(stats.copied, stats.mirrored + 3);
    EXPECT_EQ(expectEveryProxyWithinItsError(c.model, options.view), stats.proxyLevels);
}

// The fewest-calls mode's merged proxies hold each part at a level chosen for some distance:
// measured against the parts at their finest, each is within what it may show from where it
// is drawn, so no part in it shows a coarser level than its own bound allows there.
TEST(CliHierarchicalLod, EveryMergedProxyIsWithinItsErrorOfThePartsItReplaces)
{
    AssemblyConversion c = convertGrid(freshDirectory("hlod_merged_proxies"));
    HierarchyOptions options;
    options.tree = kFewestCallsTree;
    options.fewestCalls = true;
    const HierarchyStats stats = buildHierarchy(c, options, PartWelding{}, chainFrom);
    ASSERT_GE(stats.proxyLevels, 100u);  // a merged proxy on most of the 127 clusters
    EXPECT_EQ(expectEveryProxyWithinItsError(c.model, options.view), stats.proxyLevels);
    // Of the clusters of 48 placements or more, the root (128) is simplified as well; its
    // children (64 each), one depth below, are drawn merged only.
    EXPECT_GE(c.model.clusters[0].proxies.size(), 2u);
    for (std::size_t child : c.model.clusters[0].clusters)
        EXPECT_LE(c.model.clusters[child].proxies.size(), 1u) << c.model.clusters[child].name;
    // A cluster is merged again 1.5 times farther, its pieces coarser, until its parent's
    // proxy may take over: each of its proxies lighter than the one before.
    std::size_t mergedAgain = 0;
    for (std::size_t n = 1; n < c.model.clusters.size(); ++n) {
        const flt::PlacementCluster& cluster = c.model.clusters[n];
        mergedAgain += cluster.proxies.size() > 1;
        for (std::size_t i = 1; i < cluster.shapes.size(); ++i)
            EXPECT_LE(c.model.proxyShapes[cluster.shapes[i]].triangleCount(),
                      c.model.proxyShapes[cluster.shapes[i - 1]].triangleCount())
                << cluster.name << " proxy " << i + 1;
    }
    EXPECT_GE(mergedAgain, 8u);
}

// A board of `columns` x 20 chips, one Box DEF'd once and USE'd, 1 cm apart.
std::string writeBoardOfChips(const std::string& dir, int columns)
{
    std::ostringstream text;
    text << "#VRML V2.0 utf8\n";
    for (int y = 0, n = 0; y < 20; ++y)
        for (int x = 0; x < columns; ++x, ++n)
            text << "DEF C" << n << " Transform { translation " << 0.01 * x << ' ' << 0.01 * y << " 0 children "
                 << (n == 0 ? "DEF CHIP Shape { geometry Box { size 0.006 0.004 0.002 } }" : "USE CHIP") << " }\n";
    const std::string path = dir + "/chips" + std::to_string(columns) + ".wrl";
    std::ofstream(path) << text.str();
    return path;
}

// --hlod auto clusters an assembly of more placements than a frame's draw calls
// (kDrawCallBudget) for the fewest draw calls, a smaller one for its instances: each file
// is the chosen mode's, byte for byte after the header, and not the other's.
TEST(CliHierarchicalLod, AutoDrawsTheFewestCallsAboveTheDrawCallBudget)
{
    const std::string dir = freshDirectory("hlod_budget");
    for (const int columns : {20, 21}) {  // 400 placements, then 420
        const std::string input = writeBoardOfChips(dir, columns);
        std::map<std::string, std::string> files;
        for (const char* mode : {"auto", "calls", "instances"}) {
            const std::string out = freshDirectory("hlod_budget/" + std::to_string(columns) + mode) + "/board";
            const CliRun run =
                runCadlod({"convert", input, "-o", out + ".flt", "--hlod", mode, "--report", out + ".json"});
            ASSERT_EQ(run.exitCode, 0) << run.stderrText;
            files[mode] = afterHeader(readFile(out + ".flt"));
        }
        const std::string chosen = 20 * std::size_t(columns) > kDrawCallBudget ? "calls" : "instances";
        const std::string other = chosen == "calls" ? "instances" : "calls";
        const nlohmann::json hlod =
            nlohmann::json::parse(readFile(dir + "/" + std::to_string(columns) + "auto/board.json")).at("hlod");
        EXPECT_EQ(hlod.at("mode"), "auto");
        EXPECT_EQ(hlod.at("tree"), chosen) << columns;
        EXPECT_EQ(hlod.at("clusterParts").get<int>(), chosen == "calls" ? 2 : 48);
        ASSERT_GT(files["auto"].size(), 1000u);
        EXPECT_TRUE(files["auto"] == files[chosen]) << columns << " columns: not the " << chosen << " file";
        EXPECT_FALSE(files["auto"] == files[other]) << columns << " columns";
    }
}

// A simplified proxy takes each piece in its lightest form within what it may show: a child
// whose merged proxy keeps its parts at levels chosen for a nearer eye enters as its own
// pieces where those are lighter. The root of the grid is its one simplified cluster (128
// placements; its children, 64 each, are merged only), so its input is never heavier than
// every part at the coarsest level within the root proxy's allowance.
TEST(CliHierarchicalLod, ASimplifiedProxyTakesEachPieceInItsLightestForm)
{
    AssemblyConversion c = convertGrid(freshDirectory("hlod_lightest_input"));
    Box3 box;
    for (const flt::PartPlacement& p : c.model.placements)
        for (const flt::Part& part : placedLevel(c.model, p).parts)
            for (const Vec3d& v : part.positions)
                box.add(v);
    HierarchyOptions options;
    options.tree = kFewestCallsTree;
    options.fewestCalls = true;
    const HierarchyStats stats = buildHierarchy(c, options, PartWelding{}, chainFrom);
    const double radius = box.halfDiagonal();
    const double allowance =
        kProxyInputShare * detail::errorBudgetAt(switchAtNearestPoint(0.0, radius) - radius, options.view);
    std::size_t coarsest = 0;
    for (const flt::PartPlacement& p : c.model.placements) {
        const std::vector<flt::Level>& levels = c.model.definitions[p.definition].levels;
        const std::vector<LodLevel>& measured = c.parts[p.definition].result.levels;
        std::size_t best = 0;
        for (std::size_t k = 1; k < levels.size() && k < measured.size(); ++k)
            if (flt::largestScale(p.matrix) * measured[k].hausdorffMax <= allowance)
                best = k;
        coarsest += levels[best].triangleCount();
    }
    ASSERT_GT(stats.inputTriangles, 0u);
    EXPECT_LE(stats.inputTriangles, coarsest);
}

}  // namespace cadlod::test
