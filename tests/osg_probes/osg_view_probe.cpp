#include "osg_view_probe.h"

#include "osg_placed.h"

#include <osg/ComputeBoundsVisitor>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/NodeVisitor>
#include <osgDB/ReadFile>

#include "measure/triangle_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace cadlod::test {
namespace {

std::size_t trianglesOf(const osg::Geometry& g)
{
    std::size_t n = 0;
    forEachTriangle(g, [&](const osg::Vec3&, const osg::Vec3&, const osg::Vec3&) { ++n; });
    return n;
}

// Appends the triangles of `g`, placed by `m`, to `out`.
void appendTriangles(const osg::Geometry& g, const osg::Matrixd& m, std::vector<std::array<osg::Vec3d, 3>>& out)
{
    forEachTriangle(g, [&](const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c) {
        out.push_back({osg::Vec3d(a) * m, osg::Vec3d(b) * m, osg::Vec3d(c) * m});
    });
}

// The names that frame placements: the model's (the header's ID holds 7 characters of it),
// clusters ("cluster 1.2": a space no VRML name holds) and the LOD nodes OSG makes.
bool isFrame(const std::string& name, const std::string& model)
{
    return name == model || (name.size() == 7 && model.compare(0, 7, name) == 0) || name.rfind("cluster ", 0) == 0 ||
           name == "newLOD" || name.rfind("LOD child", 0) == 0;
}

// The placements below a node: the outermost names that are not frames.
class PlacementNames : public osg::NodeVisitor {
public:
    PlacementNames(const std::string& model, std::set<std::string>& out)
        : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), model_(model), out_(out)
    {
    }
    void apply(osg::Node& node) override
    {
        if (!node.getName().empty() && !isFrame(node.getName(), model_)) {
            out_.insert(node.getName());
            return;
        }
        traverse(node);
    }
    void apply(osg::LOD& lod) override  // not into the proxies of the clusters below
    {
        for (unsigned i = 0; i < lod.getNumChildren() && i < lod.getNumRanges(); ++i)
            if (lod.getMinRange(i) <= 0)
                lod.getChild(i)->accept(*this);
    }

private:
    const std::string& model_;
    std::set<std::string>& out_;
};

class Drawer : public PlacedVisitor {
public:
    Drawer(const osg::Vec3d& eye, const std::string& model) : eye_(eye), model_(model) { switchedIn_.push_back(0); }

    void apply(osg::Node& node) override
    {
        const bool placement = enter(node);
        traverse(node);
        if (placement)
            placement_.pop_back();
    }

    void apply(osg::Transform& t) override
    {
        const bool placement = enter(t);
        PlacedVisitor::apply(t);
        if (placement)
            placement_.pop_back();
    }

    void apply(osg::LOD& lod) override
    {
        const osg::Matrixd& m = placed();
        const double d = (eye_ * osg::Matrixd::inverse(m) - osg::Vec3d(lod.getCenter())).length();
        const double scale = std::max({osg::Vec3d(m(0, 0), m(0, 1), m(0, 2)).length(),
                                       osg::Vec3d(m(1, 0), m(1, 1), m(1, 2)).length(),
                                       osg::Vec3d(m(2, 0), m(2, 1), m(2, 2)).length()});
        for (unsigned i = 0; i < lod.getNumChildren() && i < lod.getNumRanges(); ++i) {
            if (!(lod.getMinRange(i) <= d && d < lod.getMaxRange(i)))
                continue;
            const bool proxy = placement_.empty() && proxyDepth_ == 0 && lod.getMinRange(i) > 0;
            if (proxy)
                standFor(lod, i);  // a cluster's proxy: what its near child holds
            proxyDepth_ += proxy;
            switchedIn_.push_back(lod.getMinRange(i) * scale);
            levelNames_.push_back(&lod.getName());
            lod.getChild(i)->accept(*this);
            levelNames_.pop_back();
            switchedIn_.pop_back();
            proxyDepth_ -= proxy;
        }
    }

    void apply(osg::Geode& geode) override
    {
        for (unsigned i = 0; i < geode.getNumDrawables(); ++i)
            if (const osg::Geometry* g = geode.getDrawable(i)->asGeometry())
                draw(*g);
    }

    OsgView view;

    // Every triangle drawn goes to `drawn` too, placed.
    void collectInto(std::vector<std::array<osg::Vec3d, 3>>& drawn) { drawn_ = &drawn; }

private:
    bool enter(osg::Node& node)
    {
        if (!placement_.empty() || proxyDepth_ > 0 || node.getName().empty() || isFrame(node.getName(), model_))
            return false;
        placement_.push_back(node.getName());
        ++view.drawnPlacements[node.getName()];
        return true;
    }

    // The near child of the proxy's cluster: in the same osg::LOD, or in a sibling one with
    // the same centre.
    void standFor(osg::LOD& lod, unsigned proxy)
    {
        std::vector<osg::LOD*> node{&lod};
        if (lod.getNumParents() > 0)
            for (unsigned c = 0; c < lod.getParent(0)->getNumChildren(); ++c)
                if (auto* sibling = dynamic_cast<osg::LOD*>(lod.getParent(0)->getChild(c)))
                    if (sibling != &lod && sibling->getCenter() == lod.getCenter())
                        node.push_back(sibling);
        for (osg::LOD* l : node)
            for (unsigned i = 0; i < l->getNumChildren() && i < l->getNumRanges(); ++i)
                if (!(l == &lod && i == proxy) && l->getMinRange(i) <= 0) {
                    std::set<std::string> names;
                    PlacementNames collect(model_, names);
                    l->getChild(i)->accept(collect);
                    for (const std::string& n : names)
                        ++view.drawnPlacements[n];
                }
    }

    void draw(const osg::Geometry& g)
    {
        const auto* v = dynamic_cast<const osg::Vec3Array*>(g.getVertexArray());
        if (!v || v->empty())
            return;
        if (drawn_)
            appendTriangles(g, placed(), *drawn_);
        const std::size_t triangles = trianglesOf(g);
        view.triangles += triangles;
        view.trianglesByLevel[levelNames_.empty() ? std::string() : *levelNames_.back()] += triangles;
        ++view.drawables;
        view.proxyDrawables += proxyDepth_ > 0 ? 1 : 0;
        const double s = switchedIn_.back();
        if (s <= 0)
            return;
        double nearest = std::numeric_limits<double>::max();
        for (const osg::Vec3& p : *v)
            nearest = std::min(nearest, (osg::Vec3d(p) * placed() - eye_).length());
        view.worstApparentPx = std::max(view.worstApparentPx, nearest > 0 ? s / nearest : 1e9);
    }

    osg::Vec3d eye_;
    const std::string& model_;
    std::vector<double> switchedIn_;
    std::vector<std::string> placement_;
    std::vector<const std::string*> levelNames_;  // of the LOD nodes being drawn
    int proxyDepth_ = 0;
    std::vector<std::array<osg::Vec3d, 3>>* drawn_ = nullptr;
};

// OSG makes one osg::LOD of each LOD record, or one of several: the LOD children of a
// group that share a centre are one node.
class LodCollector : public osg::NodeVisitor {
public:
    LodCollector() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::Group& group) override
    {
        if (seen_.insert(&group).second) {
            std::map<std::array<double, 3>, OsgLodRanges> byCentre;
            for (unsigned c = 0; c < group.getNumChildren(); ++c)
                if (const auto* lod = dynamic_cast<const osg::LOD*>(group.getChild(c))) {
                    const osg::Vec3d centre(lod->getCenter());
                    OsgLodRanges& r = byCentre[{centre.x(), centre.y(), centre.z()}];
                    for (unsigned i = 0; i < lod->getNumRanges(); ++i)
                        r.ranges.emplace_back(lod->getMinRange(i), lod->getMaxRange(i));
                }
            for (auto& entry : byCentre)
                nodes.push_back(entry.second);
        }
        traverse(group);
    }
    std::vector<OsgLodRanges> nodes;

private:
    std::set<const osg::Group*> seen_;
};

// The finest geometry, each with its placement, to `visit`: every LOD node at its child drawn
// from up close.
template <class Visit>
class FinestGeometry : public PlacedVisitor {
public:
    explicit FinestGeometry(Visit visit) : visit_(std::move(visit)) {}
    using PlacedVisitor::apply;
    void apply(osg::LOD& lod) override
    {
        for (unsigned i = 0; i < lod.getNumChildren() && i < lod.getNumRanges(); ++i)
            if (lod.getMinRange(i) <= 0 && lod.getMaxRange(i) > 0)
                lod.getChild(i)->accept(*this);
    }
    void apply(osg::Geode& geode) override
    {
        for (unsigned i = 0; i < geode.getNumDrawables(); ++i)
            if (const osg::Geometry* g = geode.getDrawable(i)->asGeometry())
                visit_(*g, placed());
    }

private:
    Visit visit_;
};

template <class Visit>
void visitFinest(osg::Node& root, Visit visit)
{
    FinestGeometry<Visit> finest(std::move(visit));
    root.accept(finest);
}

// The gaps of `query` with `drawn` seen from `eye`.
OsgGaps gapsOf(const std::vector<std::array<osg::Vec3d, 3>>& drawn, const osg::Vec3d& eye, const OsgGapQuery& query)
{
    // Single-precision corners about the eye: the distances that matter are those near it.
    std::vector<vcg::Point3f> vertices;
    std::vector<TriangleTree::Corners> corners;
    for (const auto& t : drawn) {
        const auto first = std::uint32_t(vertices.size());
        for (const osg::Vec3d& p : t)
            vertices.emplace_back(float(p.x() - eye.x()), float(p.y() - eye.y()), float(p.z() - eye.z()));
        corners.push_back({first, first + 1, first + 2});
    }
    const TriangleTree tree(std::move(vertices), std::move(corners));
    OsgGaps gaps;
    for (const Point3& s : *query.samples) {
        const vcg::Point3d p(s[0] - eye.x(), s[1] - eye.y(), s[2] - eye.z());
        double gap = std::numeric_limits<double>::infinity();
        if (!tree.empty())
            tree.closest(p, std::numeric_limits<double>::infinity(), gap);
        const double px = gap / (p.Norm() * query.pixelRadians);
        gaps.widestPx = std::max(gaps.widestPx, px);
        gaps.wider += px > query.widerThanPx ? 1 : 0;
    }
    return gaps;
}

}  // namespace

struct OsgViewProbe::Impl {
    osg::ref_ptr<osg::Node> root;
    std::string model;
};

namespace {
// The model's name as cadlod writes it: the header's ID is its first 7 characters, and the
// group below the header bears it whole.
std::string modelNameOf(const osg::Node& root)
{
    const std::string header = root.getName();
    const osg::Group* group = root.asGroup();
    for (unsigned i = 0; group && i < group->getNumChildren(); ++i) {
        const std::string& name = group->getChild(i)->getName();
        if (!header.empty() && name.compare(0, header.size(), header) == 0)
            return name;
    }
    return header;
}
}  // namespace

OsgViewProbe::OsgViewProbe(const std::string& path, const std::string& modelName) : impl_(new Impl)
{
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setObjectCacheHint(osgDB::Options::CACHE_NONE);
    impl_->root = osgDB::readRefNodeFile(path, options.get());
    impl_->model = modelName.empty() && impl_->root ? modelNameOf(*impl_->root) : modelName;
}

OsgViewProbe::~OsgViewProbe() { delete impl_; }

bool OsgViewProbe::loaded() const { return impl_->root.valid(); }

OsgView OsgViewProbe::drawFrom(const Point3& eye, const OsgGapQuery* gaps) const
{
    const osg::Vec3d e(eye[0], eye[1], eye[2]);
    Drawer drawer(e, impl_->model);
    std::vector<std::array<osg::Vec3d, 3>> drawn;
    if (gaps)
        drawer.collectInto(drawn);
    impl_->root->accept(drawer);
    if (gaps)
        drawer.view.gaps = gapsOf(drawn, e, *gaps);
    return drawer.view;
}

std::vector<OsgLodRanges> OsgViewProbe::lodNodes() const
{
    LodCollector c;
    impl_->root->accept(c);
    return c.nodes;
}

std::size_t OsgViewProbe::finestTriangles() const
{
    std::size_t n = 0;
    visitFinest(*impl_->root, [&](const osg::Geometry& g, const osg::Matrixd&) { n += trianglesOf(g); });
    return n;
}

std::vector<Point3> OsgViewProbe::finestSamples(std::size_t most) const
{
    std::vector<Point3> centroids;
    visitFinest(*impl_->root, [&](const osg::Geometry& g, const osg::Matrixd& m) {
        forEachTriangle(g, [&](const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c) {
            const osg::Vec3d p = (osg::Vec3d(a) * m + osg::Vec3d(b) * m + osg::Vec3d(c) * m) / 3.0;
            centroids.push_back({p.x(), p.y(), p.z()});
        });
    });
    const std::size_t n = centroids.size();
    const std::size_t stride = std::max<std::size_t>(1, (n + most - 1) / std::max<std::size_t>(most, 1));
    std::vector<Point3> samples;
    for (std::size_t i = 0; i < n; i += stride)
        samples.push_back(centroids[i]);
    return samples;
}

std::array<Point3, 2> OsgViewProbe::bounds() const
{
    osg::ComputeBoundsVisitor b;
    impl_->root->accept(b);
    const osg::BoundingBox& box = b.getBoundingBox();
    return {Point3{box.xMin(), box.yMin(), box.zMin()}, Point3{box.xMax(), box.yMax(), box.zMax()}};
}

}  // namespace cadlod::test
