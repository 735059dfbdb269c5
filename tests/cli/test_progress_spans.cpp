// assembly/progress_spans.h: nested spans on one MeshLab-style callback, as the plugin runs
// an assembly's parts and proxies. A step's percentage lands in the innermost span's share
// of the whole, and a labelled span names the steps inside it.
#include "assembly/progress_spans.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace cadlod::test {
namespace {

std::vector<std::pair<int, std::string>> calls;

bool record(const int percent, const char* text)
{
    calls.emplace_back(percent, text ? text : "");
    return true;
}

}  // namespace

TEST(CallbackSpans, AStepLandsInTheInnermostSpansShare)
{
    calls.clear();
    CallbackSpans progress(&record);
    const ProgressSpans spans = progress.spans();
    {
        ProgressSpan parts(spans, 10, 60, "");
        ProgressSpan second(spans, 50, 100, "part 2/2 shaft");
        calls.clear();
        spans.step(50, "Simplifying level 1");
    }
    ASSERT_EQ(calls.size(), 1u);
    // 10 + 50 * (0.5 + 0.5 * 0.5) = 47.5
    EXPECT_EQ(calls[0].first, 47);
    EXPECT_EQ(calls[0].second, "part 2/2 shaft");
}

TEST(CallbackSpans, WithoutALabelTheStepNamesItself)
{
    calls.clear();
    CallbackSpans progress(&record);
    const ProgressSpans spans = progress.spans();
    {
        ProgressSpan span(spans, 0, 50);
        spans.step(100, "Measuring level 2");
    }
    spans.step(100, "done");
    ASSERT_EQ(calls.size(), 3u);  // the span's start, its step, the step after it
    EXPECT_EQ(calls[1], std::make_pair(50, std::string("Measuring level 2")));
    EXPECT_EQ(calls[2], std::make_pair(100, std::string("done")));
}

TEST(CallbackSpans, NoCallbackNoSteps)
{
    CallbackSpans progress(nullptr);
    EXPECT_EQ(progress.spans().step, nullptr);
    const ProgressSpans spans = progress.spans();
    ProgressSpan span(spans, 0, 50, "quiet");  // does not call anything
}

}  // namespace cadlod::test
