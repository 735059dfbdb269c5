// The parameter table the MeshLab filters, the command line and the JSON report are made
// from (lib/simplify/parameter_table.h): names unique, defaults those of SimplifyParams{}
// and within their ranges, every field reads back what it writes.
#include "simplify/parameter_table.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

namespace cadlod {
namespace {

TEST(ParameterTable, NamesAreUnique)
{
    std::set<std::string> names, options, keys;
    for (const SimplifyParameter& row : kSimplifyParameters) {
        EXPECT_TRUE(names.insert(row.name).second) << row.name;
        if (row.cli.form != CliForm::None) {
            EXPECT_TRUE(options.insert(row.cli.names).second) << row.cli.names;
        }
        if (row.jsonKey) {
            EXPECT_TRUE(keys.insert(row.jsonKey).second) << row.jsonKey;
        }
    }
}

TEST(ParameterTable, EveryRowSaysWhatItIs)
{
    for (const SimplifyParameter& row : kSimplifyParameters) {
        EXPECT_STRNE(row.label, "") << row.name;
        EXPECT_STRNE(row.help, "") << row.name;
        if (row.cli.form != CliForm::None) {
            EXPECT_NE(row.cli.names, nullptr) << row.name;
            EXPECT_NE(row.cli.help, nullptr) << row.name;
        }
    }
}

TEST(ParameterTable, CommandLinePositionsAreOneToN)
{
    std::set<int> positions;
    std::size_t offered = 0;
    for (const SimplifyParameter& row : kSimplifyParameters)
        if (row.cli.form != CliForm::None) {
            ++offered;
            EXPECT_TRUE(positions.insert(row.cli.position).second) << row.name;
        }
    ASSERT_FALSE(positions.empty());
    EXPECT_EQ(*positions.begin(), 0);
    EXPECT_EQ(*positions.rbegin(), int(offered) - 1);
}

TEST(ParameterTable, CommandLineOptionsTakeNumbers)
{
    // The command stores option values as double; flags are switches.
    for (const SimplifyParameter& row : kSimplifyParameters) {
        if (row.cli.form == CliForm::Option) {
            EXPECT_EQ(row.field.kind, ParameterKind::Float) << row.name;
        }
        if (row.cli.form == CliForm::FlagOn || row.cli.form == CliForm::FlagOff) {
            EXPECT_EQ(row.field.kind, ParameterKind::Bool) << row.name;
        }
    }
}

TEST(ParameterTable, DefaultsLieInTheirRanges)
{
    for (const SimplifyParameter& row : kSimplifyParameters) {
        const double d = defaultOf(row);
        EXPECT_LE(d, row.range.max) << row.name;
        if (row.range.minExcluded) {
            EXPECT_GT(d, row.range.min) << row.name;
        } else {
            EXPECT_GE(d, row.range.min) << row.name;
        }
    }
}

TEST(ParameterTable, FlagsChangeTheDefault)
{
    // A flag turning on a parameter that is on already would do nothing.
    for (const SimplifyParameter& row : kSimplifyParameters) {
        if (row.cli.form == CliForm::FlagOn) {
            EXPECT_EQ(defaultOf(row), 0.0) << row.name;
        }
        if (row.cli.form == CliForm::FlagOff) {
            EXPECT_EQ(defaultOf(row), 1.0) << row.name;
        }
    }
}

TEST(ParameterTable, FieldsReadBackWhatTheyWrite)
{
    for (const SimplifyParameter& row : kSimplifyParameters) {
        SimplifyParams p;
        const double other = row.field.kind == ParameterKind::Bool ? 1.0 - defaultOf(row)
                             : row.field.kind == ParameterKind::Int ? defaultOf(row) + 1
                                                                    : defaultOf(row) * 0.5 + 0.25;
        row.field.set(p, other);
        EXPECT_EQ(row.field.get(p), other) << row.name;
        SimplifyParams q;
        row.field.set(q, defaultOf(row));
        EXPECT_EQ(row.field.get(q), defaultOf(row)) << row.name;
    }
}

TEST(ParameterTable, MembersAreTheirNamesakes)
{
    SimplifyParams p;
    p.featureAngle = 12.5;
    p.candidatesPerEdge = 7;
    p.keepColorBorders = false;
    for (const SimplifyParameter& row : kSimplifyParameters) {
        const std::string name = row.name;
        if (name == "featureAngle") {
            EXPECT_EQ(row.field.get(p), 12.5);
        }
        if (name == "candidatesPerEdge") {
            EXPECT_EQ(row.field.get(p), 7.0);
        }
        if (name == "keepColorBorders") {
            EXPECT_EQ(row.field.get(p), 0.0);
        }
    }
}

TEST(ParameterTable, WeightTrialsSwitchSetsTheirLimit)
{
    const SimplifyParameter* trials = nullptr;
    for (const SimplifyParameter& row : kSimplifyParameters)
        if (std::string(row.name) == "weightTrials")
            trials = &row;
    ASSERT_NE(trials, nullptr);
    SimplifyParams p;
    p.weightTrialsMaxFaces = 1234;
    trials->field.set(p, 1.0);  // on keeps the caller's limit
    EXPECT_EQ(p.weightTrialsMaxFaces, 1234);
    trials->field.set(p, 0.0);
    EXPECT_EQ(p.weightTrialsMaxFaces, 0);
    EXPECT_EQ(trials->field.get(p), 0.0);
}

TEST(ParameterTable, TheLodSetFilterOffersTheFeatureParameters)
{
    std::vector<std::string> offered;
    for (const SimplifyParameter& row : kSimplifyParameters)
        if (row.inLodSetFilter)
            offered.push_back(row.name);
    EXPECT_EQ(offered, (std::vector<std::string>{"featureAngle", "preserveBoundary", "keepPartBorders",
                                                 "keepColorBorders", "featurePenalty"}));
}

}  // namespace
}  // namespace cadlod
