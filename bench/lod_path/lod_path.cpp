#include "lod_path.h"

#include <osg/Drawable>
#include <osg/LOD>
#include <osg/NodeVisitor>
#include <osg/Transform>
#include <osg/TriangleFunctor>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace cadlod::lodpath {
namespace {

struct NonDegenerateCounter {
    std::size_t count = 0;
    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c)
    {
        count += a != b && b != c && a != c;
    }
};

std::size_t trianglesOfDrawable(osg::Drawable& d)
{
    osg::TriangleFunctor<NonDegenerateCounter> f;
    d.accept(f);
    return f.count;
}

class CountAll : public osg::NodeVisitor
{
public:
    CountAll() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Drawable& d) override { triangles += trianglesOfDrawable(d); }
    std::size_t triangles = 0;
};

class CollectLodChildren : public osg::NodeVisitor
{
public:
    CollectLodChildren() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::LOD& lod) override
    {
        for (unsigned i = 0; i < lod.getNumChildren() && i < lod.getNumRanges(); ++i)
            children.push_back({&lod, i});
        traverse(lod);
    }
    std::vector<LodChildRef> children;
};

// A range is "finite" when it is a switch distance, not the "never switched out" infinity
// the OpenFlight reader may give the coarsest level.
bool isFinite(float range, double radius) { return range > 0 && double(range) < 1e6 * radius; }

}  // namespace

std::size_t trianglesBelow(osg::Node& node)
{
    CountAll c;
    node.accept(c);
    return c.triangles;
}

std::vector<Level> findLevels(osg::Node& root)
{
    CollectLodChildren c;
    root.accept(c);
    std::map<std::pair<float, float>, Level> byRange;  // sorted by near range first
    for (const LodChildRef& ref : c.children) {
        const auto range = std::make_pair(ref.lod->getMinRange(ref.child), ref.lod->getMaxRange(ref.child));
        Level& level = byRange[range];
        level.nearRange = range.first;
        level.farRange = range.second;
        level.children.push_back(ref);
        level.triangles += trianglesBelow(*ref.lod->getChild(ref.child));
    }
    std::vector<Level> levels;
    for (auto& entry : byRange)
        levels.push_back(entry.second);
    return levels;
}

// Traverses only the children OSG's LOD nodes select from the eye (TRAVERSE_ACTIVE_CHILDREN
// makes osg::LOD::traverse ask getDistanceToViewPoint, which a plain visitor answers 0),
// and adds up the triangles below them per level.
class LodPathCounter::DrawnFromEye : public osg::NodeVisitor
{
public:
    DrawnFromEye(LodPathCounter& counter, const osg::Vec3d& eye)
        : osg::NodeVisitor(TRAVERSE_ACTIVE_CHILDREN), counter_(counter)
    {
        eyes_.push_back(eye);
        drawn.perLevel.assign(counter.levels_.size(), 0);
    }

    osg::Vec3 getEyePoint() const override { return eyes_.back(); }
    osg::Vec3 getViewPoint() const override { return eyes_.back(); }
    float getDistanceToEyePoint(const osg::Vec3& pos, bool) const override { return distanceTo(pos); }
    float getDistanceToViewPoint(const osg::Vec3& pos, bool) const override { return distanceTo(pos); }

    // LOD centres are in the local frame of their transform: the eye goes there too.
    void apply(osg::Transform& transform) override
    {
        osg::Matrixd worldToLocal;
        transform.computeWorldToLocalMatrix(worldToLocal, this);
        const bool relative = transform.getReferenceFrame() == osg::Transform::RELATIVE_RF;
        eyes_.push_back((relative ? eyes_.back() : eyes_.front()) * worldToLocal);
        traverse(transform);
        eyes_.pop_back();
    }

    void apply(osg::Drawable& drawable) override
    {
        const std::size_t n = counter_.trianglesOf(drawable);
        drawn.triangles += n;
        const int level = levelOnPath();
        if (level >= 0)
            drawn.perLevel[std::size_t(level)] += n;
    }

    Drawn drawn;

private:
    float distanceTo(const osg::Vec3& pos) const { return float((osg::Vec3d(pos) - eyes_.back()).length()); }

    // The level of the innermost LOD child on the path to the current drawable.
    int levelOnPath() const
    {
        const osg::NodePath& path = getNodePath();
        for (auto node = path.rbegin(); node != path.rend(); ++node) {
            const auto found = counter_.levelOfChild_.find(*node);
            if (found != counter_.levelOfChild_.end())
                return found->second;
        }
        return -1;
    }

    LodPathCounter& counter_;
    std::vector<osg::Vec3d> eyes_;
};

LodPathCounter::LodPathCounter(osg::Node& root) : root_(&root), levels_(findLevels(root))
{
    for (std::size_t k = 0; k < levels_.size(); ++k)
        for (const LodChildRef& ref : levels_[k].children)
            levelOfChild_[ref.lod->getChild(ref.child)] = int(k);
}

std::size_t LodPathCounter::trianglesOf(osg::Drawable& drawable)
{
    const auto found = trianglesOfDrawable_.find(&drawable);
    if (found != trianglesOfDrawable_.end())
        return found->second;
    return trianglesOfDrawable_[&drawable] = trianglesOfDrawable(drawable);
}

Drawn LodPathCounter::drawnFrom(const osg::Vec3d& eye)
{
    DrawnFromEye visitor(*this, eye);
    root_->accept(visitor);
    return visitor.drawn;
}

PathTally LodPathCounter::walk(const std::vector<osg::Vec3d>& eyes)
{
    PathTally tally;
    tally.levels.assign(levels_.size(), LevelOnPath{});
    for (std::size_t frame = 0; frame < eyes.size(); ++frame) {
        const Drawn drawn = drawnFrom(eyes[frame]);
        tally.trianglesPerFrame.push_back(drawn.triangles);
        tally.framesDrawingNothing += drawn.triangles == 0;
        for (std::size_t k = 0; k < levels_.size(); ++k) {
            if (drawn.perLevel[k] == 0)
                continue;
            LevelOnPath& on = tally.levels[k];
            ++on.frames;
            if (on.firstFrame < 0)
                on.firstFrame = int(frame);
            on.lastFrame = int(frame);
        }
    }
    return tally;
}

double PathTally::meanTriangles() const
{
    if (trianglesPerFrame.empty())
        return 0;
    return double(std::accumulate(trianglesPerFrame.begin(), trianglesPerFrame.end(), std::size_t(0))) /
           double(trianglesPerFrame.size());
}

std::vector<double> logSpaced(double from, double to, int count)
{
    std::vector<double> d;
    for (int i = 0; i < count; ++i) {
        const double t = count > 1 ? double(i) / (count - 1) : 0.0;
        d.push_back(from * std::pow(to / from, t));
    }
    return d;
}

PathEnds pathOverEveryLevel(const std::vector<Level>& levels, double radius, double fovYDegrees,
                            double viewportPixels)
{
    const double tanHalf = std::tan(0.5 * fovYDegrees * M_PI / 180.0);
    PathEnds ends;
    ends.nearDistance = radius / tanHalf;  // the bounding sphere fills the view height
    double firstSwitch = std::numeric_limits<double>::max(), lastSwitch = 0;
    for (const Level& level : levels)
        if (isFinite(level.nearRange, radius)) {
            firstSwitch = std::min(firstSwitch, double(level.nearRange));
            lastSwitch = std::max(lastSwitch, double(level.nearRange));
        }
    if (lastSwitch > 0) {
        ends.nearDistance = std::min(ends.nearDistance, 0.5 * firstSwitch);
        ends.farDistance = 1.25 * lastSwitch;
    } else {
        ends.farDistance = radius * viewportPixels / (16 * tanHalf);  // 16 pixels tall
    }
    if (ends.farDistance <= ends.nearDistance)
        ends.farDistance = 2 * ends.nearDistance;
    return ends;
}

}  // namespace cadlod::lodpath
