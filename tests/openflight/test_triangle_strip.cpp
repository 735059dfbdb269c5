// Triangles -> one strip -> triangles gives back every triangle once, winding kept.
#include "model_fixtures.h"
#include "openflight/triangle_strip.h"

#include <gtest/gtest.h>

#include <random>

using namespace cadlod::flt;
using namespace cadlod::test;

namespace {

// Rotated so that the smallest index comes first: equal for equal windings.
std::vector<Triangle> canonical(std::vector<Triangle> ts)
{
    for (Triangle& t : ts)
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    std::sort(ts.begin(), ts.end());
    return ts;
}

}  // namespace

TEST(TriangleStrip, GridBecomesLongStrips)
{
    const Part sheet = wavySheet(30, 1.0, "s", {1, 1, 1, 1});
    const auto strip = stitchedStrip(sheet.triangles);
    EXPECT_EQ(canonical(stripTriangles(strip)), canonical(sheet.triangles));
    EXPECT_LT(strip.size(), 2 * sheet.triangles.size()) << "neighbours are chained, not joined one by one";
}

TEST(TriangleStrip, ShuffledSoupWithMixedWindingsRoundTrips)
{
    std::mt19937 rng(7);
    for (int run = 0; run < 20; ++run) {
        Part sheet = wavySheet(8, 1.0, "s", {1, 1, 1, 1});
        std::shuffle(sheet.triangles.begin(), sheet.triangles.end(), rng);
        for (Triangle& t : sheet.triangles)
            if (rng() % 3 == 0)
                std::swap(t[1], t[2]);  // flipped: its edges no longer match the neighbours'
        std::uniform_int_distribution<std::uint32_t> vertex(0, 80);
        for (int extra = 0; extra < 10; ++extra) {  // a few arbitrary triangles, some sharing edges
            const std::uint32_t a = vertex(rng), b = vertex(rng), c = vertex(rng);
            if (a != b && b != c && a != c)
                sheet.triangles.push_back({a, b, c});
        }
        EXPECT_EQ(canonical(stripTriangles(stitchedStrip(sheet.triangles))), canonical(sheet.triangles));
    }
}

TEST(TriangleStrip, EmptyAndSingle)
{
    EXPECT_TRUE(stitchedStrip({}).empty());
    const std::vector<Triangle> one{{4, 9, 2}};
    EXPECT_EQ(stitchedStrip(one), (std::vector<std::uint32_t>{4, 9, 2}));
    EXPECT_EQ(stripTriangles(stitchedStrip(one)), one);
}
