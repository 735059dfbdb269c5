// Clusters that are copies of others (cluster_copies.h): moved, or turned and moved as a
// rack turned to face an aisle, with turns written to a few decimals, or set askew, or seen
// in a mirror; and clusters alike in parts that are not copies.
#include "assembly/cluster_copies.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cadlod::test {
namespace {

constexpr double kTolerance = 1e-5;
constexpr double kHalf = 0.5;  // every part a unit cube about its origin
const std::vector<double> kReach{std::sqrt(3.0) * kHalf, std::sqrt(3.0) * kHalf};

flt::PartPlacement at(std::size_t definition, double x, double y, double turnAboutZ = 0)
{
    flt::PartPlacement p;
    p.definition = definition;
    p.matrix[0] = {std::cos(turnAboutZ), -std::sin(turnAboutZ), 0, x};
    p.matrix[1] = {std::sin(turnAboutZ), std::cos(turnAboutZ), 0, y};
    return p;
}

// The placement p turned about the z axis through (cx, cy), then moved up y by `shift`, as a
// parent Transform does.
flt::PartPlacement turnedAbout(flt::PartPlacement p, double angle, double cx, double cy, double shift)
{
    const double c = std::cos(angle), s = std::sin(angle);
    flt::Mat4d out = p.matrix;
    for (int k = 0; k < 4; ++k) {
        out[0][k] = c * p.matrix[0][k] - s * p.matrix[1][k];
        out[1][k] = s * p.matrix[0][k] + c * p.matrix[1][k];
    }
    out[0][3] += cx - (c * cx - s * cy);
    out[1][3] += cy - (s * cx + c * cy) + shift;
    p.matrix = out;
    return p;
}

Box3 boxOf(const flt::PartPlacement& placement)
{
    Box3 box;
    for (int corner = 0; corner < 8; ++corner) {
            const double local[3] = {corner & 1 ? kHalf : -kHalf, corner & 2 ? kHalf : -kHalf,
                                     corner & 4 ? kHalf : -kHalf};
            std::array<double, 3> p{};
            for (int r = 0; r < 3; ++r)
                p[r] = placement.matrix[r][0] * local[0] + placement.matrix[r][1] * local[1] +
                       placement.matrix[r][2] * local[2] + placement.matrix[r][3];
            box.add(p);
    }
    return box;
}

// The tree of `children` and `items` per node, its boxes made from the placements', shared.
SharedCopies shared(const std::vector<flt::PartPlacement>& placements,
                    const std::vector<std::vector<std::size_t>>& children,
                    const std::vector<std::vector<std::size_t>>& items)
{
    std::vector<Box3> boxes;
    for (const flt::PartPlacement& p : placements)
        boxes.push_back(boxOf(p));
    std::vector<ClusterNode> nodes(children.size());
    for (std::size_t n = nodes.size(); n-- > 0;) {
        nodes[n].children = children[n];
        nodes[n].items = items[n];
        for (std::size_t p : items[n])
            nodes[n].box.add(boxes[p]);
        for (std::size_t c : children[n])
            nodes[n].box.add(nodes[c].box);
    }
    return shareCopies(nodes, placements, boxes, kReach, kTolerance);
}

// A root over two leaves, placements [0, split) and [split, end).
SharedCopies twoLeaves(const std::vector<flt::PartPlacement>& placements, std::size_t split)
{
    std::vector<std::size_t> first, second;
    for (std::size_t i = 0; i < placements.size(); ++i)
        (i < split ? first : second).push_back(i);
    return shared(placements, {{1, 2}, {}, {}}, {{}, first, second});
}

// The move puts every placement of leaf 1 onto one of leaf 2's, within the tolerance.
void expectMovedOnto(const ClusterCopy& copy, const std::vector<flt::PartPlacement>& placements, std::size_t split)
{
    for (std::size_t i = 0; i < split; ++i) {
        const flt::Mat4d moved = flt::multiply(copy.move, placements[i].matrix);
        double nearest = 1e30;
        for (std::size_t j = split; j < placements.size(); ++j) {
            if (placements[j].definition != placements[i].definition)
                continue;
            double apart = 0;
            for (int r = 0; r < 3; ++r)
                for (int c = 0; c < 4; ++c)
                    apart = std::max(apart, std::abs(moved[r][c] - placements[j].matrix[r][c]));
            nearest = std::min(nearest, apart);
        }
        EXPECT_LT(nearest, kTolerance) << "placement " << i;
    }
}

// Part 0 at the origin and part 1 twice beside it, along x: a row with no symmetry.
std::vector<flt::PartPlacement> row(double x, double y)
{
    return {at(0, x, y), at(1, x + 1.5, y, 0.3), at(1, x + 3, y)};
}

}  // namespace

TEST(ClusterCopies, AMovedClusterIsACopyOfTheFirst)
{
    std::vector<flt::PartPlacement> placements = row(0, 0);
    for (const flt::PartPlacement& p : row(10, 4))
        placements.push_back(p);
    const std::vector<ClusterCopy> copies = twoLeaves(placements, 3).copies;
    ASSERT_EQ(copies.size(), 3u);
    EXPECT_EQ(copies[0].original, 0u);
    EXPECT_EQ(copies[1].original, 1u);
    EXPECT_EQ(copies[2].original, 1u);
    EXPECT_FALSE(copies[2].turned());
    EXPECT_DOUBLE_EQ(copies[2].move[0][3], 10.0);
    EXPECT_DOUBLE_EQ(copies[2].move[1][3], 4.0);
    expectMovedOnto(copies[2], placements, 3);
}

// A row and a copy of it turned by `turn` about z through (cx, cy) and moved 20 along y:
// the copy is found, turned.
static void expectTurnedCopyFound(double turn, double cx, double cy)
{
    std::vector<flt::PartPlacement> placements = row(0, 0);
    for (const flt::PartPlacement& p : row(0, 0))
        placements.push_back(turnedAbout(p, turn, cx, cy, 20));
    const std::vector<ClusterCopy> copies = twoLeaves(placements, 3).copies;
    EXPECT_EQ(copies[2].original, 1u) << turn;
    EXPECT_TRUE(copies[2].turned()) << turn;
    expectMovedOnto(copies[2], placements, 3);
}

// A rack turned half round to face the first across an aisle, its turn written "3.14159":
// its parts miss an exact half turn by less than the tolerance. A quarter turn too.
TEST(ClusterCopies, AClusterTurnedAndMovedIsACopyWithItsTurn)
{
    for (double turn : {3.14159265358979, 3.14159, 1.5707963})
        expectTurnedCopyFound(turn, 2, 0.5);
}

// A rack set askew, by a turn that maps no axis onto an axis, is a copy all the same.
TEST(ClusterCopies, AClusterTurnedByAnyAngleIsACopy)
{
    for (double turn : {0.5235987756, -1.0, 2.5})
        expectTurnedCopyFound(turn, 1, 3);
}

// A rack seen in a mirror (x -> 20 - x) has the same parts, each placed alike but mirrored:
// it is a copy, by a mirror, drawn with its faces turned back by the writer. Scaled up, the
// same rack is no copy: its proxies' error would scale too.
TEST(ClusterCopies, AMirroredClusterIsAMirroredCopyAndAScaledOneIsNone)
{
    std::vector<flt::PartPlacement> mirrored = row(0, 0), scaled = row(0, 0);
    for (flt::PartPlacement p : row(0, 0)) {
        flt::PartPlacement q = p;
        for (int c = 0; c < 4; ++c)
            p.matrix[0][c] = -p.matrix[0][c];
        p.matrix[0][3] += 20;
        mirrored.push_back(p);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 4; ++c)
                q.matrix[r][c] *= 2;
        q.matrix[0][3] += 20;
        scaled.push_back(q);
    }
    const std::vector<ClusterCopy> copies = twoLeaves(mirrored, 3).copies;
    ASSERT_EQ(copies[2].original, 1u);
    EXPECT_TRUE(copies[2].mirrored());
    EXPECT_LT(flt::determinant3(copies[2].move), 0);
    expectMovedOnto(copies[2], mirrored, 3);
    EXPECT_FALSE(copies[1].mirrored());
    EXPECT_EQ(twoLeaves(scaled, 3).copies[2].original, 2u);
}

// The same parts in the same box, but the lone part in the middle: no turn or move makes
// one the other.
TEST(ClusterCopies, AClusterOfTheSamePartsPlacedOtherwiseIsNoCopy)
{
    std::vector<flt::PartPlacement> placements = row(0, 0);
    placements.push_back(at(1, 10, 0, 0.3));
    placements.push_back(at(0, 11.5, 0));
    placements.push_back(at(1, 13, 0));
    const std::vector<ClusterCopy> copies = twoLeaves(placements, 3).copies;
    EXPECT_EQ(copies[2].original, 2u);
}

// The tree cut the turned copy otherwise (its lone part first); it is cut again as its
// original is, and its leaves are copies of the original's leaves.
TEST(ClusterCopies, ACopyIsCutAsItsOriginal)
{
    std::vector<flt::PartPlacement> placements = row(0, 0);
    for (const flt::PartPlacement& p : row(0, 0))
        placements.push_back(turnedAbout(p, 3.14159265358979, 1.5, 0, 20));
    const SharedCopies s =
        shared(placements, {{1, 2}, {3, 4}, {5, 6}, {}, {}, {}, {}}, {{}, {}, {}, {0, 1}, {2}, {3}, {4, 5}});
    ASSERT_EQ(s.nodes.size(), 7u);
    EXPECT_EQ(s.nodes[1].children, (std::vector<std::size_t>{2, 3}));
    EXPECT_EQ(s.nodes[4].children, (std::vector<std::size_t>{5, 6}));
    EXPECT_EQ(s.copies[4].original, 1u);
    EXPECT_EQ(s.copies[5].original, 2u);
    EXPECT_EQ(s.copies[6].original, 3u);
    ASSERT_EQ(s.nodes[5].items.size(), 2u);
    ASSERT_EQ(s.nodes[6].items.size(), 1u);
    // The turned row's part 0 stands alone, as the first row's lone part 1 does not: the
    // leaves hold the same parts as their originals.
    for (std::size_t leaf : {5u, 6u})
        for (std::size_t k = 0; k < s.nodes[leaf].items.size(); ++k)
            EXPECT_EQ(placements[s.nodes[leaf].items[k]].definition,
                      placements[s.nodes[s.copies[leaf].original].items[k]].definition);
    std::vector<flt::PartPlacement> leafPlacements;
    for (std::size_t p : s.nodes[2].items)
        leafPlacements.push_back(placements[p]);
    for (std::size_t p : s.nodes[5].items)
        leafPlacements.push_back(placements[p]);
    expectMovedOnto(s.copies[5], leafPlacements, 2);
    for (std::size_t n = 0; n < s.nodes.size(); ++n)
        for (std::size_t p : s.nodes[n].items)
            for (int a = 0; a < 3; ++a) {
                EXPECT_LE(s.nodes[n].box.lo[a], boxOf(placements[p]).lo[a]);
                EXPECT_GE(s.nodes[n].box.hi[a], boxOf(placements[p]).hi[a]);
            }
}

// A part turned in place by a hundredth of a radian moves its corners by far more than
// the tolerance, though its box hardly changes.
TEST(ClusterCopies, APartTurnedInPlaceMakesNoCopy)
{
    std::vector<flt::PartPlacement> placements = row(0, 0);
    for (const flt::PartPlacement& p : row(10, 0))
        placements.push_back(p);
    placements[5] = at(1, 13, 0, 0.01);
    const std::vector<ClusterCopy> copies = twoLeaves(placements, 3).copies;
    EXPECT_EQ(copies[2].original, 2u);
}

}  // namespace cadlod::test
