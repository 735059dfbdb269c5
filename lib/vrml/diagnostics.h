// Warnings collected while reading (skipped faces, missing inlines, unknown nodes), each
// with file:line:col, summarised by kind so a log stays readable on huge files.
#pragma once

#include <algorithm>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace cadlod::vrml {

struct Diagnostic {
    std::string kind;     // short category, e.g. "bad face", "unknown node"
    std::string where;    // file:line:col
    std::string message;
};

// True for the kinds of finding after which part of the model is missing: the rest of a
// file (syntax error), a whole file (Inline), a subtree or a node. The others (a face
// skipped, an attribute or a texture replaced) leave the model whole but for that face.
inline bool losesGeometry(const std::string& kind)
{
    static const char* const kLosing[] = {"syntax error",  "missing inline",     "recursive inline",
                                          "bad inline",    "inline too deep",    "undefined USE",
                                          "unknown node",  "too deep",           "missing EXTERNPROTO",
                                          "unsupported geometry", "bad ElevationGrid", "recursive instance"};
    return std::find(std::begin(kLosing), std::end(kLosing), kind) != std::end(kLosing);
}

class Diagnostics {
public:
    static constexpr size_t kKeptPerKind = 20;

    void warn(const std::string& kind, const std::string& where, const std::string& message)
    {
        int& n = counts_[kind];
        if (size_t(n++) < kKeptPerKind)
            kept_.push_back({kind, where, message});
    }
    const std::vector<Diagnostic>& kept() const { return kept_; }
    const std::map<std::string, int>& counts() const { return counts_; }
    int count(const std::string& kind) const
    {
        auto it = counts_.find(kind);
        return it == counts_.end() ? 0 : it->second;
    }
    int total() const
    {
        int t = 0;
        for (const auto& [k, n] : counts_) t += n;
        return t;
    }

private:
    std::vector<Diagnostic> kept_;
    std::map<std::string, int> counts_;
};

}  // namespace cadlod::vrml
