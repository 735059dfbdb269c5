#include "assembly/cluster_copies.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace cadlod {
namespace {

using flt::Mat4d;

// A turn part this near to mapping axes onto axes is taken as doing so exactly (a half turn
// written "3.14159"); placedAlike then says whether the parts still land.
constexpr double kAxisSlack = 1e-5;

// A move whose columns are unit and square to one another within this keeps lengths.
constexpr double kLengthSlack = 1e-5;

// `move` with its turn made exactly the axis turn it nearly is, about the centre of box
// `from`, then shifted to the centre of box `to` (a turn that maps axes onto axes maps the
// one box onto the other); unchanged when its turn is no axis turn.
Mat4d snappedToAxes(Mat4d move, const Box3& from, const Box3& to)
{
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
            if (std::abs(move[r][c] - std::round(move[r][c])) > kAxisSlack)
                return move;
    const auto a = from.center();
    const auto b = to.center();
    for (int r = 0; r < 3; ++r) {
        move[r][3] = b[r];
        for (int c = 0; c < 3; ++c) {
            move[r][c] = std::round(move[r][c]) + 0.0;  // no negative zero
            move[r][3] -= move[r][c] * a[c];
        }
    }
    return move;
}

// Whether `move` keeps lengths (a turn or a mirror, then a shift): a copy scaled up would
// show its original's proxies' error scaled too.
bool keepsLengths(const Mat4d& move)
{
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) {
            double dot = 0;
            for (int r = 0; r < 3; ++r)
                dot += move[r][a] * move[r][b];
            if (std::abs(dot - (a == b ? 1.0 : 0.0)) > kLengthSlack)
                return false;
        }
    return true;
}

// How far apart two placements of one part put its vertices, at most (`reach`: how far
// they lie from the part's origin).
double placedApart(const Mat4d& a, const Mat4d& b, double reach)
{
    double turn = 0, move = 0;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c)
            turn += (a[r][c] - b[r][c]) * (a[r][c] - b[r][c]);
        move += (a[r][3] - b[r][3]) * (a[r][3] - b[r][3]);
    }
    return std::sqrt(move) + std::sqrt(turn) * reach;
}

// Walks the tree depth first. A node that is a copy of an original met before it (the
// original's subtree is then complete) gets the original's subtree, moved; any other node
// is an original, and its children are walked.
class CopySharing {
public:
    CopySharing(const std::vector<ClusterNode>& tree, const std::vector<flt::PartPlacement>& placements,
                const std::vector<Box3>& placedBoxes, const std::vector<double>& partReach, double tolerance)
        : tree_(tree), placements_(placements), placedBoxes_(placedBoxes), partReach_(partReach),
          tolerance_(tolerance), below_(tree.size()), landing_(placements.size())
    {
        for (std::size_t n = tree_.size(); n-- > 0;)  // a child's index is above its parent's
            gatherBelow(n);
    }

    SharedCopies share()
    {
        if (!tree_.empty())
            walk(0);
        return std::move(out_);
    }

private:
    void gatherBelow(std::size_t n)
    {
        std::vector<std::size_t>& below = below_[n];
        for (std::size_t child : tree_[n].children)
            below.insert(below.end(), below_[child].begin(), below_[child].end());
        below.insert(below.end(), tree_[n].items.begin(), tree_[n].items.end());
    }

    // Tree node n into the output; returns its index there.
    std::size_t walk(std::size_t n)
    {
        const std::size_t at = addNode(tree_[n].box);
        std::vector<std::size_t>& same = originals_[kind(n)];
        const std::vector<std::size_t> mine = byPartAndX(n);
        for (std::size_t o : same)
            for (const Mat4d& move : movesOnto(o, n, mine))
                if (placedAlike(treeNodeOf_[o], move, mine)) {
                    image(o, at, move);
                    return at;
                }
        same.push_back(at);
        treeNodeOf_[at] = n;
        out_.nodes[at].items = tree_[n].items;
        for (std::size_t child : tree_[n].children) {
            const std::size_t c = walk(child);
            out_.nodes[at].children.push_back(c);
        }
        return at;
    }

    std::size_t addNode(const Box3& box)
    {
        const std::size_t at = out_.nodes.size();
        out_.nodes.emplace_back().box = box;
        out_.copies.emplace_back().original = at;
        return at;
    }

    // Output node `at` made the image of output node o under `move`, the placements landing
    // where placedAlike found them, its subtree the image of o's.
    void image(std::size_t o, std::size_t at, const Mat4d& move)
    {
        const ClusterCopy of = out_.copies[o];  // by value: addNode below may move it
        out_.copies[at].original = of.original;
        out_.copies[at].move = of.original == o ? move : flt::multiply(move, of.move);
        Box3 box;
        for (std::size_t p : out_.nodes[o].items) {
            out_.nodes[at].items.push_back(landing_[p]);
            box.add(placedBoxes_[landing_[p]]);
        }
        for (std::size_t k = 0; k < out_.nodes[o].children.size(); ++k) {
            const std::size_t c = addNode({});
            out_.nodes[at].children.push_back(c);
            image(out_.nodes[o].children[k], c, move);
            box.add(out_.nodes[c].box);
        }
        out_.nodes[at].box = box;
    }

    // What any copy of tree node n shares with it: its parts, sorted.
    std::vector<std::size_t> kind(std::size_t n) const
    {
        std::vector<std::size_t> key;
        for (std::size_t p : below_[n])
            key.push_back(placements_[p].definition);
        std::sort(key.begin(), key.end());
        return key;
    }

    std::vector<std::size_t> byPartAndX(std::size_t n) const
    {
        std::vector<std::size_t> sorted = below_[n];
        std::sort(sorted.begin(), sorted.end(), [&](std::size_t a, std::size_t b) { return before(a, b); });
        return sorted;
    }

    bool before(std::size_t a, std::size_t b) const
    {
        const flt::PartPlacement& pa = placements_[a];
        const flt::PartPlacement& pb = placements_[b];
        if (pa.definition != pb.definition)
            return pa.definition < pb.definition;
        return pa.matrix[0][3] < pb.matrix[0][3];
    }

    // The moves that may make tree node n, its placements `mine` (sorted by part and x), a
    // copy of original o (in the output): each puts o's first placement of its rarest part
    // onto one of n's of that part, as a turn or a mirror and a shift. Plain moves first,
    // then turns, then mirrors, so that a copy that is also symmetric is found moved, not
    // turned, and turned, not mirrored.
    std::vector<Mat4d> movesOnto(std::size_t o, std::size_t n, const std::vector<std::size_t>& mine) const
    {
        const std::vector<std::size_t>& theirs = below_[treeNodeOf_.at(o)];
        const std::size_t part = rarestPart(theirs);
        const std::size_t anchor = *std::find_if(theirs.begin(), theirs.end(),
                                                 [&](std::size_t p) { return placements_[p].definition == part; });
        const Mat4d undo = flt::inverse(placements_[anchor].matrix);
        std::vector<Mat4d> moves;
        for (std::size_t q : mine) {
            if (placements_[q].definition != part)
                continue;
            const Mat4d move =
                snappedToAxes(flt::multiply(placements_[q].matrix, undo), out_.nodes[o].box, tree_[n].box);
            if (keepsLengths(move) && std::find(moves.begin(), moves.end(), move) == moves.end())
                moves.push_back(move);
        }
        std::stable_partition(moves.begin(), moves.end(), [](const Mat4d& m) { return !flt::mirrors(m); });
        std::stable_partition(moves.begin(), moves.end(), [](const Mat4d& m) { return !flt::turns(m); });
        return moves;
    }

    // Of `placements`, the part placed fewest times (the lowest-numbered of those).
    std::size_t rarestPart(const std::vector<std::size_t>& placements) const
    {
        std::map<std::size_t, std::size_t> count;
        for (std::size_t p : placements)
            ++count[placements_[p].definition];
        auto rarest = count.begin();
        for (auto it = count.begin(); it != count.end(); ++it)
            if (it->second < rarest->second)
                rarest = it;
        return rarest->first;
    }

    // Every placement below tree node o, moved, lands on a placement of the same part among
    // `mine` (sorted by part and x), each taken once; landing_ says where.
    bool placedAlike(std::size_t o, const Mat4d& move, const std::vector<std::size_t>& mine)
    {
        std::vector<bool> taken(mine.size(), false);
        for (std::size_t p : below_[o]) {
            const flt::PartPlacement& from = placements_[p];
            const Mat4d moved = flt::multiply(move, from.matrix);
            const double reach = partReach_[from.definition];
            auto at = std::lower_bound(mine.begin(), mine.end(), 0, [&](std::size_t q, int) {
                const flt::PartPlacement& pq = placements_[q];
                return pq.definition != from.definition ? pq.definition < from.definition
                                                        : pq.matrix[0][3] < moved[0][3] - tolerance_;
            });
            bool landed = false;
            for (; at != mine.end() && !landed; ++at) {
                const flt::PartPlacement& pq = placements_[*at];
                if (pq.definition != from.definition || pq.matrix[0][3] > moved[0][3] + tolerance_)
                    break;
                const std::size_t i = std::size_t(at - mine.begin());
                landed = !taken[i] && placedApart(moved, pq.matrix, reach) <= tolerance_;
                if (landed) {
                    taken[i] = true;
                    landing_[p] = *at;
                }
            }
            if (!landed)
                return false;
        }
        return true;
    }

    const std::vector<ClusterNode>& tree_;
    const std::vector<flt::PartPlacement>& placements_;
    const std::vector<Box3>& placedBoxes_;
    const std::vector<double>& partReach_;
    const double tolerance_;
    std::vector<std::vector<std::size_t>> below_;     // per tree node
    std::vector<std::size_t> landing_;                // per placement: where the last match put it
    std::map<std::vector<std::size_t>, std::vector<std::size_t>> originals_;  // output nodes, by kind
    std::map<std::size_t, std::size_t> treeNodeOf_;  // of each original in the output
    SharedCopies out_;
};

}  // namespace

bool ClusterCopy::turned() const { return flt::turns(move); }

bool ClusterCopy::mirrored() const { return flt::mirrors(move); }

SharedCopies shareCopies(const std::vector<ClusterNode>& tree, const std::vector<flt::PartPlacement>& placements,
                         const std::vector<Box3>& placedBoxes, const std::vector<double>& partReach, double tolerance)
{
    return CopySharing(tree, placements, placedBoxes, partReach, tolerance).share();
}

}  // namespace cadlod
