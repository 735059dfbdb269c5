#include "note_lines.h"

#include "progress_bar.h"

#include <cstdio>
#include <map>

namespace cadlod::cli {

std::vector<std::string> foldRepeats(const std::vector<std::string>& lines)
{
    std::vector<std::string> order;
    std::map<std::string, std::size_t> count;
    for (const std::string& line : lines)
        if (count[line]++ == 0)
            order.push_back(line);
    for (std::string& line : order)
        if (const std::size_t n = count[line]; n > 1)
            line += " (×" + std::to_string(n) + ")";
    return order;
}

void printFolded(const std::string& kind, const std::vector<std::string>& lines, std::size_t limit)
{
    const std::vector<std::string> folded = foldRepeats(lines);
    if (!folded.empty())
        progress::finish();
    for (std::size_t i = 0; i < folded.size() && i < limit; ++i)
        std::fprintf(stderr, "cadlod: %s%s%s\n", kind.c_str(), kind.empty() ? "" : ": ", folded[i].c_str());
}

}  // namespace cadlod::cli
