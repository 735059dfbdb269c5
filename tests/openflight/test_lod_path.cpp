// The triangles a camera path draws through an OpenFlight LOD model, as OpenSceneGraph's LOD
// nodes pick the levels (bench/lod_path, used by the paper's Table 1): on a three-level model
// with known switch distances (0-50-200-1000 from its LOD centre), every frame draws the
// level whose range holds the camera's distance, and a path across every switch draws them all.
#include "openflight/flt_writer.h"
#include "lod_path.h"
#include "model_fixtures.h"

#include <osgDB/ReadFile>

#include <gtest/gtest.h>

#include <filesystem>

using namespace cadlod;

namespace {

const osg::Vec3d kLodCenter(2.0, 2.0, 1.5);  // threeLevelModel's

osg::ref_ptr<osg::Node> loadThreeLevelModel()
{
    const std::string path = (std::filesystem::temp_directory_path() / "cadlod_lod_path.flt").string();
    std::string error;
    EXPECT_TRUE(flt::writeOpenFlightFile(path, test::threeLevelModel(), flt::WriteOptions{}, error)) << error;
    return osgDB::readRefNodeFile(path);
}

// Eyes backing away from the LOD centre along a slanted line.
std::vector<osg::Vec3d> eyesAt(const std::vector<double>& distances)
{
    osg::Vec3d direction(1.0, 0.5, 0.25);
    direction.normalize();
    std::vector<osg::Vec3d> eyes;
    for (double d : distances)
        eyes.push_back(kLodCenter + direction * d);
    return eyes;
}

int levelHolding(const std::vector<lodpath::Level>& levels, double distance)
{
    for (std::size_t k = 0; k < levels.size(); ++k)
        if (levels[k].nearRange <= distance && distance < levels[k].farRange)
            return int(k);
    return -1;
}

}  // namespace

TEST(LodPath, FindsTheLevelsWithTheirRangesAndTriangles)
{
    osg::ref_ptr<osg::Node> model = loadThreeLevelModel();
    ASSERT_TRUE(model);
    lodpath::LodPathCounter counter(*model);
    const auto& levels = counter.levels();
    ASSERT_EQ(levels.size(), 3u);
    const float edges[4] = {0, 50, 200, 1000};
    const std::size_t triangles[3] = {2 * 12 * 12 * 2, 2 * 6 * 6 * 2, 2 * 3 * 3 * 2};  // two sheets per level
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_FLOAT_EQ(levels[k].nearRange, edges[k]);
        EXPECT_FLOAT_EQ(levels[k].farRange, edges[k + 1]);
        EXPECT_EQ(levels[k].triangles, triangles[k]);
    }
}

TEST(LodPath, EachFrameDrawsTheLevelWhoseRangeHoldsTheDistance)
{
    osg::ref_ptr<osg::Node> model = loadThreeLevelModel();
    ASSERT_TRUE(model);
    lodpath::LodPathCounter counter(*model);
    const auto& levels = counter.levels();
    for (double d : lodpath::logSpaced(5, 2000, 40)) {
        const lodpath::Drawn drawn = counter.drawnFrom(eyesAt({d}).front());
        const int expected = levelHolding(levels, d);
        for (std::size_t k = 0; k < levels.size(); ++k)
            EXPECT_EQ(drawn.perLevel[k], int(k) == expected ? levels[k].triangles : 0u) << "distance " << d;
        EXPECT_EQ(drawn.triangles, expected >= 0 ? levels[std::size_t(expected)].triangles : 0u) << "distance " << d;
    }
}

TEST(LodPath, APathAcrossEverySwitchDistanceDrawsEveryLevel)
{
    osg::ref_ptr<osg::Node> model = loadThreeLevelModel();
    ASSERT_TRUE(model);
    lodpath::LodPathCounter counter(*model);
    const auto& levels = counter.levels();
    // Radius 3 and a 45° view: the model fills the view from about 7, closer than the first switch.
    const lodpath::PathEnds ends = lodpath::pathOverEveryLevel(levels, 3.0, 45.0, 1080);
    EXPECT_LT(ends.nearDistance, 50.0);
    EXPECT_GT(ends.farDistance, 200.0);
    const auto distances = lodpath::logSpaced(ends.nearDistance, ends.farDistance, 30);
    const lodpath::PathTally tally = counter.walk(eyesAt(distances));
    ASSERT_EQ(tally.levels.size(), 3u);
    int frames = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_GT(tally.levels[k].frames, 0) << "level " << k;
        frames += tally.levels[k].frames;
    }
    EXPECT_EQ(frames, 30);  // one level per frame
    EXPECT_EQ(tally.framesDrawingNothing, 0);
    // Backing away: the levels come in order, finest first.
    EXPECT_EQ(tally.levels[0].firstFrame, 0);
    EXPECT_EQ(tally.levels[1].firstFrame, tally.levels[0].lastFrame + 1);
    EXPECT_EQ(tally.levels[2].firstFrame, tally.levels[1].lastFrame + 1);
    EXPECT_EQ(tally.levels[2].lastFrame, 29);
    double sum = 0;
    for (std::size_t k = 0; k < 3; ++k)
        sum += double(tally.levels[k].frames * levels[k].triangles);
    EXPECT_DOUBLE_EQ(tally.meanTriangles(), sum / 30);
}

TEST(LodPath, APathBetweenTwoSwitchesDrawsOneLevelAndBeyondTheLastNothing)
{
    osg::ref_ptr<osg::Node> model = loadThreeLevelModel();
    ASSERT_TRUE(model);
    lodpath::LodPathCounter counter(*model);
    const lodpath::PathTally middle = counter.walk(eyesAt(lodpath::logSpaced(60, 190, 8)));
    EXPECT_EQ(middle.levels[0].frames, 0);
    EXPECT_EQ(middle.levels[1].frames, 8);
    EXPECT_EQ(middle.levels[2].frames, 0);
    EXPECT_DOUBLE_EQ(middle.meanTriangles(), double(counter.levels()[1].triangles));

    const lodpath::PathTally beyond = counter.walk(eyesAt(lodpath::logSpaced(1100, 3000, 5)));
    EXPECT_EQ(beyond.framesDrawingNothing, 5);
    EXPECT_EQ(beyond.meanTriangles(), 0.0);
}

TEST(LodPath, LogSpacedDistancesKeepAConstantRatio)
{
    const auto d = lodpath::logSpaced(1, 1000, 4);
    ASSERT_EQ(d.size(), 4u);
    EXPECT_DOUBLE_EQ(d.front(), 1);
    EXPECT_NEAR(d[1], 10, 1e-9);
    EXPECT_NEAR(d[2], 100, 1e-9);
    EXPECT_DOUBLE_EQ(d.back(), 1000);
}
