// Clusters that are copies of one another: the same parts placed alike, the whole moved and
// maybe turned, as a rack USE'd again further along a row or turned to face it across an
// aisle. A copy's proxies are its original's, moved the same way: the move is rigid, so
// they keep their error. A copy is cut into clusters as its original is, so that its
// clusters are copies too: the cuts of a turned rack would fall elsewhere. Any turn is found
// (a rack set askew), and a mirror (the left console of a cockpit, the right one's image):
// the writer draws a mirrored copy's proxies with their faces turned back. Placements agree
// within a tolerance, and a turn within a hair of mapping axes onto axes is taken as doing
// so, so that a half turn written with a few decimals ("3.14159") still matches.
#pragma once

#include "lod/cluster_tree.h"
#include "openflight/instanced_writer.h"

#include <cstddef>
#include <vector>

namespace cadlod {

struct ClusterCopy {
    std::size_t original = 0;  // the first cluster this one is a copy of; itself when none
    // Model to model: the original's parts onto this cluster's (a turn, then a move).
    flt::Mat4d move{{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}};
    bool turned() const;    // false: a plain move
    bool mirrored() const;  // seen in a mirror (maybe turned as well)
};

struct SharedCopies {
    std::vector<ClusterNode> nodes;   // the tree, depth first
    std::vector<ClusterCopy> copies;  // of each node
};

// The tree again, each copy given its original's shape: a node whose placements a move (a
// turn or a mirror, then a shift) puts onto those of a node met before it,
// every part's vertices within `tolerance` of where the node has them, gets that node's
// subtree, moved, in place of its own. Its nodes are then copies too, at the same height
// as their originals. An original is never itself a copy. `placedBoxes[p]`: placement p's
// box; `partReach[d]`: how far part definition d's vertices lie from its own origin.
SharedCopies shareCopies(const std::vector<ClusterNode>& tree, const std::vector<flt::PartPlacement>& placements,
                         const std::vector<Box3>& placedBoxes, const std::vector<double>& partReach, double tolerance);

}  // namespace cadlod
