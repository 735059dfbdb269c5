#include "lod/cluster_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace cadlod {

void Box3::add(const std::array<double, 3>& p)
{
    for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
    }
}

void Box3::add(const Box3& b)
{
    if (!b.empty()) {
        add(b.lo);
        add(b.hi);
    }
}

std::array<double, 3> Box3::center() const
{
    return {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
}

double Box3::halfDiagonal() const
{
    if (empty())
        return 0.0;
    const double x = hi[0] - lo[0], y = hi[1] - lo[1], z = hi[2] - lo[2];
    return 0.5 * std::sqrt(x * x + y * y + z * z);
}

namespace {

using Group = std::vector<std::size_t>;

// Gaps that differ by less than this share of the group's extent are alike: copies of a
// rack stand the same gap apart, to the rounding of single-precision vertices.
constexpr double kGapsAlike = 1e-4;

// What a split cuts: boxes, each standing for a number of items (one where no weights).
struct Atoms {
    const std::vector<Box3>& boxes;
    const std::vector<std::size_t>& weights;
};

Box3 centresOf(const Group& g, const std::vector<Box3>& boxes)
{
    Box3 b;
    for (std::size_t i : g)
        b.add(boxes[i].center());
    return b;
}

std::size_t weightOf(const Group& g, const Atoms& atoms)
{
    if (atoms.weights.empty())
        return g.size();
    std::size_t w = 0;
    for (std::size_t i : g)
        w += atoms.weights[i];
    return w;
}

// Where to cut `sorted` (by centre along `axis`): at the widest gap between the boxes on
// either side within its middle half, the one nearest the median of gaps alike, so that
// the pieces of an assembly that stand apart (racks, bays) become clusters of their own,
// and copies of one piece get clusters alike; at the median where no gap is.
std::size_t cutIndex(const Group& sorted, const std::vector<Box3>& boxes, int axis, double extent)
{
    const std::size_t n = sorted.size();
    std::vector<double> lowestRight(n + 1, std::numeric_limits<double>::max());
    for (std::size_t k = n; k-- > 0;)
        lowestRight[k] = std::min(lowestRight[k + 1], boxes[sorted[k]].lo[axis]);
    const double alike = kGapsAlike * extent;
    auto offMedian = [n](std::size_t k) { return k > n / 2 ? k - n / 2 : n / 2 - k; };
    std::size_t cut = n / 2;
    double widest = alike;
    double highestLeft = -std::numeric_limits<double>::max();
    for (std::size_t k = 1; k < n; ++k) {
        highestLeft = std::max(highestLeft, boxes[sorted[k - 1]].hi[axis]);
        if (4 * k < n || 4 * k > 3 * n)
            continue;
        const double gap = lowestRight[k] - highestLeft;
        if (gap > widest + alike || (gap > widest - alike && gap > alike && offMedian(k) < offMedian(cut))) {
            widest = std::max(widest, gap);
            cut = k;
        }
    }
    return cut;
}

// Cuts `g` in two along the widest axis of its centres (cutIndex).
std::pair<Group, Group> bisect(Group g, const std::vector<Box3>& boxes)
{
    const Box3 c = centresOf(g, boxes);
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (c.hi[a] - c.lo[a] > c.hi[axis] - c.lo[axis])
            axis = a;
    std::sort(g.begin(), g.end(), [&](std::size_t a, std::size_t b) {
        const double ca = boxes[a].center()[axis], cb = boxes[b].center()[axis];
        return ca != cb ? ca < cb : a < b;
    });
    const auto middle = g.begin() + std::ptrdiff_t(cutIndex(g, boxes, axis, c.hi[axis] - c.lo[axis]));
    return {Group(g.begin(), middle), Group(middle, g.end())};
}

// Splits `g` (atoms by index) into at most `fanout` groups, the one standing for most items
// cut first, until every group of two atoms or more stands for at most `leafItems`.
std::vector<Group> split(Group g, const Atoms& atoms, const ClusterTreeOptions& options)
{
    std::vector<Group> groups{std::move(g)};
    while (groups.size() < options.fanout) {
        auto largest = groups.end();
        for (auto it = groups.begin(); it != groups.end(); ++it)
            if (it->size() > 1 && (largest == groups.end() || weightOf(*it, atoms) > weightOf(*largest, atoms)))
                largest = it;
        if (largest == groups.end() || weightOf(*largest, atoms) <= options.leafItems)
            break;
        auto halves = bisect(std::move(*largest), atoms.boxes);
        *largest = std::move(halves.first);
        groups.push_back(std::move(halves.second));
    }
    return groups;
}

// The pieces of `g` at the first depth at which their paths differ; an item whose path
// ends there is a piece of its own.
std::vector<Group> piecesOf(const Group& g, const AssemblyPaths& paths)
{
    const std::vector<std::size_t>& first = paths[g.front()];
    std::size_t depth = 0;
    while (depth < first.size() && std::all_of(g.begin(), g.end(), [&](std::size_t i) {
               return depth < paths[i].size() && paths[i][depth] == first[depth];
           }))
        ++depth;
    std::map<std::pair<std::size_t, std::size_t>, Group> pieces;  // (group, 0) or (item, 1)
    for (std::size_t i : g)
        pieces[depth < paths[i].size() ? std::make_pair(paths[i][depth], std::size_t(0)) : std::make_pair(i, std::size_t(1))]
            .push_back(i);
    std::vector<Group> out;
    for (auto& [key, piece] : pieces)
        out.push_back(std::move(piece));
    return out;
}

Box3 boxOf(const Group& g, const std::vector<Box3>& items)
{
    Box3 box;
    for (std::size_t i : g)
        box.add(items[i]);
    return box;
}

// Whether the assembly's pieces of a node (box `all`) are to be kept whole: some hold more
// than one item, and none of those is larger than kAssemblyPieceShare of the node.
bool keepWhole(const std::vector<Group>& pieces, const std::vector<Box3>& boxes, const Box3& all)
{
    bool grouped = false;
    for (std::size_t p = 0; p < pieces.size(); ++p)
        if (pieces[p].size() > 1) {
            if (boxes[p].halfDiagonal() > kAssemblyPieceShare * all.halfDiagonal())
                return false;
            grouped = true;
        }
    return grouped;
}

// The children of a node holding `g` (box `all`): the pieces the assembly makes of it, when
// they are to be kept whole (keepWhole), grouped by their boxes where there are more than
// `fanout`; otherwise the items grouped by their boxes.
std::vector<Group> childrenOf(Group g, const Box3& all, const std::vector<Box3>& items, const AssemblyPaths& paths,
                              const ClusterTreeOptions& options)
{
    static const std::vector<std::size_t> kOneEach;
    const std::vector<Group> pieces = paths.empty() ? std::vector<Group>{} : piecesOf(g, paths);
    std::vector<Box3> boxes;
    std::vector<std::size_t> weights;
    for (const Group& piece : pieces) {
        boxes.push_back(boxOf(piece, items));
        weights.push_back(piece.size());
    }
    if (!keepWhole(pieces, boxes, all))
        return split(std::move(g), Atoms{items, kOneEach}, options);
    if (pieces.size() <= options.fanout)
        return pieces;
    Group every(pieces.size());
    std::iota(every.begin(), every.end(), std::size_t(0));
    std::vector<Group> children;
    for (const Group& group : split(std::move(every), Atoms{boxes, weights}, options)) {
        Group& child = children.emplace_back();
        for (std::size_t a : group)
            child.insert(child.end(), pieces[a].begin(), pieces[a].end());
    }
    return children;
}

// Takes out of `g` the items nearly as large as the whole group (box `all`), at most
// `leafItems` of them: below, each would make the cluster holding it about as large as this
// one, and keep its smaller neighbours from being drawn together until as far off.
Group takeLarge(Group& g, const Box3& all, const std::vector<Box3>& items, const ClusterTreeOptions& options)
{
    if (options.largeShare <= 0)
        return {};
    const double large = options.largeShare * all.halfDiagonal();
    Group held;
    for (std::size_t i : g)
        if (items[i].halfDiagonal() > large)
            held.push_back(i);
    if (held.empty() || held.size() > options.leafItems || held.size() == g.size())
        return {};
    std::sort(held.begin(), held.end());
    g.erase(std::remove_if(g.begin(), g.end(),
                           [&](std::size_t i) { return std::binary_search(held.begin(), held.end(), i); }),
            g.end());
    return held;
}

void buildNode(std::vector<ClusterNode>& nodes, std::size_t index, Group g, const std::vector<Box3>& items,
               const AssemblyPaths& paths, const ClusterTreeOptions& options)
{
    for (std::size_t i : g)
        nodes[index].box.add(items[i]);
    if (g.size() > options.leafItems)
        nodes[index].items = takeLarge(g, nodes[index].box, items, options);
    if (g.size() <= options.leafItems) {
        nodes[index].items.insert(nodes[index].items.end(), g.begin(), g.end());
        std::sort(nodes[index].items.begin(), nodes[index].items.end());
        return;
    }
    std::vector<Group> children = childrenOf(std::move(g), nodes[index].box, items, paths, options);
    for (Group& child : children) {
        const std::size_t c = nodes.size();
        nodes[index].children.push_back(c);
        nodes.emplace_back();
        buildNode(nodes, c, std::move(child), items, paths, options);
    }
}

}  // namespace

std::vector<ClusterNode> buildClusterTree(const std::vector<Box3>& items, const ClusterTreeOptions& options,
                                          const AssemblyPaths& paths)
{
    std::vector<ClusterNode> nodes;
    if (items.empty())
        return nodes;
    ClusterTreeOptions o = options;
    o.leafItems = std::max<std::size_t>(o.leafItems, 1);
    o.fanout = std::max<std::size_t>(o.fanout, 2);
    Group all(items.size());
    std::iota(all.begin(), all.end(), std::size_t(0));
    nodes.emplace_back();
    static const AssemblyPaths kNone;
    buildNode(nodes, 0, std::move(all), items, paths.size() == items.size() ? paths : kNone, o);
    return nodes;
}

}  // namespace cadlod
