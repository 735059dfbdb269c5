// The log of components removed whole (component_removal.h): one line per part name.
//
// A user reads the log to learn which parts vanished. A scene of thousands of copies of one
// name (a forest of "Mesh" trees) or a part of thousands of loose pieces would otherwise
// print a line per piece; each name gets one line instead, rewritten as its count grows:
// how many, their faces in all, the largest, and the farthest any stood off the rest.
// Pieces without a part name (logged as "component N") share one line.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <string>
#include <unordered_map>
#include <vector>

namespace cadlod {

class RemovalLog
{
public:
    // One removal of `name` (`named`: a CAD part's name, not "component N"; faces, size and
    // distance off the rest in model units) into `lines`: its name's line is rewritten in
    // place while it is still there as written (a caller may have taken the lines away
    // since), else a new line is added.
    void add(std::vector<std::string>& lines, const std::string& name, bool named, std::size_t faces, double size,
             double standingOff, double diagonal)
    {
        const bool unnamed = !named;
        Tally& t = tallies_[unnamed ? std::string() : name];
        if (t.line >= lines.size() || lines[t.line] != t.text)
            t = Tally{lines.size(), std::string(), name};
        ++t.count;
        t.faces += faces;
        t.largest = std::max(t.largest, size);
        t.farthestOff = std::max(t.farthestOff, standingOff > size ? standingOff : 0.0);
        t.text = lineOf(t, unnamed, diagonal);
        if (t.line == lines.size())
            lines.push_back(t.text);
        else
            lines[t.line] = t.text;
    }

private:
    struct Tally {
        std::size_t line = 0;
        std::string text;
        std::string firstName;  // the name of the first piece: a lone piece keeps its own
        int count = 0;
        std::size_t faces = 0;
        double largest = 0.0, farthestOff = 0.0;
    };

    static std::string lineOf(const Tally& t, bool unnamed, double diagonal)
    {
        const double percent = diagonal > 0 ? 100.0 / diagonal : 0.0;
        char off[80] = "";
        char line[480];
        if (t.count == 1) {
            if (t.farthestOff > 0)
                std::snprintf(off, sizeof off, ", standing %.4g %% off the rest", percent * t.farthestOff);
            std::snprintf(line, sizeof line, "removed %s whole (%zu face%s, size %.4g %% of the diagonal%s)",
                          t.firstName.c_str(), t.faces, t.faces == 1 ? "" : "s", percent * t.largest, off);
            return line;
        }
        if (t.farthestOff > 0)
            std::snprintf(off, sizeof off, ", standing up to %.4g %% off the rest", percent * t.farthestOff);
        const std::string what =
            unnamed ? std::to_string(t.count) + " unnamed components" : std::to_string(t.count) + " pieces of " + t.firstName;
        std::snprintf(line, sizeof line, "removed %s whole (%zu faces in all, the largest %.4g %% of the diagonal%s)",
                      what.c_str(), t.faces, percent * t.largest, off);
        return line;
    }

    std::unordered_map<std::string, Tally> tallies_;
};

}  // namespace cadlod
