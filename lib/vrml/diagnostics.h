// Warnings collected while reading (skipped faces, missing inlines, unknown nodes), each
// with file:line:col, summarised by kind so a log stays readable on huge files.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace cadlod::vrml {

struct Diagnostic {
    std::string kind;     // short category, e.g. "bad face", "unknown node"
    std::string where;    // file:line:col
    std::string message;
};

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
