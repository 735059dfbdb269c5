#include "lod/nearest_point.h"

#include <gtest/gtest.h>

#include <vector>

namespace cadlod {
namespace {

struct Range {
    double switchIn = 0, switchOut = 0;
};

// Levels at the centre switched at `at` (finest first, the last never culled), every one
// reaching `reach` from the centre.
std::vector<Range> chainSwitchedAt(const std::vector<double>& at)
{
    std::vector<Range> levels(at.size() + 1);
    for (std::size_t k = 0; k < at.size(); ++k) {
        levels[k].switchIn = at[k];
        levels[k + 1].switchOut = at[k];
    }
    levels.back().switchIn = kNeverCulled;
    return levels;
}

TEST(NearestPoint, EverySwitchMovesOutByTheReachAndNoNearerThanTheFloor)
{
    std::vector<Range> levels = chainSwitchedAt({1.0, 2.0});
    const std::vector<std::size_t> kept = holdAtNearestPoint(levels, {0.1, 0.1, 0.1});
    EXPECT_EQ(kept, (std::vector<std::size_t>{0, 1, 2}));
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_DOUBLE_EQ(levels[0].switchIn, 1.1);
    EXPECT_DOUBLE_EQ(levels[1].switchOut, 1.1);
    EXPECT_DOUBLE_EQ(levels[1].switchIn, 2.1);
    EXPECT_DOUBLE_EQ(levels[2].switchOut, 2.1);

    levels = chainSwitchedAt({1.0, 2.0});
    holdAtNearestPoint(levels, {0.3, 0.3, 0.3});
    EXPECT_DOUBLE_EQ(levels[1].switchOut, kNearestPointReach * 0.3);
}

// A level moved out to within kNarrowestRange of the next one's switch would be drawn over a
// sliver of distances: the finer level serves up to the next switch instead, so no level is
// ever drawn nearer than its own held switch.
TEST(NearestPoint, ALevelLeftWithANarrowRangeGivesWayToTheFinerOne)
{
    const double next = 1.1 * (1 + kNarrowestRange / 2);  // where level 2 is held
    std::vector<Range> levels = chainSwitchedAt({1.0, next - 0.1, 2.0});
    const std::vector<std::size_t> kept = holdAtNearestPoint(levels, {0.1, 0.1, 0.1, 0.1});
    EXPECT_EQ(kept, (std::vector<std::size_t>{0, 2, 3}));
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_DOUBLE_EQ(levels[0].switchIn, next);
    EXPECT_DOUBLE_EQ(levels[1].switchOut, next);
    EXPECT_DOUBLE_EQ(levels[1].switchIn, 2.1);

    // A range twice as wide stays.
    const double wider = 1.1 * (1 + 2 * kNarrowestRange);
    levels = chainSwitchedAt({1.0, wider - 0.1, 2.0});
    EXPECT_EQ(holdAtNearestPoint(levels, {0.1, 0.1, 0.1, 0.1}), (std::vector<std::size_t>{0, 1, 2, 3}));
}

// Levels clamped to the floor one after another, each a hair farther (a coarser level
// reaching a little farther), all give way: level 0 serves up to the last of them.
TEST(NearestPoint, LevelsHeldAtTheFloorCollapseIntoOne)
{
    std::vector<Range> levels = chainSwitchedAt({0.5, 0.6, 0.7, 3.0});
    const std::vector<std::size_t> kept = holdAtNearestPoint(levels, {0.2, 0.2, 0.2001, 0.2002, 0.2});
    EXPECT_EQ(kept, (std::vector<std::size_t>{0, 3, 4}));
    EXPECT_DOUBLE_EQ(levels[0].switchIn, kNearestPointReach * 0.2002);
    EXPECT_DOUBLE_EQ(levels[2].switchOut, 3.2);
}

}  // namespace
}  // namespace cadlod
