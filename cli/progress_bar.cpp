#include "progress_bar.h"

#include <algorithm>
#include <cstdio>
#include <unistd.h>

namespace cadlod::cli::progress {
namespace {

struct State {
    bool enabled = true;
    bool terminal = ::isatty(STDERR_FILENO) != 0;
    bool barOpen = false;
    std::string lastText;
    int lastTenth = -1;
    bool inSpan = false;
    int spanFrom = 0, spanTo = 100;
    std::string spanLabel;
};

State& state()
{
    static State s;
    return s;
}

void drawBar(State& s, int percent, const std::string& text)
{
    constexpr int kWidth = 30;
    const int filled = percent * kWidth / 100;
    std::fprintf(stderr, "\r[%.*s%*s] %3d%% %-48.48s", filled, "##############################", kWidth - filled, "",
                 percent, text.c_str());
    std::fflush(stderr);
    s.barOpen = true;
}

void printLine(State& s, int percent, const std::string& text)
{
    const int tenth = percent / 10;
    if (text == s.lastText && tenth == s.lastTenth)
        return;
    s.lastText = text;
    s.lastTenth = tenth;
    std::fprintf(stderr, "cadlod: %3d%% %s\n", percent, text.c_str());
}

}  // namespace

void enable(bool on) { state().enabled = on; }

void report(int percent, const std::string& text)
{
    State& s = state();
    if (!s.enabled)
        return;
    percent = std::clamp(percent, 0, 100);
    if (s.inSpan)
        percent = s.spanFrom + (s.spanTo - s.spanFrom) * percent / 100;
    const std::string& shown = s.inSpan ? s.spanLabel : text;
    if (s.terminal)
        drawBar(s, percent, shown);
    else
        printLine(s, percent, shown);
}

void beginSpan(int from, int to, const std::string& label)
{
    State& s = state();
    s.spanFrom = std::clamp(from, 0, 100);
    s.spanTo = std::clamp(to, s.spanFrom, 100);
    s.spanLabel = label;
    s.inSpan = true;
    report(0, label);
}

void endSpan() { state().inSpan = false; }

void finish()
{
    State& s = state();
    if (s.barOpen)
        std::fputc('\n', stderr);
    s.barOpen = false;
}

bool callback(const int percent, const char* text)
{
    report(percent, text ? text : "");
    return true;
}

}  // namespace cadlod::cli::progress
