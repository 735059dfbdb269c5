#include "lod/level_names.h"

#include "lod/lod_chain.h"

#include <gtest/gtest.h>

namespace cadlod {
namespace {

TEST(LevelNames, TwoSignificantDigitsWithoutExponent)
{
    EXPECT_EQ(twoSignificantDigits(0.00768), "0.0077");
    EXPECT_EQ(twoSignificantDigits(7.68), "7.7");
    EXPECT_EQ(twoSignificantDigits(15.3), "15");
    EXPECT_EQ(twoSignificantDigits(2872), "2900");
    EXPECT_EQ(twoSignificantDigits(0), "0");
}

TEST(LevelNames, MillimetresBelowAMetreMetresAboveNoUnitWhenUnknown)
{
    EXPECT_EQ(distanceWithUnit(0.00768, 1.0), "7.7 mm");
    EXPECT_EQ(distanceWithUnit(0.25, 1.0), "250 mm");
    EXPECT_EQ(distanceWithUnit(0.9996, 1.0), "1.0 m");
    EXPECT_EQ(distanceWithUnit(1441, 1.0), "1400 m");
    EXPECT_EQ(distanceWithUnit(7.68, 0.001), "7.7 mm");
    EXPECT_EQ(distanceWithUnit(0.00768, 0.0), "0.0077");
    EXPECT_EQ(distanceWithUnit(kNeverCulled, 1.0), "inf");
}

TEST(LevelNames, LevelsBySwitchInDistanceLevelZeroByWhereItGivesWay)
{
    EXPECT_EQ(levelRangeName(1, 0.00768, 0.0153, 1.0), "LOD1 \u22657.7 mm");
    EXPECT_EQ(levelRangeName(0, 0.0, 0.00768, 1.0), "LOD0 <7.7 mm");
    EXPECT_EQ(levelRangeName(0, 0.0, kNeverCulled, 1.0), "LOD0");
}

TEST(LevelNames, BaseNameKeptWhenItFitsThePanel)
{
    EXPECT_EQ(levelLabel("shaft", "LOD1 \u22657.7 mm", ".flt"), "shaft LOD1 \u22657.7 mm.flt");
    EXPECT_EQ(levelLabel("cabinet_assembly", "LOD1 \u22657.7 mm", ".flt"), "LOD1 \u22657.7 mm.flt");
    EXPECT_EQ(levelLabel("", "LOD0", ""), "LOD0");
}

}  // namespace
}  // namespace cadlod
