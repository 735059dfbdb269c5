// ProgressLines: what reaches MeshLab's callback is one line per step, as meshlabserver
// prints it (printf("%s") of each message, nothing added).
#include "support/progress_lines.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using cadlod::ProgressLines;

namespace {

// Stands in for meshlabserver's callback: records what it would print.
struct Printed {
    static inline std::vector<std::pair<int, std::string>> calls;
    static bool record(const int percent, const char* message)
    {
        calls.emplace_back(percent, message);
        return true;
    }
    static std::string text()
    {
        std::string all;
        for (const auto& c : calls)
            all += c.second;
        return all;
    }
};

class ProgressLinesTest : public ::testing::Test {
protected:
    void SetUp() override { Printed::calls.clear(); }
};

}  // namespace

TEST_F(ProgressLinesTest, EveryMessageEndsItsLine)
{
    ProgressLines progress(&Printed::record);
    vcg::CallBackPos* cb = progress.callback();
    cb(0, "Simplifying level 1");
    cb(50, "Measuring level 1");
    cb(100, "LOD chain done\n");  // already a line: no second newline
    EXPECT_EQ(Printed::text(), "Simplifying level 1\nMeasuring level 1\nLOD chain done\n");
}

TEST_F(ProgressLinesTest, SameMessageGetsThroughOnlyEveryFivePoints)
{
    ProgressLines progress(&Printed::record);
    for (int percent = 0; percent <= 99; ++percent)
        progress(percent, "CAD edge collapse");
    ASSERT_EQ(Printed::calls.size(), 20u);  // 0, 5, ..., 95
    for (std::size_t i = 0; i < Printed::calls.size(); ++i)
        EXPECT_EQ(Printed::calls[i].first, int(5 * i));
    progress(100, "CAD edge collapse");
    EXPECT_EQ(Printed::calls.back().first, 100) << "the end always gets through";
}

TEST_F(ProgressLinesTest, NewTextGetsThroughAtAnyPosition)
{
    ProgressLines progress(&Printed::record);
    progress(10, "Simplifying level 1");
    progress(11, "Measuring level 1");
    progress(12, "Measuring level 1");
    ASSERT_EQ(Printed::calls.size(), 2u);
    EXPECT_EQ(Printed::calls[1].second, "Measuring level 1\n");
}

TEST_F(ProgressLinesTest, NoCallbackGivesNoCallback)
{
    ProgressLines progress(nullptr);
    EXPECT_EQ(progress.callback(), nullptr) << "callers skip their messages when MeshLab gives none";
    EXPECT_TRUE(progress(50, "anything"));
}

TEST_F(ProgressLinesTest, WrappingAnAdaptersCallbackAgainForwardsOnce)
{
    ProgressLines outer(&Printed::record);
    {
        ProgressLines inner(outer.callback());
        inner.callback()(0, "Reading VRML");
        inner.callback()(1, "Reading VRML");
    }
    outer.callback()(10, "Building mesh");
    ASSERT_EQ(Printed::calls.size(), 2u);
    EXPECT_EQ(Printed::text(), "Reading VRML\nBuilding mesh\n");
}
