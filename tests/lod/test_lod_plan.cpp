#include "lod/lod_plan.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace cadlod;

TEST(LodPlan, PaperReductionsGiveDecreasingFaceCounts)
{
    const LevelPlan p = planLevels("50 60 70 80 90", LevelSpec::ReductionPercent, 47508);
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_EQ(p.targetFaces, (std::vector<int>{23754, 19003, 14252, 9502, 4751}));
}

TEST(LodPlan, AcceptsPercentSignsAndCommas)
{
    const LevelPlan p = planLevels("50%, 75%", LevelSpec::ReductionPercent, 1000);
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_EQ(p.targetFaces, (std::vector<int>{500, 250}));
}

TEST(LodPlan, FaceCounts)
{
    const LevelPlan p = planLevels("20000 8000 2000", LevelSpec::FaceCount, 47508);
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_EQ(p.targetFaces, (std::vector<int>{20000, 8000, 2000}));
}

TEST(LodPlan, RejectsBadLists)
{
    EXPECT_FALSE(planLevels("", LevelSpec::ReductionPercent, 100).ok());
    EXPECT_FALSE(planLevels("50 abc", LevelSpec::ReductionPercent, 100).ok());
    EXPECT_FALSE(planLevels("0", LevelSpec::ReductionPercent, 100).ok());
    EXPECT_FALSE(planLevels("100", LevelSpec::ReductionPercent, 100).ok());
    EXPECT_FALSE(planLevels("70 50", LevelSpec::ReductionPercent, 100).ok());  // not coarser
    EXPECT_FALSE(planLevels("100 500", LevelSpec::FaceCount, 1000).ok());      // not coarser
    EXPECT_FALSE(planLevels("10.5", LevelSpec::FaceCount, 100).ok());
    const LevelPlan p = planLevels("60 60", LevelSpec::ReductionPercent, 1000);
    ASSERT_FALSE(p.ok());
    EXPECT_TRUE(p.targetFaces.empty() || p.targetFaces.size() == 1);
    EXPECT_NE(p.error.find("not coarser"), std::string::npos);
}

TEST(LodPlan, LevelsTheMeshIsTooSmallForAreLeftOutWithAWarning)
{
    LevelPlan p = planLevels("20000 8000 50", LevelSpec::FaceCount, 5000);
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_EQ(p.targetFaces, std::vector<int>{50});
    ASSERT_EQ(p.warnings.size(), 2u);
    EXPECT_NE(p.warnings[0].find("'20000' left out"), std::string::npos) << p.warnings[0];

    p = planLevels("50 60 70 80 90", LevelSpec::ReductionPercent, 3);  // 2, 1, 1, 1, 0->1
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_EQ(p.targetFaces, (std::vector<int>{2, 1}));
    EXPECT_EQ(p.warnings.size(), 3u);

    p = planLevels("50", LevelSpec::ReductionPercent, 1);  // a single triangle: level 0 only
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_TRUE(p.targetFaces.empty());
    EXPECT_EQ(p.warnings.size(), 1u);
}

TEST(LodPlan, TinyMeshesKeepAtLeastOneFace)
{
    const LevelPlan p = planLevels("99.9", LevelSpec::ReductionPercent, 10);
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_EQ(p.targetFaces, std::vector<int>{1});
}

TEST(SwitchDistance, ProjectsErrorToPixels)
{
    ViewParams view;  // 45 deg, 1080 px, 1 px
    // At distance d the viewport spans 2 d tan(22.5 deg); an error e covers e*1080/span px.
    const double d = projectedErrorDistance(0.5, view);
    const double pixels = 0.5 * 1080.0 / (2.0 * d * std::tan(22.5 * M_PI / 180.0));
    EXPECT_NEAR(pixels, 1.0, 1e-12);
    view.pixelThreshold = 2.0;
    EXPECT_NEAR(projectedErrorDistance(0.5, view), d / 2.0, 1e-9);
}

TEST(SwitchDistance, RangesAreContiguousAndMonotone)
{
    std::vector<LodLevel> levels(4);
    const double errors[] = {0.0, 0.01, 0.05, 0.2};
    for (int k = 0; k < 4; ++k) {
        levels[k].level = k;
        levels[k].hausdorffMax = errors[k];
    }
    ViewParams view;
    assignSwitchDistances(levels, 300.0, view);
    EXPECT_EQ(levels[0].switchOut, 0.0);
    for (int k = 0; k < 4; ++k)
        EXPECT_LT(levels[k].switchOut, levels[k].switchIn) << "level " << k;
    for (int k = 0; k + 1 < 4; ++k) {
        EXPECT_EQ(levels[k].switchIn, levels[k + 1].switchOut);
        EXPECT_NEAR(levels[k].switchIn, projectedErrorDistance(errors[k + 1], view), 1e-9);
    }
    EXPECT_NEAR(levels[3].switchIn, projectedErrorDistance(300.0, view), 1e-9);
}

TEST(SwitchDistance, NonIncreasingErrorGivesEmptyRangeNotDisorder)
{
    std::vector<LodLevel> levels(3);
    levels[1].hausdorffMax = 0.05;
    levels[2].hausdorffMax = 0.03;  // measured closer than level 1
    assignSwitchDistances(levels, 100.0, ViewParams{});
    EXPECT_EQ(levels[1].switchOut, levels[1].switchIn);  // never shown
    for (int k = 0; k + 1 < 3; ++k) {
        EXPECT_LE(levels[k].switchOut, levels[k].switchIn);
        EXPECT_EQ(levels[k].switchIn, levels[k + 1].switchOut);
    }
}

namespace {
std::vector<LodLevel> levelsWith(std::vector<int> faces, std::vector<double> errors)
{
    std::vector<LodLevel> levels(faces.size());
    for (std::size_t k = 0; k < faces.size(); ++k) {
        levels[k].level = int(k);
        levels[k].faces = faces[k];
        levels[k].hausdorffMax = errors[k];
    }
    return levels;
}
}  // namespace

TEST(LevelSelection, KeepsLevelsThatGetLighterAndCoarser)
{
    const LevelSelection s = selectUsefulLevels(levelsWith({100, 50, 20}, {0, 0.1, 0.3}), 1e-9);
    EXPECT_EQ(s.keep, (std::vector<bool>{true, true, true}));
}

TEST(LevelSelection, DropsALevelTheSimplifierCouldNotReduce)
{
    const LevelSelection s = selectUsefulLevels(levelsWith({100, 50, 50, 20}, {0, 0.1, 0.1, 0.3}), 1e-9);
    EXPECT_EQ(s.keep, (std::vector<bool>{true, true, false, true}));
    EXPECT_NE(s.why[2].find("stopped at 50 faces"), std::string::npos) << s.why[2];
}

TEST(LevelSelection, DropsALevelThatWouldNeverBeShown)
{
    // Level 2 is lighter than level 1 and no less accurate: level 1 has no distance range.
    const LevelSelection s = selectUsefulLevels(levelsWith({100, 50, 40, 20}, {0, 0.2, 0.2, 0.5}), 1e-9);
    EXPECT_EQ(s.keep, (std::vector<bool>{true, false, true, true}));
    EXPECT_NE(s.why[1].find("never be shown"), std::string::npos) << s.why[1];
}

TEST(LevelSelection, LosslessLevelsKeepTheLightestAndLevelZeroStays)
{
    const LevelSelection s = selectUsefulLevels(levelsWith({100, 50, 40}, {0, 0, 0}), 1e-9);
    EXPECT_EQ(s.keep, (std::vector<bool>{true, false, true}));
    std::vector<LodLevel> kept = levelsWith({100, 40}, {0, 0});
    assignSwitchDistances(kept, 10.0, ViewParams{}, 1e-9);
    EXPECT_LT(kept[0].switchOut, kept[0].switchIn);  // the original keeps a (tiny) range
    EXPECT_LT(kept[1].switchOut, kept[1].switchIn);
}
