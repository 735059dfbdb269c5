// The per-cluster estimate of design.md §8: level 0 of a reference chain split into a grid of
// clusters over the measured model's box, each cluster drawn at the share of level 0 the
// chain keeps at the distance from the eye to the cluster's box. Beside it, the same grid as
// LOD nodes: each cell switched by the distance to its centre, as OSG does, and a level shown
// only where the bound of §8 holds at the cell's nearest point (from six radii off and its
// error's distance plus a radius): what the finest hierarchy of cell-sized nodes could draw.
// And the estimate with every finest triangle held whole near it: what LOD nodes that draw
// the finest triangles whole could draw at best, where some are long.
#pragma once

#include <osg/BoundingBox>
#include <osg/Vec3d>
#include <osg/Vec3f>

#include <array>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

// The bound on the error on screen, pixels: what every path is held to.
inline constexpr double kErrorBoundPx = 1.2;

struct ReferenceLevel {
    double minRange = 0;
    double maxRange = 0;
    std::size_t triangles = 0;
};

// A one-LOD-node chain as OSG reads it: its levels by range and where level 0's triangles lie.
struct ReferenceChain {
    std::vector<ReferenceLevel> levels;  // sorted by minRange; levels[0] starts at 0
    std::vector<osg::Vec3f> finestCentroids;  // world coordinates
    std::vector<float> finestRadii;           // each one's least bounding radius: half its longest side
    std::vector<osg::Vec3f> finestSideMidpoints;  // the midpoint of each one's longest side

    // T_k / T_0 of the level whose range holds the distance, else of the level nearest by range.
    double shareAt(double distance) const;
};

// Reads REF; false with a message when OSG cannot read it or it has no level starting at 0.
bool readReferenceChain(const std::string& file, ReferenceChain& chain, std::string& error);

class ClusterGrid {
public:
    static constexpr int kCells = 16;

    ClusterGrid(const ReferenceChain& chain, const osg::BoundingBox& box);

    // The triangles the clusters draw from this eye, as a share of level 0.
    double share(const osg::Vec3d& eye) const;
    // The same, each cell an LOD node.
    double nodeShare(const osg::Vec3d& eye) const;
    // share(), but each finest triangle drawn whole wherever the eye is nearer the midpoint of its
    // longest side than kHeldRadii of its radii h (half that side). An LOD node whose levels
    // each cover the surface of its finest, centred d off that midpoint, reaches at least
    // sqrt(h^2 + d^2) from its centre: with 1.2 px at most on screen, it may not draw a coarser
    // level until the eye is 1.2 / 0.2 = 6 such reaches off its centre. Wherever the node's
    // centre, every eye within min over d of 6 sqrt(h^2 + d^2) - d = sqrt(35) h of the midpoint
    // is that near it, and so sees the triangle at its finest.
    double heldShare(const osg::Vec3d& eye) const;
    static constexpr double kSwitchReaches = kErrorBoundPx / (kErrorBoundPx - 1.0);
    static inline const double kHeldRadii = std::sqrt(kSwitchReaches * kSwitchReaches - 1);
    // Level 0's triangles, which the shares are of.
    std::size_t levelZero() const { return total_; }

private:
    int cellIndex(const osg::Vec3f& point) const;
    osg::BoundingBoxd cellBox(int cell) const;
    double distanceToCell(const osg::Vec3d& eye, int cell) const;
    // Each cell's share of its level 0 drawn from `eye` (0 for an empty cell).
    std::vector<double> cellShares(const osg::Vec3d& eye) const;
    double distanceToCentre(const osg::Vec3d& eye, int cell) const;

    const ReferenceChain& chain_;
    osg::Vec3d lo_, size_;
    double cellRadius_ = 0;
    std::array<std::size_t, kCells * kCells * kCells> triangles_{};
    std::vector<int> cellOfFinest_;
    std::size_t total_ = 0;
};
