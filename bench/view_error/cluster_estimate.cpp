#include "cluster_estimate.h"

#include "osg_placed.h"

#include <osg/Geode>
#include <osg/LOD>
#include <osgDB/ReadFile>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace {

// Walks REF: every LOD child becomes a level (children sharing a range add up), and the
// children starting at 0 give their triangles' centroids.
class ChainCollector : public cadlod::test::PlacedVisitor {
public:
    explicit ChainCollector(ReferenceChain& chain) : chain_(chain) {}

    using PlacedVisitor::apply;

    void apply(osg::LOD& lod) override
    {
        if (level_)  // a nested LOD belongs to the level that holds it
            return traverse(lod);
        for (unsigned i = 0; i < lod.getNumChildren() && i < lod.getNumRanges(); ++i) {
            const auto key = std::make_pair(double(lod.getMinRange(i)), double(lod.getMaxRange(i)));
            level_ = &levels_[key];
            finest_ = key.first <= 0;
            lod.getChild(i)->accept(*this);
            level_ = nullptr;
        }
    }

    void apply(osg::Geode& geode) override
    {
        if (!level_)
            return;
        for (unsigned i = 0; i < geode.getNumDrawables(); ++i)
            if (const osg::Geometry* g = geode.getDrawable(i)->asGeometry())
                count(*g);
    }

    void finish()
    {
        for (const auto& [range, triangles] : levels_)
            chain_.levels.push_back({range.first, range.second, triangles});
    }

private:
    // Adds the triangles of `g` that have an area to the level's, and their centroids if it is
    // the finest.
    void count(const osg::Geometry& g)
    {
        const osg::Matrixd& m = placed();
        cadlod::test::forEachTriangle(g, [&](const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c) {
            ++*level_;
            if (!finest_)
                return;
            const osg::Vec3d pa = osg::Vec3d(a) * m, pb = osg::Vec3d(b) * m, pc = osg::Vec3d(c) * m;
            const osg::Vec3d centroid = (pa + pb + pc) / 3.0;
            chain_.finestCentroids.push_back(osg::Vec3f(centroid));
            const double ab = (pa - pb).length(), bc = (pb - pc).length(), ca = (pc - pa).length();
            const double longest = std::max({ab, bc, ca});
            chain_.finestRadii.push_back(float(0.5 * longest));
            const osg::Vec3d midpoint = longest == ab ? pa + pb : longest == bc ? pb + pc : pc + pa;
            chain_.finestSideMidpoints.push_back(osg::Vec3f(midpoint / 2.0));
        });
    }

    ReferenceChain& chain_;
    std::map<std::pair<double, double>, std::size_t> levels_;  // ordered by min range
    std::size_t* level_ = nullptr;
    bool finest_ = false;
};

double gapToRange(double distance, const ReferenceLevel& level)
{
    return std::max({level.minRange - distance, distance - level.maxRange, 0.0});
}

}  // namespace

double ReferenceChain::shareAt(double distance) const
{
    const ReferenceLevel* chosen = &levels.front();
    for (const ReferenceLevel& level : levels) {
        if (level.minRange <= distance && distance < level.maxRange)
            return double(level.triangles) / double(levels.front().triangles);
        if (gapToRange(distance, level) < gapToRange(distance, *chosen))
            chosen = &level;
    }
    return double(chosen->triangles) / double(levels.front().triangles);
}

bool readReferenceChain(const std::string& file, ReferenceChain& chain, std::string& error)
{
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setObjectCacheHint(osgDB::Options::CACHE_NONE);
    osg::ref_ptr<osg::Node> root = osgDB::readRefNodeFile(file, options.get());
    if (!root) {
        error = "OpenSceneGraph could not read " + file;
        return false;
    }
    ChainCollector collector(chain);
    root->accept(collector);
    collector.finish();
    if (chain.levels.empty() || chain.levels.front().minRange > 0 || chain.levels.front().triangles == 0) {
        error = file + " has no LOD child with triangles whose range starts at 0";
        return false;
    }
    return true;
}

ClusterGrid::ClusterGrid(const ReferenceChain& chain, const osg::BoundingBox& box)
    : chain_(chain), lo_(box.xMin(), box.yMin(), box.zMin())
{
    size_ = osg::Vec3d(box.xMax(), box.yMax(), box.zMax()) - lo_;
    cellRadius_ = 0.5 * size_.length() / kCells;
    for (const osg::Vec3f& c : chain.finestCentroids) {
        cellOfFinest_.push_back(cellIndex(c));
        ++triangles_[cellOfFinest_.back()];
    }
    total_ = chain.finestCentroids.size();
}

int ClusterGrid::cellIndex(const osg::Vec3f& point) const
{
    int index = 0;
    for (int axis = 2; axis >= 0; --axis) {
        const double t = size_[axis] > 0 ? (point[axis] - lo_[axis]) / size_[axis] : 0;
        index = index * kCells + std::clamp(int(std::floor(t * kCells)), 0, kCells - 1);
    }
    return index;
}

osg::BoundingBoxd ClusterGrid::cellBox(int cell) const
{
    const int along[3] = {cell % kCells, cell / kCells % kCells, cell / (kCells * kCells)};
    osg::BoundingBoxd box;
    for (int axis = 0; axis < 3; ++axis) {
        const double step = size_[axis] / kCells;
        box._min[axis] = lo_[axis] + step * along[axis];
        box._max[axis] = box._min[axis] + step;
    }
    return box;
}

double ClusterGrid::distanceToCell(const osg::Vec3d& eye, int cell) const
{
    const osg::BoundingBoxd box = cellBox(cell);
    double squared = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const double gap = std::max({box._min[axis] - eye[axis], eye[axis] - box._max[axis], 0.0});
        squared += gap * gap;
    }
    return std::sqrt(squared);
}

double ClusterGrid::distanceToCentre(const osg::Vec3d& eye, int cell) const
{
    return (cellBox(cell).center() - eye).length();
}

double ClusterGrid::nodeShare(const osg::Vec3d& eye) const
{
    if (total_ == 0)
        return 0;
    double drawn = 0;
    for (int cell = 0; cell < int(triangles_.size()); ++cell) {
        if (triangles_[cell] == 0)
            continue;
        // A level whose error is 1 px at s may be drawn from max(s + r, 6 r) off the centre.
        const double d = distanceToCentre(eye, cell);
        drawn += double(triangles_[cell]) * (d >= 6 * cellRadius_ ? chain_.shareAt(d - cellRadius_) : 1.0);
    }
    return drawn / double(total_);
}

std::vector<double> ClusterGrid::cellShares(const osg::Vec3d& eye) const
{
    std::vector<double> shares(triangles_.size(), 0.0);
    for (int cell = 0; cell < int(triangles_.size()); ++cell)
        if (triangles_[cell] > 0)
            shares[cell] = chain_.shareAt(distanceToCell(eye, cell));
    return shares;
}

double ClusterGrid::share(const osg::Vec3d& eye) const
{
    if (total_ == 0)
        return 0;
    const std::vector<double> shares = cellShares(eye);
    double drawn = 0;
    for (int cell = 0; cell < int(triangles_.size()); ++cell)
        drawn += double(triangles_[cell]) * shares[cell];
    return drawn / double(total_);
}

double ClusterGrid::heldShare(const osg::Vec3d& eye) const
{
    if (total_ == 0)
        return 0;
    const std::vector<double> shares = cellShares(eye);
    double drawn = 0;
    for (std::size_t t = 0; t < total_; ++t) {
        const double fromSide = (osg::Vec3d(chain_.finestSideMidpoints[t]) - eye).length();
        const bool held = fromSide < kHeldRadii * chain_.finestRadii[t];
        drawn += held ? 1.0 : shares[cellOfFinest_[t]];
    }
    return drawn / double(total_);
}
