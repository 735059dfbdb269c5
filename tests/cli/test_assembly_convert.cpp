// cadlod convert on an assembly that shares parts (Inline files, USE'd groups, a mirror):
// read back with OpenSceneGraph, level 0 draws exactly what the expanded file holds, every
// placement is a named node of its own where the file puts it, and each distinct part and
// level is one subgraph, shared.
#include "cli_runner.h"
#include "osg_assembly_probe.h"

#include "assembly/stretched_placements.h"
#include "lod/nearest_point.h"
#include "vrml/importer.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>

namespace cadlod::test {
namespace {

using Box = std::pair<std::array<double, 3>, std::array<double, 3>>;

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// Two part files placed by Inline; a board of parts DEF'd once and USE'd; one part mirrored.
std::string writeAssembly(const std::string& dir)
{
    write(dir + "/knob.wrl", "#VRML V2.0 utf8\nShape { geometry Sphere { radius 2 } }\n"
                             "Transform { translation 0 0 2 children Shape { geometry Cylinder { radius 0.5 height 3 } } }\n");
    write(dir + "/bracket.wrl", "#VRML V2.0 utf8\nShape { appearance Appearance { material Material { diffuseColor 1 0 0 } }\n"
                                "  geometry IndexedFaceSet { coord Coordinate { point [0 0 0, 4 0 0, 4 1 0, 0 1 0, "
                                "0 0 3, 4 0 3, 4 1 3, 0 1 3] }\n  coordIndex [0 3 2 1 -1 4 5 6 7 -1 0 1 5 4 -1 "
                                "1 2 6 5 -1 2 3 7 6 -1 3 0 4 7 -1] } }\n");
    write(dir + "/asm.wrl", "#VRML V2.0 utf8\n"
                            "DEF BOARD Group { children [\n"
                            "  Shape { geometry Box { size 30 20 1 } }\n"
                            "  DEF K1 Transform { translation -8 0 1 children Inline { url \"knob.wrl\" } }\n"
                            "  DEF K2 Transform { translation 8 0 1 rotation 0 0 1 0.7 children Inline { url \"knob.wrl\" } }\n"
                            "  DEF B1 Transform { translation 0 5 1 children Inline { url \"bracket.wrl\" } }\n"
                            "  DEF B2 Transform { translation 0 -5 1 scale -1 1 1 children Inline { url \"bracket.wrl\" } }\n"
                            "] }\n"
                            "DEF Board_2 Transform { translation 0 0 40 children USE BOARD }\n"
                            "DEF Board_3 Transform { translation 50 0 0 rotation 1 0 0 1.5708 scale 2 2 2 children USE BOARD }\n");
    return dir + "/asm.wrl";
}

vrml::Scene importAt(const std::string& path, vrml::Instances instances)
{
    vrml::ImportOptions o;
    o.unitScale = 0.001;
    o.instances = instances;
    vrml::ImportResult r = vrml::importVrmlFile(path, o);
    EXPECT_TRUE(r.ok()) << r.error;
    return std::move(r.scene);
}

std::map<std::string, Box> placementBoxes(const vrml::Scene& kept)
{
    std::map<std::string, Box> out;
    for (const vrml::Placement& p : vrml::flattenPlacements(kept.assembly, "asm")) {
        Box b{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
        for (const vrml::Part& part : kept.assembly.geometries[p.geometry].parts)
            for (const auto& v : part.positions) {
                const vrml::Vec3 w = p.matrix.transformPoint({v[0], v[1], v[2]});
                const double c[3] = {w.x, w.y, w.z};
                for (int k = 0; k < 3; ++k) {
                    b.first[k] = std::min(b.first[k], c[k]);
                    b.second[k] = std::max(b.second[k], c[k]);
                }
            }
        out[p.path] = b;
    }
    return out;
}

std::multiset<std::array<long, 3>> centroids(const std::vector<std::array<std::array<double, 3>, 3>>& triangles,
                                             double grid)
{
    std::multiset<std::array<long, 3>> out;
    for (const auto& t : triangles)
        out.insert({std::lround((t[0][0] + t[1][0] + t[2][0]) / 3 / grid),
                    std::lround((t[0][1] + t[1][1] + t[2][1]) / 3 / grid),
                    std::lround((t[0][2] + t[1][2] + t[2][2]) / 3 / grid)});
    return out;
}

std::vector<std::array<std::array<double, 3>, 3>> expandedTriangles(const vrml::Scene& s)
{
    std::vector<std::array<std::array<double, 3>, 3>> out;
    for (const vrml::Part& p : s.parts)
        for (std::size_t t = 0; t < p.triangleCount(); ++t) {
            std::array<std::array<double, 3>, 3> tri{};
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 3; ++c)
                    tri[k][c] = p.positions[p.triangles[3 * t + k]][c];
            out.push_back(tri);
        }
    return out;
}

}  // namespace

TEST(CliAssembly, InstancesKeptDrawTheExpandedModelWithEveryPlacementNamedAndEachPartShared)
{
    const std::string dir = freshDirectory("assembly");
    const std::string input = writeAssembly(dir);
    const CliRun run = runCadlod({"convert", input, "-o", dir + "/asm.flt", "--unit", "mm", "--report",
                                  dir + "/asm.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/asm.json"));
    const vrml::Scene kept = importAt(input, vrml::Instances::Keep);
    const vrml::Scene expanded = importAt(input, vrml::Instances::Expand);
    const OsgAssemblyProbe osg = probeAssemblyWithOsg(dir + "/asm.flt", "asm");
    ASSERT_TRUE(osg.loaded);

    // Level 0 draws exactly the input's triangles, where expanding puts them.
    const std::vector<std::array<std::array<double, 3>, 3>> input3 = expandedTriangles(expanded);
    EXPECT_EQ(osg.finestTriangles.size(), input3.size());
    EXPECT_EQ(centroids(osg.finestTriangles, 1e-5), centroids(input3, 1e-5));

    // Every placement a named node of its own, its box where the file puts it.
    const std::map<std::string, Box> boxes = placementBoxes(kept);
    EXPECT_EQ(boxes.size(), 15u);  // 3 boards x (the board + 4 parts)
    EXPECT_EQ(osg.placements.size(), boxes.size());
    EXPECT_EQ(report.at("output").at("placements").get<std::size_t>(), boxes.size());
    const double diagonal = 0.1;  // the assembly's, in metres: about 0.08
    for (const auto& [name, box] : boxes) {
        ASSERT_EQ(osg.placements.count(name), 1u) << name;
        const OsgNamedNode& n = osg.placements.at(name);
        EXPECT_EQ(n.visits, 1u) << name;
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(n.min[c], box.first[c], 1e-5 * diagonal) << name;
            EXPECT_NEAR(n.max[c], box.second[c], 1e-5 * diagonal) << name;
        }
    }

    // One subgraph per distinct part and level: the knob and the plain bracket shared, the
    // mirrored bracket (one per board, so shared as well) apart, the board's own box placed 3x;
    // and the clusters' near ranges and proxies.
    std::size_t levels = 0;
    for (const auto& part : report.at("parts"))
        levels += part.at("levels").size() * (part.at("name") == "bracket" ? 2 : 1);
    const nlohmann::json& hlod = report.at("hlod");
    EXPECT_GE(hlod.at("withProxies").get<std::size_t>(), 1u);
    levels += hlod.at("proxyLevels").get<std::size_t>() + hlod.at("withProxies").get<std::size_t>();
    EXPECT_EQ(osg.lodSubgraphs, levels);
    EXPECT_EQ(report.at("output").at("instanceDefinitions").get<std::size_t>(), 4u);
    EXPECT_GE(osg.sharedNodes, 4u);
}

TEST(CliAssembly, InstancesExpandedWriteOneChainWithoutInstanceRecords)
{
    const std::string dir = freshDirectory("assembly_expand");
    const std::string input = writeAssembly(dir);
    const CliRun run = runCadlod({"convert", input, "-o", dir + "/asm.flt", "--unit", "mm", "--instances", "expand",
                                  "--report", dir + "/asm.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const std::string bytes = readFile(dir + "/asm.flt");
    for (std::size_t at = 0; at + 4 <= bytes.size();) {
        const unsigned op = (unsigned char)bytes[at] << 8 | (unsigned char)bytes[at + 1];
        const unsigned length = (unsigned char)bytes[at + 2] << 8 | (unsigned char)bytes[at + 3];
        EXPECT_NE(op, 61u);
        EXPECT_NE(op, 62u);
        ASSERT_GE(length, 4u);
        at += length;
    }
    const OsgAssemblyProbe osg = probeAssemblyWithOsg(dir + "/asm.flt");
    ASSERT_TRUE(osg.loaded);
    EXPECT_EQ(osg.finestTriangles.size(), expandedTriangles(importAt(input, vrml::Instances::Expand)).size());
    EXPECT_EQ(osg.sharedNodes, 0u);
}

// Placements that scale their part unevenly (along its axes, or sheared by a turn inside an
// uneven scale) get parts with the stretch built in: every triangle stays where it was, each
// matrix left is a turn or a mirror and a move, and placements stretched alike share a part.
TEST(CliAssembly, StretchedPlacementsKeepEveryTriangleWhereItWas)
{
    const std::string dir = freshDirectory("assembly_stretched");
    write(dir + "/knob.wrl", "#VRML V2.0 utf8\nShape { geometry Sphere { radius 2 } }\n"
                             "Transform { translation 0 0 2 children Shape { geometry Cylinder { radius 0.5 height 3 } } }\n");
    write(dir + "/asm.wrl", "#VRML V2.0 utf8\n"
                            "DEF A Transform { translation 10 0 0 children Inline { url \"knob.wrl\" } }\n"
                            "DEF B Transform { translation 20 0 0 scale 1 1 3 children Inline { url \"knob.wrl\" } }\n"
                            "DEF C Transform { translation 30 0 0 rotation 0 1 0 0.4 scale 1 1 3 children Inline { url \"knob.wrl\" } }\n"
                            "DEF D Transform { translation 40 0 0 scale -1 1 3 children Inline { url \"knob.wrl\" } }\n"
                            "DEF E Transform { scale 1 2 1 children Transform { translation 50 0 0 rotation 0 0 1 0.7 "
                            "children Inline { url \"knob.wrl\" } } }\n"
                            "DEF F Transform { translation 60 0 0 scale 2 2 2 children Inline { url \"knob.wrl\" } }\n");
    vrml::Scene scene = importAt(dir + "/asm.wrl", vrml::Instances::Keep);
    std::vector<vrml::Placement> placements = vrml::flattenPlacements(scene.assembly, "asm");
    ASSERT_EQ(placements.size(), 6u);
    const auto worldTriangles = [&](const std::vector<vrml::Placement>& all) {
        std::vector<std::array<std::array<double, 3>, 3>> out;
        for (const vrml::Placement& p : all)
            for (const vrml::Part& part : scene.assembly.geometries[p.geometry].parts)
                for (std::size_t t = 0; t < part.triangleCount(); ++t) {
                    std::array<std::array<double, 3>, 3> tri{};
                    for (int k = 0; k < 3; ++k) {
                        const auto& v = part.positions[part.triangles[3 * t + k]];
                        const vrml::Vec3 w = p.matrix.transformPoint({v[0], v[1], v[2]});
                        tri[k] = {w.x, w.y, w.z};
                    }
                    out.push_back(tri);
                }
        return out;
    };
    const auto before = worldTriangles(placements);
    const std::size_t knob = placements[0].geometry;

    EXPECT_EQ(buildStretchesIn(scene.assembly, placements), 4u);  // B, C turned after, D mirrored, E sheared
    const auto after = worldTriangles(placements);
    ASSERT_EQ(after.size(), before.size());
    double moved = 0;
    for (std::size_t t = 0; t < before.size(); ++t)
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c)
                moved = std::max(moved, std::abs(after[t][k][c] - before[t][k][c]));
    EXPECT_LT(moved, 1e-5);  // the float positions' rounding, in millimetres of a 60 mm model

    EXPECT_EQ(placements[0].geometry, knob);  // plain
    EXPECT_EQ(placements[5].geometry, knob);  // scaled evenly
    EXPECT_NE(placements[1].geometry, knob);
    EXPECT_EQ(placements[1].geometry, placements[2].geometry);  // stretched alike, then turned
    EXPECT_EQ(placements[1].geometry, placements[3].geometry);  // stretched alike, then mirrored
    EXPECT_NE(placements[4].geometry, knob);
    EXPECT_NE(placements[4].geometry, placements[1].geometry);
    EXPECT_TRUE(placements[3].mirrored());
    for (std::size_t i = 1; i < 5; ++i)
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                double dot = 0;  // the matrix times its transpose: the identity for a turn or a mirror
                for (int k = 0; k < 3; ++k)
                    dot += placements[i].matrix.m[r][k] * placements[i].matrix.m[c][k];
                EXPECT_NEAR(dot, r == c ? 1.0 : 0.0, 1e-9) << placements[i].path;
            }
    EXPECT_EQ(scene.assembly.geometries[placements[1].geometry].name, "knob stretched");
}

// Site coordinates: the assembly (lengths in mm) 5,000 km off, where a float is 0.5 m coarse,
// at a translation no float holds. The reader keeps it in double precision, and the file is
// written about a local origin that its root Group's Matrix restores, so OSG puts every
// placement where it belongs, as near as it does for the assembly at the origin.
TEST(CliAssembly, PlacementsFarFromTheOriginStandWhereTheyBelong)
{
    const std::string dir = freshDirectory("assembly_far");
    writeAssembly(dir);
    write(dir + "/site.wrl", "#VRML V2.0 utf8\nTransform { translation 5080123456.7 2000000123.4 0 children Inline { url \"asm.wrl\" } }\n");
    const auto convert = [&](const std::string& name, const std::string& hlod) {
        const std::string out = dir + "/" + name + "_" + hlod;
        const CliRun run = runCadlod({"convert", dir + "/" + name + ".wrl", "-o", out + ".flt", "--unit", "mm",
                                      "--hlod", hlod, "--report", out + ".json"});
        EXPECT_EQ(run.exitCode, 0) << run.stderrText;
        const nlohmann::json report = nlohmann::json::parse(readFile(out + ".json"));
        const bool far = name == "site";
        const std::string printed = run.stdoutText + run.stderrText;
        EXPECT_EQ(printed.find("local origin") != std::string::npos, far) << printed;
        EXPECT_EQ(report.contains("notes"), far) << report.dump();
        const std::vector<double> origin = report.at("output").at("origin");  // in metres, near the site's
        EXPECT_EQ(std::hypot(origin.at(0) - 5080123.4567, origin.at(1) - 2000000.1234, origin.at(2)) < 1, far);
        EXPECT_EQ(origin == std::vector<double>(3, 0.0), !far);
        const OsgAssemblyProbe osg = probeAssemblyWithOsg(out + ".flt", name + "_" + hlod);
        EXPECT_TRUE(osg.loaded);
        return osg.placements;
    };
    for (const std::string hlod : {"auto", "off"}) {
        const std::map<std::string, OsgNamedNode> near = convert("asm", hlod);
        const std::map<std::string, OsgNamedNode> far = convert("site", hlod);
        ASSERT_EQ(near.size(), 15u) << hlod;
        ASSERT_EQ(far.size(), near.size()) << hlod;
        const std::array<double, 3> offset{5080123.4567, 2000000.1234, 0};
        for (const auto& [name, placed] : near) {
            ASSERT_EQ(far.count("asm/" + name), 1u) << name;  // the site's paths go through its Inline
            const OsgNamedNode& moved = far.at("asm/" + name);
            EXPECT_EQ(moved.triangles, placed.triangles) << name;
            for (int a = 0; a < 3; ++a) {  // to a micrometre, where floats there are 0.5 m apart
                EXPECT_NEAR(moved.min[a] - offset[a], placed.min[a], 1e-6) << hlod << " " << name << " axis " << a;
                EXPECT_NEAR(moved.max[a] - offset[a], placed.max[a], 1e-6) << hlod << " " << name << " axis " << a;
            }
        }
    }
}

// A board of named parts that share nothing: each part's geometry stands where it is on the
// board, far from its own origin for a part of a millimetre, yet near enough for floats to
// hold it to a pixel's share. Nothing is moved, and no note says the model is far off.
TEST(CliAssembly, SmallPartsAcrossABoardAreNotMovedAboutALocalOrigin)
{
    const std::string dir = freshDirectory("assembly_board_origin");
    write(dir + "/board.wrl", "#VRML V2.0 utf8\n"
                              "DEF BOARD Shape { geometry Box { size 400 300 2 } }\n"
                              "DEF SCREW Transform { translation 190 140 2 children Shape { geometry Cylinder { "
                              "radius 0.5 height 1 } } }\n"
                              "DEF PIN Transform { translation -190 -140 2 children Shape { geometry Box { "
                              "size 0.6 0.6 1 } } }\n");
    const CliRun run = runCadlod({"convert", dir + "/board.wrl", "-o", dir + "/board.flt", "--unit", "mm", "--report",
                                  dir + "/board.json"});
    ASSERT_EQ(run.exitCode, 0) << run.stderrText;
    const nlohmann::json report = nlohmann::json::parse(readFile(dir + "/board.json"));
    EXPECT_EQ(report.at("input").at("placements"), 3);
    EXPECT_EQ(report.at("output").at("origin"), nlohmann::json::array({0.0, 0.0, 0.0}));
    EXPECT_FALSE(report.contains("notes")) << report.dump();
    EXPECT_EQ((run.stdoutText + run.stderrText).find("local origin"), std::string::npos);
}

TEST(CliAssembly, TooManyPlacementsFailWithoutOutput)
{
    const std::string dir = freshDirectory("assembly_bomb");
    std::string text = "#VRML V2.0 utf8\nDEF L0 Shape { geometry Box {} }\n";
    for (int level = 1; level <= 7; ++level) {
        text += "DEF L" + std::to_string(level) + " Group { children [";
        for (int k = 0; k < 10; ++k)
            text += " USE L" + std::to_string(level - 1);
        text += " ] }\n";
    }
    write(dir + "/bomb.wrl", text);
    const CliRun run = runCadlod({"convert", dir + "/bomb.wrl", "-o", dir + "/bomb.flt"});
    EXPECT_EQ(run.exitCode, 1);
    EXPECT_NE(run.stderrText.find("more than the limit"), std::string::npos) << run.stderrText;
    EXPECT_FALSE(fileExists(dir + "/bomb.flt"));
}

}  // namespace cadlod::test

namespace cadlod::test {

// A part's LOD node holds its pixel error at the part's nearest point (nearest_point.h):
// each switch distance is the part's own chain's (converted alone), pushed out by how far
// the level reaches from the centre, and never nearer than kNearestPointReach times that.
TEST(CliAssembly, EveryPartSwitchesItsOwnChainWhereItHoldsAtItsNearestPoint)
{
    const std::string dir = freshDirectory("assembly_radius");
    const std::string input = writeAssembly(dir);
    ASSERT_EQ(runCadlod({"convert", input, "-o", dir + "/asm.flt", "--unit", "mm", "--report", dir + "/asm.json"})
                  .exitCode, 0);
    // The knob alone in one LOD node switched by its centre (--hlod off), as the chain plans it.
    const CliRun alone = runCadlod({"convert", dir + "/knob.wrl", "-o", dir + "/knob.flt", "--unit", "mm", "--hlod",
                                    "off", "--report", dir + "/knob.json"});
    ASSERT_EQ(alone.exitCode, 0) << alone.stderrText;
    const nlohmann::json assembly = nlohmann::json::parse(readFile(dir + "/asm.json"));
    const nlohmann::json knob = nlohmann::json::parse(readFile(dir + "/knob.json"));
    const nlohmann::json* placed = nullptr;
    for (const auto& part : assembly.at("parts"))
        if (part.at("name") == "knob")
            placed = &part;
    ASSERT_NE(placed, nullptr);
    const auto& own = knob.at("levels");
    const auto& shifted = placed->at("levels");
    ASSERT_GE(own.size(), 3u);
    ASSERT_GE(shifted.size(), 3u);
    // The knob: a sphere of 2 mm about the origin and a pin along y (VRML's cylinder axis),
    // 3 mm long, 0.5 mm thick, centred 2 mm up; its box centre is at z = 0.25 mm, its farthest
    // vertices where the pin's ends reach z = 2.5 mm, 1.5 mm out along y. A simplified level
    // reaches about as far (more than half of it); a coarse one (a box, a tetrahedron grown
    // about the centre) may reach farther, up to twice the box's half-diagonal.
    const double radius = std::hypot(0.0015, 0.00225);
    const double farthest = 2 * std::sqrt(0.002 * 0.002 + 0.002 * 0.002 + 0.00225 * 0.00225);
    EXPECT_DOUBLE_EQ(shifted[0].at("switchOut").get<double>(), 0.0);
    for (std::size_t k = 1; k < shifted.size(); ++k) {
        const double out = shifted[k].at("switchOut").get<double>();
        EXPECT_DOUBLE_EQ(shifted[k - 1].at("switchIn").get<double>(), out) << "level " << k;
        const nlohmann::json* same = nullptr;
        for (const auto& level : own)
            if (level.at("faces") == shifted[k].at("faces"))
                same = &level;
        ASSERT_NE(same, nullptr) << "level " << k << " is none of the part's own chain";
        const double ownOut = same->at("switchOut").get<double>();
        EXPECT_GE(out, switchAtNearestPoint(ownOut, radius / 2)) << "level " << k;
        EXPECT_LE(out, switchAtNearestPoint(ownOut, farthest) + 1e-9) << "level " << k;
    }
}

}  // namespace cadlod::test
