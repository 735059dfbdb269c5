// Lists of warnings and notes on stderr, where one cause can give the same line many times
// (a USE'd shape with a bad face, expanded once per use): each line once, with its count.
#pragma once
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace cadlod::cli {

// The distinct lines in order of first appearance, a repeated one ending in " (×N)".
std::vector<std::string> foldRepeats(const std::vector<std::string>& lines);

// "cadlod: <kind>: <line>" ("cadlod: <line>" without a kind) for each folded line, at most `limit` of them, below any
// progress bar line.
void printFolded(const std::string& kind, const std::vector<std::string>& lines,
                 std::size_t limit = std::numeric_limits<std::size_t>::max());

}  // namespace cadlod::cli
