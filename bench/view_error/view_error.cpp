// view_error FILE.flt...: the error on screen of an OpenFlight LOD model wherever the viewer
// stands (design.md §8), as OpenSceneGraph reads and draws it. On three paths, inside (a
// 4x4x2 grid of points in the bounding box), walk (50 points along the longest horizontal
// side, 5 % of the diagonal outside it) and approach (1x to 1000x the diagonal, log-spaced),
// every LOD node picks its children by the distance from the eye to its centre in its own
// frame, as OSG's cull does. A drawn level switched in at s shows its error as s / n pixels,
// n being the distance from the eye to the nearest vertex of that level's own geometry (by
// the chain's contract the error is 1 px at s). Prints per path the worst and mean worst
// error, the triangles drawn as a share of level 0 and the drawables; with --estimate REF, also
// the share the per-cluster estimate of REF's chain draws (cluster_estimate.h) and the ratio of
// the two; with --walk-csv, every walk point's figures.
#include <osg/ComputeBoundsVisitor>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/NodeVisitor>
#include <osg/TriangleIndexFunctor>
#include <osgDB/ReadFile>

#include <CLI/CLI.hpp>

#include "cluster_estimate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
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

// Where the walk's rows go: one per eye point and measured file.
class WalkCsv {
public:
    bool open(const std::string& path)
    {
        file_ = std::fopen(path.c_str(), "w");
        if (file_)
            std::fputs("file,index,x,y,z,triangles_share,worst_px,drawables,estimate_share\n", file_);
        return file_ != nullptr;
    }
    ~WalkCsv()
    {
        if (file_)
            std::fclose(file_);
    }
    bool isOpen() const { return file_ != nullptr; }

    void row(const std::string& model, std::size_t index, const osg::Vec3d& eye, double share,
             const Frame& frame, const double* estimate)
    {
        std::fprintf(file_, "%s,%zu,%.9g,%.9g,%.9g,%.6f,%.4f,%zu,", quoted(model).c_str(), index, eye.x(),
                     eye.y(), eye.z(), share, frame.worstPx, frame.drawables);
        if (estimate)
            std::fprintf(file_, "%.6f", *estimate);
        std::fputc('\n', file_);
    }

private:
    static std::string quoted(const std::string& field)
    {
        if (field.find_first_of(",\"\n") == std::string::npos)
            return field;
        std::string out = "\"";
        for (char c : field)
            out += c == '"' ? std::string("\"\"") : std::string(1, c);
        return out + "\"";
    }

    std::FILE* file_ = nullptr;
};

struct PathTotals {
    double worst = 0, meanWorst = 0, share = 0, drawables = 0, estimate = 0;
};

struct Model {
    std::string file;
    osg::ref_ptr<osg::Node> root;
    double levelZero = 1;
    std::unique_ptr<ClusterGrid> clusters;  // only with --estimate
};

PathTotals measurePath(const Model& model, const Path& path, WalkCsv* walkCsv)
{
    PathTotals totals;
    for (std::size_t i = 0; i < path.eyes.size(); ++i) {
        const osg::Vec3d& eye = path.eyes[i];
        Drawer drawer(eye);
        model.root->accept(drawer);
        const Frame& f = drawer.frame();
        const double share = double(f.triangles) / model.levelZero;
        const double estimate = model.clusters ? model.clusters->share(eye) : 0;
        totals.worst = std::max(totals.worst, f.worstPx);
        totals.meanWorst += f.worstPx;
        totals.share += share;
        totals.drawables += double(f.drawables);
        totals.estimate += estimate;
        if (walkCsv)
            walkCsv->row(model.file, i, eye, share, f, model.clusters ? &estimate : nullptr);
    }
    return totals;
}

void printPath(const Model& model, const Path& path, const PathTotals& totals)
{
    const double n = double(path.eyes.size());
    std::printf("%s %s worst_px %.2f mean_worst_px %.2f triangles_share %.4f drawables_mean %.0f",
                model.file.c_str(), path.name, totals.worst, totals.meanWorst / n, totals.share / n,
                totals.drawables / n);
    if (model.clusters)
        std::printf(" estimate_share %.4f ratio_to_estimate %.4f", totals.estimate / n,
                    totals.estimate > 0 ? totals.share / totals.estimate : 0.0);
    std::printf("\n");
}

int measure(const std::string& file, const ReferenceChain* reference, WalkCsv& walkCsv)
{
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setObjectCacheHint(osgDB::Options::CACHE_NONE);
    Model model;
    model.file = file;
    model.root = osgDB::readRefNodeFile(file, options.get());
    if (!model.root) {
        std::fprintf(stderr, "view_error: OpenSceneGraph could not read %s\n", file.c_str());
        return 1;
    }
    Drawer finest(osg::Vec3d(), true);
    model.root->accept(finest);
    model.levelZero = double(std::max<std::size_t>(1, finest.frame().triangles));
    osg::ComputeBoundsVisitor bounds;
    model.root->accept(bounds);
    if (reference)
        model.clusters = std::make_unique<ClusterGrid>(*reference, bounds.getBoundingBox());
    for (const Path& path : paths(bounds.getBoundingBox())) {
        const bool isWalk = std::string(path.name) == "walk";
        printPath(model, path, measurePath(model, path, isWalk && walkCsv.isOpen() ? &walkCsv : nullptr));
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    CLI::App app{"The error on screen of OpenFlight LOD models wherever the viewer stands"};
    std::vector<std::string> files;
    std::string estimateFile, walkCsvFile;
    app.add_option("files", files, "OpenFlight files to measure")->required();
    app.add_option("--estimate", estimateFile,
                   "a one-LOD-node chain of the same model: compare with its per-cluster estimate");
    app.add_option("--walk-csv", walkCsvFile, "write one row per walk eye point and file");
    CLI11_PARSE(app, argc, argv);

    ReferenceChain reference;
    std::string error;
    if (!estimateFile.empty() && !readReferenceChain(estimateFile, reference, error)) {
        std::fprintf(stderr, "view_error: %s\n", error.c_str());
        return 1;
    }
    WalkCsv walkCsv;
    if (!walkCsvFile.empty() && !walkCsv.open(walkCsvFile)) {
        std::fprintf(stderr, "view_error: cannot write %s\n", walkCsvFile.c_str());
        return 1;
    }
    int rc = 0;
    for (const std::string& file : files)
        rc |= measure(file, estimateFile.empty() ? nullptr : &reference, walkCsv);
    return rc;
}
