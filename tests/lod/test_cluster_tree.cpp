#include "lod/cluster_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

namespace cadlod {
namespace {

Box3 cube(double x, double y, double z, double half)
{
    Box3 b;
    b.add(std::array<double, 3>{x - half, y - half, z - half});
    b.add(std::array<double, 3>{x + half, y + half, z + half});
    return b;
}

// A grid of n x n small cubes at unit pitch on z = 0.
std::vector<Box3> grid(int n)
{
    std::vector<Box3> boxes;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            boxes.push_back(cube(i, j, 0, 0.2));
    return boxes;
}

// Which node holds each item; -1 where none, -2 where more than one.
std::vector<int> holders(const std::vector<ClusterNode>& nodes, std::size_t count)
{
    std::vector<int> holder(count, -1);
    for (std::size_t n = 0; n < nodes.size(); ++n)
        for (std::size_t i : nodes[n].items)
            holder[i] = holder[i] == -1 ? int(n) : -2;
    return holder;
}

bool contains(const Box3& outer, const Box3& inner)
{
    for (int a = 0; a < 3; ++a)
        if (inner.lo[a] < outer.lo[a] || inner.hi[a] > outer.hi[a])
            return false;
    return true;
}

TEST(ClusterTree, EveryItemIsHeldOnceAndEveryBoxHoldsWhatIsBelow)
{
    std::vector<Box3> boxes = grid(12);
    boxes.push_back(cube(5.5, 5.5, -0.5, 6.5));  // a board under the parts
    const std::vector<ClusterNode> nodes = buildClusterTree(boxes, {4, 3, 0.5});
    const std::vector<int> holder = holders(nodes, boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        ASSERT_GE(holder[i], 0) << "item " << i;
        EXPECT_TRUE(contains(nodes[std::size_t(holder[i])].box, boxes[i])) << "item " << i;
    }
    for (std::size_t n = 0; n < nodes.size(); ++n) {
        EXPECT_LE(nodes[n].children.size(), 3u);
        EXPECT_LE(nodes[n].items.size(), 4u);
        EXPECT_FALSE(nodes[n].leaf() && nodes[n].items.empty());
        for (std::size_t child : nodes[n].children) {
            ASSERT_GT(child, n);
            EXPECT_TRUE(contains(nodes[n].box, nodes[child].box));
        }
    }
}

TEST(ClusterTree, ABoardUnderItsPartsStaysAboveTheSplit)
{
    std::vector<Box3> boxes = grid(8);
    const std::size_t board = boxes.size();
    boxes.push_back(cube(3.5, 3.5, -0.5, 4.5));
    const std::vector<ClusterNode> nodes = buildClusterTree(boxes, {2, 2, 0.5});
    ASSERT_FALSE(nodes.empty());
    const std::vector<std::size_t>& top = nodes.front().items;
    EXPECT_NE(std::find(top.begin(), top.end(), board), top.end());
    EXPECT_EQ(top.size(), 1u);
    // Below the board, every cluster is as small as its parts make it: a leaf of two
    // neighbouring parts spans two pitches at most.
    for (const ClusterNode& node : nodes)
        if (node.leaf())
            EXPECT_LT(node.box.halfDiagonal(), 1.0);
}

TEST(ClusterTree, PartsOfOneSizeAreHeldOnlyByLeaves)
{
    const std::vector<Box3> boxes = grid(10);
    const std::vector<ClusterNode> nodes = buildClusterTree(boxes, {2, 2, 0.5});
    for (const ClusterNode& node : nodes) {
        EXPECT_TRUE(node.leaf() || node.items.empty());
        if (node.leaf())
            EXPECT_LE(node.items.size(), 2u);
    }
}

TEST(ClusterTree, WithoutALargeShareEveryBoxGoesDownToALeaf)
{
    std::vector<Box3> boxes = grid(8);
    const std::size_t board = boxes.size();
    boxes.push_back(cube(3.5, 3.5, -0.5, 4.5));
    const std::vector<ClusterNode> nodes = buildClusterTree(boxes, {2, 2});
    for (const ClusterNode& node : nodes) {
        EXPECT_TRUE(node.leaf() || node.items.empty());
        if (std::find(node.items.begin(), node.items.end(), board) != node.items.end())
            EXPECT_GT(node.box.halfDiagonal(), 4.5);
    }
}

// Three racks of 4 x 4 parts, a rack's width apart: each rack is a cluster of its own, not
// cut at the median through the middle one.
TEST(ClusterTree, RacksThatStandApartAreClustersOfTheirOwn)
{
    std::vector<Box3> boxes;
    for (int rack = 0; rack < 3; ++rack)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
                boxes.push_back(cube(8.0 * rack + i, j, 0, 0.2));
    const std::vector<ClusterNode> nodes = buildClusterTree(boxes, {16, 8});
    ASSERT_FALSE(nodes.empty());
    ASSERT_EQ(nodes.front().children.size(), 3u);
    for (std::size_t child : nodes.front().children) {
        const ClusterNode& rack = nodes[child];
        ASSERT_EQ(rack.items.size(), 16u);
        const std::size_t first = rack.items.front() / 16;
        for (std::size_t i : rack.items)
            EXPECT_EQ(i / 16, first) << "a cluster holds parts of two racks";
    }
}

// Four racks of 16 parts set askew, each rack's box overlapping its neighbours': no gap
// parts them, and boxes alone cut across racks. The assembly's paths make each rack a
// cluster of its own; with one path for all, the boxes decide again.
TEST(ClusterTree, RacksTheAssemblyNamesAreClustersThoughTheirBoxesOverlap)
{
    std::vector<Box3> boxes;
    AssemblyPaths racks, oneGroup;
    for (std::size_t rack = 0; rack < 4; ++rack)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) {
                boxes.push_back(cube(4.0 * double(rack) + i + j, j - i, 0, 0.2));  // 45 degrees
                racks.push_back({7, rack});
                oneGroup.push_back({7});
            }
    auto racksKeptWhole = [&](const std::vector<ClusterNode>& nodes) {
        for (std::size_t child : nodes.front().children)
            for (std::size_t i : nodes[child].items)
                if (i / 16 != nodes[child].items.front() / 16)
                    return false;
        return nodes.front().children.size() == 4;
    };
    EXPECT_TRUE(racksKeptWhole(buildClusterTree(boxes, {16, 8}, racks)));
    EXPECT_FALSE(racksKeptWhole(buildClusterTree(boxes, {16, 8}, oneGroup)));
    EXPECT_FALSE(racksKeptWhole(buildClusterTree(boxes, {16, 8})));
}

// Whether every leaf holds items of one piece only (items of a piece numbered together,
// `perPiece` each) and holds all of them.
bool piecesKeptWhole(const std::vector<ClusterNode>& nodes, std::size_t perPiece)
{
    for (const ClusterNode& node : nodes)
        if (node.leaf()) {
            if (node.items.size() != perPiece)
                return false;
            for (std::size_t i : node.items)
                if (i / perPiece != node.items.front() / perPiece)
                    return false;
        }
    return true;
}

// Six askew racks under a node of at most three children: the racks are grouped by their
// boxes, none is cut.
TEST(ClusterTree, MoreRacksThanANodeHasChildrenAreGroupedNotCut)
{
    std::vector<Box3> boxes;
    AssemblyPaths racks;
    for (std::size_t rack = 0; rack < 6; ++rack)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i) {
                boxes.push_back(cube(4.0 * double(rack) + i + j, j - i, 0, 0.2));
                racks.push_back({7, rack});
            }
    EXPECT_TRUE(piecesKeptWhole(buildClusterTree(boxes, {16, 3}, racks), 16));
    EXPECT_FALSE(piecesKeptWhole(buildClusterTree(boxes, {16, 3}), 16));
}

// Ten stations of 12 parts along a line, each its own group, and one beam under them all:
// the stations stay whole, more of them than a node has children.
TEST(ClusterTree, StationsAlongABeamStayWhole)
{
    std::vector<Box3> boxes;
    AssemblyPaths paths;
    for (std::size_t station = 0; station < 10; ++station)
        for (int i = 0; i < 12; ++i) {
            boxes.push_back(cube(10.0 * double(station) + i % 4 + 0.35 * (i / 4), i / 4, 1, 0.3));
            paths.push_back({0, 1 + station});
        }
    const std::size_t beamItem = boxes.size();
    Box3 beam;
    beam.add(std::array<double, 3>{-1, 0, -0.5});
    beam.add(std::array<double, 3>{100, 2, 0});
    boxes.push_back(beam);
    paths.push_back({0});
    const std::vector<ClusterNode> nodes = buildClusterTree(boxes, {16, 4}, paths);
    for (const ClusterNode& node : nodes) {
        if (!node.leaf())
            continue;
        std::size_t station = beamItem;
        for (std::size_t i : node.items)
            if (i < beamItem) {
                EXPECT_TRUE(station == beamItem || station == i / 12) << "a leaf holds parts of two stations";
                station = i / 12;
            }
    }
    for (std::size_t s = 0; s < 10; ++s) {
        std::size_t holder = nodes.size();
        for (std::size_t n = 0; n < nodes.size(); ++n)
            for (std::size_t i : nodes[n].items)
                if (i / 12 == s && i < beamItem) {
                    EXPECT_TRUE(holder == nodes.size() || holder == n) << "station " << s << " is cut";
                    holder = n;
                }
    }
}

// Two pieces each nearly as large as the whole (two interleaved combs): the assembly's
// pieces would make clusters no smaller than their parent, and the boxes cut instead.
TEST(ClusterTree, PiecesNearlyAsLargeAsTheirNodeAreCutByTheirBoxes)
{
    std::vector<Box3> boxes;
    AssemblyPaths paths;
    for (int i = 0; i < 40; ++i) {
        boxes.push_back(cube(i, 0, 0, 0.2));
        paths.push_back({std::size_t(i % 2)});
    }
    const std::vector<ClusterNode> nodes = buildClusterTree(boxes, {8, 2}, paths);
    ASSERT_EQ(nodes.front().children.size(), 2u);
    for (std::size_t child : nodes.front().children)
        EXPECT_LT(nodes[child].box.hi[0] - nodes[child].box.lo[0], 30.0);
}

TEST(ClusterTree, NoItemsNoNodes)
{
    EXPECT_TRUE(buildClusterTree({}).empty());
}

}  // namespace
}  // namespace cadlod
