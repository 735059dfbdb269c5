#include "measure/compactness.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

using P = std::array<double, 3>;
using cadlod::compactness;

namespace {
// Independent formulation: Heron's formula for the area.
double heronCompactness(P a, P b, P c)
{
    auto len = [](P u, P v) {
        return std::sqrt((u[0] - v[0]) * (u[0] - v[0]) + (u[1] - v[1]) * (u[1] - v[1]) +
                         (u[2] - v[2]) * (u[2] - v[2]));
    };
    const double x = len(a, b), y = len(b, c), z = len(c, a);
    const double s = 0.5 * (x + y + z);
    const double area = std::sqrt(std::max(0.0, s * (s - x) * (s - y) * (s - z)));
    return 4.0 * std::sqrt(3.0) * area / (x * x + y * y + z * z);
}
}  // namespace

TEST(Compactness, EquilateralIsOne)
{
    EXPECT_NEAR(compactness(P{0, 0, 0}, P{1, 0, 0}, P{0.5, std::sqrt(3.0) / 2, 0}), 1.0, 1e-12);
}

TEST(Compactness, RightIsoscelesMatchesClosedForm)
{
    // A = 1/2, sum of squared edges = 1 + 1 + 2 = 4 -> c = 4*sqrt(3)*0.5/4 = sqrt(3)/2
    EXPECT_NEAR(compactness(P{0, 0, 0}, P{1, 0, 0}, P{0, 1, 0}), std::sqrt(3.0) / 2, 1e-12);
}

TEST(Compactness, InvariantUnderScaleRotationAndVertexOrder)
{
    const P a{0.3, -1.2, 2.0}, b{4.0, 0.5, -1.0}, c{-2.0, 3.0, 0.7};
    const double ref = compactness(a, b, c);
    EXPECT_NEAR(compactness(b, c, a), ref, 1e-12);
    EXPECT_NEAR(compactness(c, b, a), ref, 1e-12);
    auto scaled = [](P p) { return P{p[0] * 1000, p[1] * 1000, p[2] * 1000}; };
    EXPECT_NEAR(compactness(scaled(a), scaled(b), scaled(c)), ref, 1e-12);
    auto rotZ = [](P p) { return P{-p[1], p[0], p[2]}; };
    EXPECT_NEAR(compactness(rotZ(a), rotZ(b), rotZ(c)), ref, 1e-12);
}

TEST(Compactness, AgreesWithHeronOnRandomTriangles)
{
    unsigned seed = 12345;
    auto next = [&seed]() {
        seed = seed * 1103515245u + 12345u;
        return double((seed >> 8) & 0xFFFF) / 65535.0 * 10.0 - 5.0;
    };
    for (int i = 0; i < 1000; ++i) {
        P a{next(), next(), next()}, b{next(), next(), next()}, c{next(), next(), next()};
        EXPECT_NEAR(compactness(a, b, c), heronCompactness(a, b, c), 1e-6);
    }
}

TEST(Compactness, SliverIsSmall)
{
    EXPECT_LT(compactness(P{0, 0, 0}, P{100, 0, 0}, P{50, 0.5, 0}), 0.02);
}

TEST(Compactness, DegenerateFacesAreZero)
{
    EXPECT_EQ(compactness(P{0, 0, 0}, P{1, 1, 1}, P{2, 2, 2}), 0.0);    // collinear
    EXPECT_EQ(compactness(P{1, 2, 3}, P{1, 2, 3}, P{1, 2, 3}), 0.0);    // one point
    EXPECT_EQ(compactness(P{0, 0, 0}, P{0, 0, 0}, P{1, 0, 0}), 0.0);    // two coincide
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(compactness(P{nan, 0, 0}, P{1, 0, 0}, P{0, 1, 0}), 0.0);
    EXPECT_EQ(compactness(P{inf, 0, 0}, P{1, 0, 0}, P{0, 1, 0}), 0.0);
}

TEST(Compactness, FloatInputsAreComputedInDouble)
{
    using Pf = std::array<float, 3>;
    // A thin but valid float triangle far from the origin.
    const Pf a{1000.0f, 1000.0f, 0.0f}, b{1001.0f, 1000.0f, 0.0f}, c{1000.5f, 1000.001f, 0.0f};
    const double expected = heronCompactness(P{1000, 1000, 0}, P{1001, 1000, 0},
                                             P{1000.5, double(1000.001f), 0});
    EXPECT_NEAR(compactness(a, b, c), expected, 1e-6);
    EXPECT_GT(compactness(a, b, c), 0.0);
}

TEST(CompactnessStats, SummarizesMeanMinPercentileAndShares)
{
    std::vector<double> v;
    for (int i = 0; i < 100; ++i)
        v.push_back(i / 100.0);  // 0.00 .. 0.99
    const cadlod::CompactnessStats s = cadlod::summarizeCompactness(v);
    EXPECT_EQ(s.faces, 100u);
    EXPECT_NEAR(s.mean, 0.495, 1e-12);
    EXPECT_EQ(s.min, 0.0);
    EXPECT_NEAR(s.p5, 0.04, 1e-12);  // nearest rank: 5th of 100 sorted values
    EXPECT_NEAR(s.shareBelow01, 0.10, 1e-12);
    EXPECT_NEAR(s.shareBelow03, 0.30, 1e-12);
}

TEST(CompactnessStats, EmptyAndSingle)
{
    std::vector<double> none;
    EXPECT_EQ(cadlod::summarizeCompactness(none).faces, 0u);
    std::vector<double> one{0.7};
    const auto s = cadlod::summarizeCompactness(one);
    EXPECT_EQ(s.p5, 0.7);
    EXPECT_EQ(s.min, 0.7);
    EXPECT_EQ(s.shareBelow03, 0.0);
}
