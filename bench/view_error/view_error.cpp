// view_error FILE.flt...: the error on screen of an OpenFlight LOD model wherever the viewer
// stands (design.md §8), as OpenSceneGraph reads and draws it. On three paths, inside (a
// 4x4x2 grid of points in the bounding box), walk (50 points along the longest horizontal
// side, 5 % of the diagonal outside it) and approach (1x to 1000x the diagonal, log-spaced),
// every LOD node picks its children by the distance from the eye to its centre in its own
// frame, as OSG's cull does. A drawn level switched in at s shows its error as s / n pixels,
// n being the distance from the eye to the nearest vertex of that level's own geometry (by
// the chain's contract the error is 1 px at s). Prints per path the worst and mean worst
// error, the triangles drawn as a share of level 0 and the drawables.
#include <osg/ComputeBoundsVisitor>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/NodeVisitor>
#include <osg/TriangleIndexFunctor>
#include <osgDB/ReadFile>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace {

struct Count {
    std::size_t triangles = 0;
    void operator()(unsigned a, unsigned b, unsigned c) { triangles += (a != b && b != c && a != c); }
};

struct Frame {
    double worstPx = 0;
    std::size_t triangles = 0;
    std::size_t drawables = 0;
};

// Draws the model from one eye point: which LOD children, what they show.
class Drawer : public osg::NodeVisitor {
public:
    explicit Drawer(const osg::Vec3d& eye, bool finestOnly = false)
        : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), eye_(eye), finestOnly_(finestOnly)
    {
        matrices_.push_back(osg::Matrixd::identity());
        switchedIn_.push_back(0);
    }

    void apply(osg::Transform& t) override
    {
        osg::Matrixd local;
        t.computeLocalToWorldMatrix(local, this);
        matrices_.push_back(local * matrices_.back());
        traverse(t);
        matrices_.pop_back();
    }

    void apply(osg::LOD& lod) override
    {
        const osg::Matrixd& m = matrices_.back();
        const osg::Vec3d localEye = eye_ * osg::Matrixd::inverse(m);
        const double d = (localEye - osg::Vec3d(lod.getCenter())).length();
        const double scale = std::max({osg::Vec3d(m(0, 0), m(0, 1), m(0, 2)).length(),
                                       osg::Vec3d(m(1, 0), m(1, 1), m(1, 2)).length(),
                                       osg::Vec3d(m(2, 0), m(2, 1), m(2, 2)).length()});
        for (unsigned i = 0; i < lod.getNumChildren() && i < lod.getNumRanges(); ++i) {
            const bool drawn = finestOnly_ ? lod.getMinRange(i) <= 0 && lod.getMaxRange(i) > 0
                                           : lod.getMinRange(i) <= d && d < lod.getMaxRange(i);
            if (!drawn)
                continue;
            switchedIn_.push_back(lod.getMinRange(i) * scale);
            lod.getChild(i)->accept(*this);
            switchedIn_.pop_back();
        }
    }

    void apply(osg::Geode& geode) override
    {
        for (unsigned i = 0; i < geode.getNumDrawables(); ++i)
            if (const osg::Geometry* g = geode.getDrawable(i)->asGeometry())
                draw(*g);
    }

    const Frame& frame() const { return frame_; }

private:
    void draw(const osg::Geometry& g)
    {
        const auto* v = dynamic_cast<const osg::Vec3Array*>(g.getVertexArray());
        if (!v || v->empty())
            return;
        osg::TriangleIndexFunctor<Count> count;
        g.accept(count);
        frame_.triangles += count.triangles;
        ++frame_.drawables;
        const double s = switchedIn_.back();
        if (s <= 0)
            return;
        const osg::Matrixd& m = matrices_.back();
        double nearest = std::numeric_limits<double>::max();
        for (const osg::Vec3& p : *v)
            nearest = std::min(nearest, (osg::Vec3d(p) * m - eye_).length());
        frame_.worstPx = std::max(frame_.worstPx, nearest > 0 ? s / nearest : 1e9);
    }

    osg::Vec3d eye_;
    bool finestOnly_;
    std::vector<osg::Matrixd> matrices_;
    std::vector<double> switchedIn_;
    Frame frame_;
};

struct Path {
    const char* name;
    std::vector<osg::Vec3d> eyes;
};

std::vector<Path> paths(const osg::BoundingBox& box)
{
    const osg::Vec3d lo(box.xMin(), box.yMin(), box.zMin()), hi(box.xMax(), box.yMax(), box.zMax());
    const osg::Vec3d size = hi - lo, centre = (lo + hi) * 0.5;
    const double diagonal = size.length();
    Path inside{"inside", {}}, walk{"walk", {}}, approach{"approach", {}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 2; ++k)
                inside.eyes.push_back(lo + osg::Vec3d(size.x() * (i + 0.5) / 4, size.y() * (j + 0.5) / 4,
                                                      size.z() * (k + 0.5) / 2));
    const bool alongX = size.x() >= size.y();
    for (int i = 0; i < 50; ++i) {
        const double t = (i + 0.5) / 50;
        walk.eyes.push_back(alongX ? osg::Vec3d(lo.x() + t * size.x(), lo.y() - 0.05 * diagonal, centre.z())
                                   : osg::Vec3d(lo.x() - 0.05 * diagonal, lo.y() + t * size.y(), centre.z()));
    }
    osg::Vec3d direction(-0.3, -1, 0.4);
    direction.normalize();
    for (int i = 0; i < 30; ++i)
        approach.eyes.push_back(centre + direction * (diagonal * std::pow(1000.0, i / 29.0)));
    return {inside, walk, approach};
}

int measure(const std::string& file)
{
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setObjectCacheHint(osgDB::Options::CACHE_NONE);
    osg::ref_ptr<osg::Node> root = osgDB::readRefNodeFile(file, options.get());
    if (!root) {
        std::fprintf(stderr, "view_error: OpenSceneGraph could not read %s\n", file.c_str());
        return 1;
    }
    Drawer finest(osg::Vec3d(), true);
    root->accept(finest);
    const double levelZero = double(std::max<std::size_t>(1, finest.frame().triangles));
    osg::ComputeBoundsVisitor bounds;
    root->accept(bounds);
    for (const Path& path : paths(bounds.getBoundingBox())) {
        double worst = 0, meanWorst = 0, share = 0, drawables = 0;
        for (const osg::Vec3d& eye : path.eyes) {
            Drawer drawer(eye);
            root->accept(drawer);
            const Frame& f = drawer.frame();
            worst = std::max(worst, f.worstPx);
            meanWorst += f.worstPx;
            share += double(f.triangles) / levelZero;
            drawables += double(f.drawables);
        }
        const double n = double(path.eyes.size());
        std::printf("%s %s worst_px %.2f mean_worst_px %.2f triangles_share %.4f drawables_mean %.0f\n",
                    file.c_str(), path.name, worst, meanWorst / n, share / n, drawables / n);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s FILE.flt...\n", argv[0]);
        return 2;
    }
    int rc = 0;
    for (int i = 1; i < argc; ++i)
        rc |= measure(argv[i]);
    return rc;
}
