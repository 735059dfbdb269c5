#include "progress_bar.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sys/ioctl.h>
#include <unistd.h>
#include <vector>

namespace cadlod::cli::progress {
namespace {

// A share of the whole bar, in % of it; a labelled one names itself instead of its steps.
struct Frame {
    double from = 0, to = 100;
    std::string label;
};

struct State {
    bool enabled = true;
    bool terminal = ::isatty(STDERR_FILENO) != 0;
    bool barOpen = false;
    std::vector<Frame> frames{Frame{}};  // the phase first, then its spans
    std::string phaseName;
    double shown = 0;                    // the most of the bar shown so far
    int lastTenth = -1;
    std::set<std::string> named;         // plain lines: what a line has named already
};

State& state()
{
    static State s;
    return s;
}

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

// Terminal columns as characters, counting a UTF-8 sequence once.
int columnsOf(const std::string& s)
{
    return int(std::count_if(s.begin(), s.end(), [](char c) { return !isContinuationByte(c); }));
}

// The bytes of the longest prefix of `s` that takes at most `columns` columns.
std::size_t bytesForColumns(const std::string& s, int columns)
{
    std::size_t i = 0;
    for (int used = 0; i < s.size(); ++i) {
        if (!isContinuationByte(s[i]) && used++ == columns)
            break;
    }
    return i;
}

// `text` in at most `room` columns: whole words, then "..." where it is cut.
std::string fitText(const std::string& text, int room)
{
    if (columnsOf(text) <= room)
        return text;
    const std::string ellipsis = "...";
    if (room <= int(ellipsis.size()))
        return {};
    std::size_t keep = bytesForColumns(text, room - int(ellipsis.size()));
    if (const std::size_t space = text.rfind(' ', keep); space != std::string::npos && space > 0)
        keep = space;
    while (keep > 0 && std::string(" :,;").find(text[keep - 1]) != std::string::npos)
        --keep;
    return text.substr(0, keep) + ellipsis;
}

std::string barText(int percent, int width)
{
    const int filled = percent * width / 100;
    return "[" + std::string(std::size_t(filled), '#') + std::string(std::size_t(width - filled), ' ') + "] ";
}

std::string lower(std::string s)
{
    for (char& c : s)
        c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// A step named after its phase reads as part of it: "LOD chain: simplifying ...". A step
// that names the phase again says nothing more.
std::string describe(const State& s, const std::string& text)
{
    std::string step;
    for (std::size_t k = 1; k < s.frames.size(); ++k)
        if (!s.frames[k].label.empty())
            step += (step.empty() ? "" : ": ") + s.frames[k].label;
    if (step.empty())
        step = text;
    if (s.phaseName.empty())
        return step;
    if (step.empty() || lower(step).find(lower(s.phaseName)) != std::string::npos)
        return s.phaseName;
    if (step.size() > 1 && std::isupper(static_cast<unsigned char>(step[0])) &&
        !std::isupper(static_cast<unsigned char>(step[1])))
        step[0] = char(std::tolower(static_cast<unsigned char>(step[0])));
    return s.phaseName + ": " + step;
}

void drawBar(State& s, int percent, const std::string& description)
{
    std::fprintf(stderr, "\r%s", fitLine(percent, description, terminalColumns()).c_str());
    std::fflush(stderr);
    s.barOpen = true;
}

// A line for each step named for the first time, and one (naming only the phase) for each
// 10 % of the job reached in between.
void printLine(State& s, int percent, const std::string& description)
{
    const int tenth = percent / 10;
    std::string shown;
    if (s.named.insert(description).second)
        shown = description;
    else if (tenth > s.lastTenth)
        shown = s.phaseName;
    else
        return;
    s.lastTenth = std::max(s.lastTenth, tenth);
    std::fprintf(stderr, "cadlod: %3d%%%s%s\n", percent, shown.empty() ? "" : " ", shown.c_str());
}

}  // namespace

std::string fitLine(int percent, const std::string& text, int columns)
{
    const int width = std::max(columns - 1, 0);
    percent = std::clamp(percent, 0, 100);
    char percentText[8];
    std::snprintf(percentText, sizeof percentText, "%3d%%", percent);
    // The bar takes a quarter of the line, and none on a line too narrow to name the step too.
    const int barWidth = width >= 40 ? std::clamp(width / 4, 10, 30) : 0;
    std::string line = (barWidth > 0 ? barText(percent, barWidth) : std::string()) + percentText;
    const int room = width - columnsOf(line) - 1;
    if (const std::string fitted = fitText(text, room); !fitted.empty())
        line += " " + fitted;
    line.resize(bytesForColumns(line, width));
    return line + std::string(std::size_t(width - columnsOf(line)), ' ');
}

int terminalColumns()
{
    winsize size{};
    if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0)
        return size.ws_col;
    if (const char* columns = std::getenv("COLUMNS"); columns && std::atoi(columns) > 0)
        return std::atoi(columns);
    return 80;
}

void enable(bool on) { state().enabled = on; }

void phase(int from, int to, const std::string& name)
{
    State& s = state();
    const double start = std::clamp(from, 0, 100);
    s.frames = {Frame{start, std::clamp<double>(to, start, 100), ""}};
    s.phaseName = name;
    report(0, "");
}

void report(int percent, const std::string& text)
{
    State& s = state();
    if (!s.enabled)
        return;
    const Frame& inner = s.frames.back();
    s.shown = std::max(s.shown, inner.from + (inner.to - inner.from) * std::clamp(percent, 0, 100) / 100.0);
    const std::string description = describe(s, text);
    if (s.terminal)
        drawBar(s, int(s.shown), description);
    else
        printLine(s, int(s.shown), description);
}

void beginSpan(int from, int to, const std::string& label)
{
    State& s = state();
    const Frame& outer = s.frames.back();
    const double share = (outer.to - outer.from) / 100.0;
    const double start = std::clamp(from, 0, 100);
    const double end = std::clamp<double>(to, start, 100);
    s.frames.push_back(Frame{outer.from + share * start, outer.from + share * end, label});
    report(0, "");
}

void endSpan()
{
    State& s = state();
    if (s.frames.size() > 1)
        s.frames.pop_back();
}

void done()
{
    State& s = state();
    s.frames = {Frame{}};
    report(100, "");
    finish();
}

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
