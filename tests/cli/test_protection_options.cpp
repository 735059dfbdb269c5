// The simplifier's options of `cadlod simplify` and `cadlod convert` (cli_options.h, from
// parameter_table.h): what each option and flag sets, and the report's options block.
#include "cli_options.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace cadlod::cli {
namespace {

SimplifyParams parsed(std::vector<std::string> args, ProtectionArgs& a)
{
    CLI::App app;
    addProtectionOptions(app, a);
    std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
    app.parse(args);
    SimplifyParams p;
    applyProtection(a, p);
    return p;
}

TEST(ProtectionOptions, NoneGivenKeepTheSimplifierDefaults)
{
    ProtectionArgs a;
    const SimplifyParams p = parsed({}, a);
    const SimplifyParams d;
    EXPECT_EQ(p.featureAngle, d.featureAngle);
    EXPECT_EQ(p.featurePenalty, d.featurePenalty);
    EXPECT_EQ(p.shadingWeight, d.shadingWeight);
    EXPECT_EQ(p.keepPartBorders, d.keepPartBorders);
    EXPECT_EQ(p.keepColorBorders, d.keepColorBorders);
    EXPECT_EQ(p.preserveBoundary, d.preserveBoundary);
    EXPECT_EQ(p.relaxToReachTarget, d.relaxToReachTarget);
    EXPECT_EQ(p.closeTunnels, d.closeTunnels);
    EXPECT_EQ(p.weightTrialsMaxFaces, d.weightTrialsMaxFaces);
}

TEST(ProtectionOptions, EachOptionSetsItsParameter)
{
    ProtectionArgs a;
    const SimplifyParams p = parsed({"--feature-angle", "45", "--feature-penalty", "0", "--shading-weight", "0.5",
                                     "--part-borders", "--no-color-borders", "--no-boundary", "--no-relax",
                                     "--keep-tunnels", "--no-weight-trials"},
                                    a);
    EXPECT_EQ(p.featureAngle, 45.0);
    EXPECT_EQ(p.featurePenalty, 0.0);
    EXPECT_EQ(p.shadingWeight, 0.5);
    EXPECT_TRUE(p.keepPartBorders);
    EXPECT_FALSE(p.keepColorBorders);
    EXPECT_FALSE(p.preserveBoundary);
    EXPECT_FALSE(p.relaxToReachTarget);
    EXPECT_FALSE(p.closeTunnels);
    EXPECT_EQ(p.weightTrialsMaxFaces, 0);
}

TEST(ProtectionOptions, TheBritishSpellingIsTheSameFlag)
{
    ProtectionArgs a;
    EXPECT_FALSE(parsed({"--no-colour-borders"}, a).keepColorBorders);
}

TEST(ProtectionOptions, RangesAreChecked)
{
    ProtectionArgs a;
    EXPECT_THROW(parsed({"--feature-angle", "200"}, a), CLI::ValidationError);
    ProtectionArgs b;
    EXPECT_THROW(parsed({"--feature-penalty", "-1"}, b), CLI::ValidationError);
}

TEST(ProtectionOptions, TheReportNamesWhatWasUsed)
{
    ProtectionArgs a;
    parsed({"--feature-angle", "45", "--no-colour-borders", "--no-weight-trials"}, a);
    const SimplifyParams d;
    const nlohmann::json expected{{"featureAngle", 45.0},       {"featurePenalty", d.featurePenalty},
                                  {"shadingWeight", d.shadingWeight}, {"keepPartBorders", false},
                                  {"keepColourBorders", false}, {"preserveBoundary", true},
                                  {"relaxToReachTarget", true}, {"closeTunnels", true},
                                  {"weightTrials", false}};
    EXPECT_EQ(toJson(a), expected);
    EXPECT_EQ(toJson(a).dump(), expected.dump());
}

}  // namespace
}  // namespace cadlod::cli
