// The bound on how many triangles a scene may expand to. DEF/USE makes a few hundred bytes
// describe billions of triangles (a USE of a group of USEs of ...), so before a subtree is
// evaluated its triangles are counted from the node tree alone: once per distinct node
// (memoised), then summed over references, which multiplies them out without expanding
// anything. A file that would exceed the limit stops with an error naming the reference
// (usually a USE) whose expansion crosses it.
#pragma once

#include "vrml/node.h"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace cadlod::vrml {

// The triangle limit for a scene read from `inputBytes` bytes (main file and inlines,
// inflated): the larger of an absolute floor and a multiple of the input size.
uint64_t triangleLimit(uint64_t maxTriangles, double maxTrianglesPerInputByte, uint64_t inputBytes);

class InstancingBudget {
public:
    // Upper bound of the triangles `node` emits when evaluated (faces of n corners count
    // n - 2; bad faces, which the emitter skips, are counted too). Saturates at UINT64_MAX.
    uint64_t triangles(const Node& node, bool vrml1);

    // "" when `nodes` (with `useSites`, as written in the file) fit into `limit` triangles on
    // top of `used`; otherwise the error naming the reference whose expansion crosses it.
    std::string check(const std::vector<NodePtr>& nodes, const std::vector<UseSite>& useSites, bool vrml1,
                      uint64_t used, uint64_t limit);

private:
    uint64_t computeAll(const Node& root, bool vrml1);

    std::unordered_map<const Node*, uint64_t> triangles_;
};

}  // namespace cadlod::vrml
