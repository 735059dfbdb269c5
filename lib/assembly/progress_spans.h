// How an assembly's conversion reports progress to whoever runs it: the caller's progress
// is split into nested spans (a part, a cluster's proxy), each with a label the caller may
// show in place of the steps inside it; the steps (welding, the LOD chain) report through
// `step`, within the innermost span. The command line maps them onto its one bar, the
// plugin onto MeshLab's callback.
#pragma once

#include <algorithm>
#include <cstring>  // before wrap/callback.h, which uses strcpy without including it
#include <functional>
#include <string>
#include <vector>

#include <wrap/callback.h>

namespace cadlod {

struct ProgressSpans {
    std::function<void(int from, int to, const std::string& label)> begin = [](int, int, const std::string&) {};
    std::function<void()> end = [] {};
    vcg::CallBackPos* step = nullptr;
};

// A span for the scope it lives in.
class ProgressSpan {
public:
    ProgressSpan(const ProgressSpans& spans, int from, int to, const std::string& label = "") : spans_(spans)
    {
        spans_.begin(from, to, label);
    }
    ~ProgressSpan() { spans_.end(); }
    ProgressSpan(const ProgressSpan&) = delete;
    ProgressSpan& operator=(const ProgressSpan&) = delete;

private:
    const ProgressSpans& spans_;
};

// Spans on one vcg::CallBackPos (MeshLab's): a span's [from, to] is a share of the span
// around it, a step's percentage a share of the innermost span; the innermost label names
// the steps inside it. CallBackPos is a plain function pointer, so the spans of the one run
// alive are reached through a process-wide pointer; make one per run, on the stack.
class CallbackSpans {
public:
    explicit CallbackSpans(vcg::CallBackPos* target) : target_(target), outer_(active_) { active_ = this; }
    ~CallbackSpans() { active_ = outer_; }
    CallbackSpans(const CallbackSpans&) = delete;
    CallbackSpans& operator=(const CallbackSpans&) = delete;

    ProgressSpans spans()
    {
        ProgressSpans s;
        s.begin = [this](int from, int to, const std::string& label) { begin(from, to, label); };
        s.end = [this] { end(); };
        s.step = target_ ? &toActive : nullptr;
        return s;
    }

    // `percent` of the innermost span, as a percentage of the whole run.
    int overall(int percent) const
    {
        const Range& r = stack_.back();
        return int(r.from + (r.to - r.from) * std::clamp(percent, 0, 100) / 100.0);
    }

private:
    struct Range {
        double from, to;
        std::string label;
    };

    void begin(int from, int to, const std::string& label)
    {
        const Range& outer = stack_.back();
        const double width = (outer.to - outer.from) / 100.0;
        stack_.push_back({outer.from + width * from, outer.from + width * to, label.empty() ? outer.label : label});
        report(0, "");
    }

    void end()
    {
        if (stack_.size() > 1)
            stack_.pop_back();
    }

    bool report(int percent, const char* text)
    {
        if (!target_)
            return true;
        const std::string& label = stack_.back().label;
        const std::string line = label.empty() ? std::string(text ? text : "") : label;
        return target_(overall(percent), line.c_str());
    }

    static bool toActive(const int percent, const char* text) { return active_ ? active_->report(percent, text) : true; }

    inline static CallbackSpans* active_ = nullptr;
    vcg::CallBackPos* target_;
    CallbackSpans* outer_;
    std::vector<Range> stack_{{0.0, 100.0, ""}};
};

// The share (%) of a part's progress that welding its mesh takes, beside its LOD chain.
inline constexpr int kWeldingShare = 5;

}  // namespace cadlod
