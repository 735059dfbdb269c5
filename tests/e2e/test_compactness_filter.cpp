// "Compute Triangle Compactness" through meshlabserver: the saved face quality is the
// compactness of each face, checked against an independent (Heron) computation.
#include "meshlabserver_runner.h"
#include "test_mesh.h"

#include <gtest/gtest.h>

#include <vcg/complex/algorithms/create/platonic.h>

#include <cmath>
#include <regex>

using namespace cadlod::test;

namespace {

double heronCompactness(const vcg::Point3f& a, const vcg::Point3f& b, const vcg::Point3f& c)
{
    const double x = vcg::Distance(a, b), y = vcg::Distance(b, c), z = vcg::Distance(c, a);
    const double s = 0.5 * (x + y + z);
    const double area = std::sqrt(std::max(0.0, s * (s - x) * (s - y) * (s - z)));
    const double sum = x * x + y * y + z * z;
    return sum > 0 ? 4.0 * std::sqrt(3.0) * area / sum : 0.0;
}

// A CAD-like part: a long cylinder tessellated as thin strips, plus one well-shaped
// triangle on the side.
void makeCadLikeMesh(TestMesh& m)
{
    vcg::tri::Cylinder(24, 2, m);  // slices, stacks
    for (auto& v : m.vert)
        v.P() = vcg::Point3f(v.P()[0], v.P()[1] * 20.0f, v.P()[2]);  // stretch: slivers
    auto v = vcg::tri::Allocator<TestMesh>::AddVertices(m, 3);
    v[0].P() = vcg::Point3f(5, 0, 0);
    v[1].P() = vcg::Point3f(6, 0, 0);
    v[2].P() = vcg::Point3f(5.5f, 0.8660254f, 0);
    vcg::tri::Allocator<TestMesh>::AddFace(m, &v[0], &v[1], &v[2]);
}

}  // namespace

TEST(CompactnessFilter, SavedFaceQualityIsCompactness)
{
    const std::string dir = scratchDir("compactness_filter");
    TestMesh in;
    makeCadLikeMesh(in);
    ASSERT_GT(in.fn, 40);
    ASSERT_TRUE(savePly(dir + "/in.ply", in));
    writeText(dir + "/compactness.mlx", mlxScript({mlxFilter("Compute Triangle Compactness")}));

    const ServerRun run = runMeshlabServer(
        {"-i", dir + "/in.ply", "-o", dir + "/out.ply", "-m", "fq", "-s", dir + "/compactness.mlx"});
    ASSERT_TRUE(run.ok()) << run.output;

    TestMesh out;
    int mask = 0;
    std::string error;
    ASSERT_TRUE(loadPly(dir + "/out.ply", out, mask, error)) << error;
    ASSERT_TRUE(mask & vcg::tri::io::Mask::IOM_FACEQUALITY) << "no face quality saved";
    ASSERT_EQ(out.fn, in.fn);
    double minQ = 1.0, maxQ = 0.0;
    for (const auto& f : out.face) {
        const double expected = heronCompactness(f.cP(0), f.cP(1), f.cP(2));
        EXPECT_NEAR(f.cQ(), expected, 1e-4);
        minQ = std::min(minQ, double(f.cQ()));
        maxQ = std::max(maxQ, double(f.cQ()));
    }
    EXPECT_LT(minQ, 0.2);  // the stretched side has slivers
    EXPECT_GT(maxQ, 0.5);  // the caps do not

    const std::regex line("Triangle compactness of .*\\(([0-9]+) faces\\): mean ([0-9.]+), min ([0-9.]+), "
                          "p5 ([0-9.]+), below 0\\.1: ([0-9.]+)%, below 0\\.3: ([0-9.]+)%");
    std::smatch match;
    ASSERT_TRUE(std::regex_search(run.output, match, line)) << run.output;
    EXPECT_EQ(std::stoi(match[1]), in.fn);
    EXPECT_NEAR(std::stod(match[3]), minQ, 1e-3);
}

// The faces are painted by compactness on a fixed 0..1 scale (red 0, yellow 0.5, green 1)
// and the log says so (issue 16, item 13: the filter used to leave the mesh as it was).
TEST(CompactnessFilter, FacesArePaintedRedToGreenOnAFixedScale)
{
    const std::string dir = scratchDir("compactness_colors");
    TestMesh in;
    makeCadLikeMesh(in);
    ASSERT_TRUE(savePly(dir + "/in.ply", in));
    writeText(dir + "/compactness.mlx", mlxScript({mlxFilter("Compute Triangle Compactness")}));
    const ServerRun run = runMeshlabServer(
        {"-i", dir + "/in.ply", "-o", dir + "/out.ply", "-m", "fq", "fc", "-s", dir + "/compactness.mlx"});
    ASSERT_TRUE(run.ok()) << run.output;
    EXPECT_NE(run.output.find("painted by compactness, fixed scale: red 0"), std::string::npos) << run.output;

    TestMesh out;
    int mask = 0;
    std::string error;
    ASSERT_TRUE(loadPly(dir + "/out.ply", out, mask, error)) << error;
    ASSERT_TRUE(mask & vcg::tri::io::Mask::IOM_FACECOLOR) << "no face colour saved";
    int slivers = 0, good = 0;
    for (const auto& f : out.face) {
        const double c = heronCompactness(f.cP(0), f.cP(1), f.cP(2));
        const double red = std::min(1.0, 2.0 * (1.0 - c)), green = std::min(1.0, 2.0 * c);
        EXPECT_NEAR(f.cC()[0], 255.0 * red, 2.0);
        EXPECT_NEAR(f.cC()[1], 255.0 * green, 2.0);
        EXPECT_EQ(f.cC()[2], 0);
        slivers += c < 0.1 && f.cC()[0] == 255 && f.cC()[1] < 60;
        good += c > 0.99 && f.cC()[1] == 255 && f.cC()[0] < 5;
    }
    EXPECT_GT(slivers, 10) << "the stretched cylinder's strips are red";
    EXPECT_EQ(good, 1) << "the equilateral triangle is green";
}
