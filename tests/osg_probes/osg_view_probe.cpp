#include "osg_view_probe.h"

#include <osg/ComputeBoundsVisitor>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/NodeVisitor>
#include <osg/TriangleIndexFunctor>
#include <osgDB/ReadFile>

#include <algorithm>
#include <limits>
#include <set>

namespace cadlod::test {
namespace {

struct Count {
    std::size_t triangles = 0;
    void operator()(unsigned a, unsigned b, unsigned c) { triangles += (a != b && b != c && a != c); }
};

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

class Drawer : public osg::NodeVisitor {
public:
    Drawer(const osg::Vec3d& eye, const std::string& model)
        : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), eye_(eye), model_(model)
    {
        matrices_.push_back(osg::Matrixd::identity());
        switchedIn_.push_back(0);
    }

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
        osg::Matrixd local;
        t.computeLocalToWorldMatrix(local, this);
        matrices_.push_back(local * matrices_.back());
        traverse(t);
        matrices_.pop_back();
        if (placement)
            placement_.pop_back();
    }

    void apply(osg::LOD& lod) override
    {
        const osg::Matrixd& m = matrices_.back();
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
            lod.getChild(i)->accept(*this);
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
        osg::TriangleIndexFunctor<Count> count;
        g.accept(count);
        view.triangles += count.triangles;
        ++view.drawables;
        view.proxyDrawables += proxyDepth_ > 0 ? 1 : 0;
        const double s = switchedIn_.back();
        if (s <= 0)
            return;
        double nearest = std::numeric_limits<double>::max();
        for (const osg::Vec3& p : *v)
            nearest = std::min(nearest, (osg::Vec3d(p) * matrices_.back() - eye_).length());
        view.worstApparentPx = std::max(view.worstApparentPx, nearest > 0 ? s / nearest : 1e9);
    }

    osg::Vec3d eye_;
    const std::string& model_;
    std::vector<osg::Matrixd> matrices_;
    std::vector<double> switchedIn_;
    std::vector<std::string> placement_;
    int proxyDepth_ = 0;
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

class FinestCounter : public osg::NodeVisitor {
public:
    FinestCounter() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::LOD& lod) override
    {
        for (unsigned i = 0; i < lod.getNumChildren() && i < lod.getNumRanges(); ++i)
            if (lod.getMinRange(i) <= 0 && lod.getMaxRange(i) > 0)
                lod.getChild(i)->accept(*this);
    }
    void apply(osg::Geode& geode) override
    {
        for (unsigned i = 0; i < geode.getNumDrawables(); ++i)
            if (const osg::Geometry* g = geode.getDrawable(i)->asGeometry()) {
                osg::TriangleIndexFunctor<Count> count;
                g->accept(count);
                triangles += count.triangles;
            }
    }
    std::size_t triangles = 0;
};

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

OsgView OsgViewProbe::drawFrom(const Point3& eye) const
{
    Drawer drawer(osg::Vec3d(eye[0], eye[1], eye[2]), impl_->model);
    impl_->root->accept(drawer);
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
    FinestCounter c;
    impl_->root->accept(c);
    return c.triangles;
}

std::array<Point3, 2> OsgViewProbe::bounds() const
{
    osg::ComputeBoundsVisitor b;
    impl_->root->accept(b);
    const osg::BoundingBox& box = b.getBoundingBox();
    return {Point3{box.xMin(), box.yMin(), box.zMin()}, Point3{box.xMax(), box.yMax(), box.zMax()}};
}

}  // namespace cadlod::test
