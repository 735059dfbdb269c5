#include "openflight/lod_assembly.h"

#include <algorithm>

namespace cadlod::flt {
namespace {

std::string levelText(int level) { return "level " + std::to_string(level); }

bool checkRanges(const std::vector<LodSetMember>& set, std::string& error)
{
    for (std::size_t i = 0; i < set.size(); ++i) {
        const Level& l = set[i].geometry;
        if (!(l.switchOut >= 0.0 && l.switchIn > l.switchOut)) {
            error = levelText(set[i].level) + " has no usable switch range (switch-out " +
                    std::to_string(l.switchOut) + ", switch-in " + std::to_string(l.switchIn) + ")";
            return false;
        }
        if (i > 0) {
            const Level& prev = set[i - 1].geometry;
            if (l.switchOut < prev.switchOut || l.switchIn < prev.switchIn) {
                error = levelText(set[i].level) + " is shown nearer than " + levelText(set[i - 1].level) +
                        " (ranges must move outwards with the level)";
                return false;
            }
        }
    }
    return true;
}

}  // namespace

bool assembleLodSet(std::vector<LodSetMember> members, int setId, LodModel& model, std::string& error)
{
    std::vector<LodSetMember> set;
    for (LodSetMember& m : members)
        if (m.setId == setId)
            set.push_back(std::move(m));
    std::sort(set.begin(), set.end(), [](const LodSetMember& a, const LodSetMember& b) { return a.level < b.level; });
    const std::string prefix = "LOD set " + std::to_string(setId) + ": ";
    if (set.empty() || set.front().level != 0) {
        error = prefix + "no layer holds level 0 (the original)";
        return false;
    }
    for (std::size_t i = 1; i < set.size(); ++i)
        if (set[i].level == set[i - 1].level) {
            error = prefix + "two layers hold " + levelText(set[i].level);
            return false;
        }
    if (!checkRanges(set, error)) {
        error = prefix + error;
        return false;
    }
    model.levels.clear();
    for (LodSetMember& m : set) {
        if (m.geometry.name.empty())
            m.geometry.name = "lod" + std::to_string(m.level);
        model.levels.push_back(std::move(m.geometry));
    }
    return true;
}

}  // namespace cadlod::flt
