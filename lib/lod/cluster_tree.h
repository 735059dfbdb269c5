// A spatial hierarchy of placed parts (design.md §5, HLOD): boxes grouped top-down into
// clusters of nearby boxes, so that a viewer near one part is far from most clusters. Each
// split cuts the largest group along the widest axis of its box centres, at the widest gap
// between its boxes in the middle half of them (the median where there is none), until a
// node has `fanout` groups; a node of at most `leafItems` boxes is a leaf. Optionally
// a box nearly as large as its whole group (a board under its parts) stays at the node above
// the split, so that the clusters below are as small as their other boxes. Where the
// assembly groups a node's boxes into compact pieces (racks, boards, stations: the paths of
// the placements' names), no piece is cut: a few are its children, however close they
// stand, and more than `fanout` are grouped by their boxes. Plain data:
// no mesh type.
#pragma once

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace cadlod {

struct Box3 {
    std::array<double, 3> lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::max()};
    std::array<double, 3> hi{-std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
                             -std::numeric_limits<double>::max()};

    bool empty() const { return lo[0] > hi[0]; }
    void add(const std::array<double, 3>& p);
    void add(const Box3& b);
    std::array<double, 3> center() const;
    double halfDiagonal() const;  // the radius of the sphere about center() holding the box
};

struct ClusterNode {
    Box3 box;
    std::vector<std::size_t> items;     // the boxes held here, by index: a leaf's all, above only large ones
    std::vector<std::size_t> children;  // the nodes below, by index (after this one)
    bool leaf() const { return children.empty(); }
};

struct ClusterTreeOptions {
    std::size_t leafItems = 48;
    std::size_t fanout = 8;
    // A box stays above a split when its half-diagonal exceeds this share of its group's, and
    // at most `leafItems` boxes do (0: every box goes down to a leaf).
    double largeShare = 0;
};

// Where each item sits in the assembly: the names of the groups above it, outermost first,
// then its own, each as a number (equal numbers at one depth: the same group). Empty: boxes
// only.
using AssemblyPaths = std::vector<std::vector<std::size_t>>;

// A node's pieces in the assembly are the groups its items form at the first depth at which
// their paths differ. They are kept whole when each piece of two items or more has a
// half-diagonal of at most this share of the node's: a piece nearly as large as the node (a
// loose subassembly) is cut better by its boxes. Kept whole, 2 to `fanout` pieces are the
// node's children; more are grouped into `fanout` children by their boxes.
inline constexpr double kAssemblyPieceShare = 0.75;

// nodes[0] is the root; every item is held by exactly one node. Empty for no items.
std::vector<ClusterNode> buildClusterTree(const std::vector<Box3>& items, const ClusterTreeOptions& options = {},
                                          const AssemblyPaths& paths = {});

}  // namespace cadlod
