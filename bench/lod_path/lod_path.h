// Which levels of an OpenSceneGraph LOD model a camera draws along a path, and how many
// triangles (the paper's Table 1 redone over every level, issue 13 item 5). The level is
// picked by OSG's own osg::LOD traversal from the eye position, as the viewer's cull does
// with an LOD scale of 1; view-frustum culling is not applied, so a frame counts every
// triangle the LOD nodes select, in view or not.
#pragma once

#include <osg/Node>
#include <osg/Vec3d>

#include <cstddef>
#include <map>
#include <vector>

namespace osg {
class Drawable;
class LOD;
}  // namespace osg

namespace cadlod::lodpath {

// One child of one osg::LOD. The OpenFlight reader turns every LOD record into an
// osg::LOD with one child, so a level is the set of children sharing a range.
struct LodChildRef {
    osg::LOD* lod = nullptr;
    unsigned child = 0;
};

struct Level {
    float nearRange = 0;  // drawn for nearRange <= distance < farRange
    float farRange = 0;
    std::vector<LodChildRef> children;
    std::size_t triangles = 0;
};

// Triangles of every drawable below `node`, all LOD children included; degenerate ones
// (stitched triangle strips) are not counted.
std::size_t trianglesBelow(osg::Node& node);

// The LOD levels of `root`, sorted from the finest (nearest range) to the coarsest.
std::vector<Level> findLevels(osg::Node& root);

// What one frame draws: all its triangles, and those of each level (perLevel[k]).
struct Drawn {
    std::size_t triangles = 0;
    std::vector<std::size_t> perLevel;
};

// How often each level was drawn along a path.
struct LevelOnPath {
    int frames = 0;
    int firstFrame = -1;
    int lastFrame = -1;
};

struct PathTally {
    std::vector<std::size_t> trianglesPerFrame;
    std::vector<LevelOnPath> levels;  // one per level of the model
    int framesDrawingNothing = 0;
    double meanTriangles() const;
};

class LodPathCounter
{
public:
    explicit LodPathCounter(osg::Node& root);

    const std::vector<Level>& levels() const { return levels_; }
    Drawn drawnFrom(const osg::Vec3d& eye);
    PathTally walk(const std::vector<osg::Vec3d>& eyes);

private:
    class DrawnFromEye;  // the visitor, a friend of the caches below
    std::size_t trianglesOf(osg::Drawable& drawable);

    osg::ref_ptr<osg::Node> root_;
    std::vector<Level> levels_;
    std::map<const osg::Node*, int> levelOfChild_;
    std::map<const osg::Drawable*, std::size_t> trianglesOfDrawable_;
};

// `count` distances from `from` to `to`, evenly spaced on a log scale (both ends included).
std::vector<double> logSpaced(double from, double to, int count);

struct PathEnds {
    double nearDistance = 0;
    double farDistance = 0;
};

// A camera path backing away from the model that sweeps every level: it starts where the
// bounding sphere fills the view height, or at half the first switch distance when the
// finest level is only drawn closer than that, and ends 1.25 times beyond the last switch
// between levels. Without LOD levels it ends where the model is 16 pixels tall in a
// `viewportPixels` high view.
PathEnds pathOverEveryLevel(const std::vector<Level>& levels, double radius, double fovYDegrees,
                            double viewportPixels);

}  // namespace cadlod::lodpath
