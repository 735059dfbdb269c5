// MeshLab's progress callback, wrapped so that meshlabserver prints one readable line per
// step instead of messages run together.
#pragma once

#include <cstdlib>
#include <cstring>  // before wrap/callback.h, which uses strcpy without including it
#include <string>

#include <wrap/callback.h>

namespace cadlod {

// meshlabserver 2020.09 prints each progress message with printf("%s") and no newline, so
// messages ran together ("Simplifying level 1Measuring level 1"), and a loop reporting
// every percent printed a hundred of them. Through this adapter every message ends with a
// newline and reaches MeshLab only when its text changes or its position has moved by
// kStep points (the end, 100, always gets through). The GUI shows the message in its
// one-line status bar, which does not draw the newline.
//
// Code that takes a plain vcg::CallBackPos* (a function pointer, it carries no state) is
// given callback(): a trampoline to the innermost adapter alive on this thread. Make one
// adapter per filter or file operation, on the stack, where MeshLab hands over its callback.
class ProgressLines {
public:
    static constexpr int kStep = 5;

    explicit ProgressLines(vcg::CallBackPos* target) : target_(target), outer_(innermost_)
    {
        // Wrapping an adapter's trampoline again would call itself: wrap what it wraps.
        if (target_ == &toInnermost)
            target_ = outer_ ? outer_->target_ : nullptr;
        innermost_ = this;
    }
    ~ProgressLines() { innermost_ = outer_; }
    ProgressLines(const ProgressLines&) = delete;
    ProgressLines& operator=(const ProgressLines&) = delete;

    // Null when MeshLab gave no callback, so that callers can still skip building messages.
    vcg::CallBackPos* callback() const { return target_ ? &toInnermost : nullptr; }

    bool operator()(int percent, const char* message)
    {
        if (!target_)
            return true;
        std::string line = message ? message : "";
        if (line.empty() || line.back() != '\n')
            line += '\n';
        if (!worthALine(percent, line))
            return true;
        lastPercent_ = percent;
        lastLine_ = std::move(line);
        return target_(percent, lastLine_.c_str());
    }

private:
    bool worthALine(int percent, const std::string& line) const
    {
        if (line != lastLine_)
            return true;
        const bool reachesTheEnd = percent == 100 && lastPercent_ != 100;
        return reachesTheEnd || std::abs(percent - lastPercent_) >= kStep;
    }

    static bool toInnermost(const int percent, const char* message)
    {
        return innermost_ ? (*innermost_)(percent, message) : true;
    }

    inline static thread_local ProgressLines* innermost_ = nullptr;
    vcg::CallBackPos* target_;
    ProgressLines* outer_;
    std::string lastLine_;  // empty until the first message, which always gets through
    int lastPercent_ = 0;
};

}  // namespace cadlod
