// Gathering the layers of an LOD set into one model (what the exporter does with the
// document's layers).
#include "openflight/lod_assembly.h"
#include "model_fixtures.h"

#include <gtest/gtest.h>

using namespace cadlod::flt;
using namespace cadlod::test;

namespace {

LodSetMember member(int setId, int level, double out, double in)
{
    LodSetMember m;
    m.setId = setId;
    m.level = level;
    m.geometry = twoPartLevel(2 + level, std::to_string(level));
    m.geometry.switchOut = out;
    m.geometry.switchIn = in;
    m.geometry.center = {1, 2, 3};
    return m;
}

}  // namespace

TEST(LodAssembly, OrdersLevelsAndIgnoresOtherSets)
{
    std::vector<LodSetMember> members{member(7, 2, 100, 400), member(7, 0, 0, 30), member(3, 0, 0, 10),
                                      member(7, 1, 30, 100)};
    LodModel model;
    std::string error;
    ASSERT_TRUE(assembleLodSet(members, 7, model, error)) << error;
    ASSERT_EQ(model.levels.size(), 3u);
    EXPECT_EQ(model.levels[0].name, "lod0");
    EXPECT_DOUBLE_EQ(model.levels[0].switchIn, 30);
    EXPECT_DOUBLE_EQ(model.levels[1].switchOut, 30);
    EXPECT_DOUBLE_EQ(model.levels[2].switchIn, 400);
    EXPECT_EQ(model.levels[2].triangleCount(), 2u * (2 * 4 * 4));
}

TEST(LodAssembly, RejectsUnusableSets)
{
    LodModel model;
    std::string error;
    EXPECT_FALSE(assembleLodSet({member(1, 1, 0, 10)}, 1, model, error));
    EXPECT_NE(error.find("level 0"), std::string::npos) << error;
    EXPECT_FALSE(assembleLodSet({member(1, 0, 0, 10), member(1, 1, 10, 50), member(1, 1, 10, 50)}, 1, model, error));
    EXPECT_NE(error.find("two layers"), std::string::npos) << error;
    EXPECT_FALSE(assembleLodSet({member(1, 0, 0, 0)}, 1, model, error));
    EXPECT_NE(error.find("no usable switch range"), std::string::npos) << error;
    EXPECT_FALSE(assembleLodSet({member(1, 0, 0, 100), member(1, 1, 0, 50)}, 1, model, error));
    EXPECT_NE(error.find("outwards"), std::string::npos) << error;
    EXPECT_FALSE(assembleLodSet({member(2, 0, 0, 10)}, 1, model, error));
}
