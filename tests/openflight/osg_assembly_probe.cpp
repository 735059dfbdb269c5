#include "osg_assembly_probe.h"

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/NodeVisitor>
#include <osg/TriangleIndexFunctor>
#include <osgDB/ReadFile>

#include <chrono>
#include <set>

namespace cadlod::test {
namespace {

struct Indices {
    std::vector<unsigned> corners;
    void operator()(unsigned a, unsigned b, unsigned c) { corners.insert(corners.end(), {a, b, c}); }
};

class AssemblyCollector : public osg::NodeVisitor {
public:
    AssemblyCollector(OsgAssemblyProbe& probe, const std::string& modelName)
        : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), probe_(probe), modelName_(modelName)
    {
        matrices_.push_back(osg::Matrixd::identity());
    }

    void apply(osg::Node& node) override
    {
        enter(node);
        traverse(node);
        leave(node);
    }

    void apply(osg::Transform& transform) override
    {
        enter(transform);
        osg::Matrixd local;
        transform.computeLocalToWorldMatrix(local, this);
        matrices_.push_back(local * matrices_.back());  // OSG's row vectors: local first
        traverse(transform);
        matrices_.pop_back();
        leave(transform);
    }

    void apply(osg::LOD& lod) override
    {
        enter(lod);
        lods_.insert(&lod);
        // The finest level is the one drawn from up close: its range starts at 0.
        for (unsigned i = 0; i < lod.getNumChildren(); ++i) {
            subgraphs_.insert(lod.getChild(i));
            if (i < lod.getNumRanges() && lod.getMinRange(i) <= 0 && lod.getMaxRange(i) > 0)
                lod.getChild(i)->accept(*this);
        }
        leave(lod);
    }

    void apply(osg::Geode& geode) override
    {
        enter(geode);
        for (unsigned i = 0; i < geode.getNumDrawables(); ++i)
            if (osg::Geometry* g = geode.getDrawable(i)->asGeometry()) {
                ++probe_.drawables;
                collect(*g);
            }
        leave(geode);
    }

    void finish()
    {
        probe_.sharedNodes = shared_.size();
        probe_.lodNodes = lods_.size();
        probe_.lodSubgraphs = subgraphs_.size();
    }

private:
    void enter(osg::Node& node)
    {
        if (node.getNumParents() > 1)
            shared_.insert(&node);
        if (!node.getName().empty()) {
            if (!isFrame(node.getName()) && placement().empty())
                ++probe_.placements[node.getName()].visits;
            names_.push_back(node.getName());
            ++probe_.named[node.getName()].visits;
        }
    }

    void leave(osg::Node& node)
    {
        if (!node.getName().empty())
            names_.pop_back();
    }

    void collect(osg::Geometry& g)
    {
        const auto* v = dynamic_cast<const osg::Vec3Array*>(g.getVertexArray());
        if (!v)
            return;
        osg::TriangleIndexFunctor<Indices> f;
        g.accept(f);
        const osg::Matrixd& m = matrices_.back();
        for (std::size_t t = 0; t + 2 < f.corners.size(); t += 3) {
            const unsigned a = f.corners[t], b = f.corners[t + 1], c = f.corners[t + 2];
            if ((*v)[a] == (*v)[b] || (*v)[b] == (*v)[c] || (*v)[a] == (*v)[c])
                continue;  // degenerate: strip joints
            std::array<std::array<double, 3>, 3> tri{};
            for (int k = 0; k < 3; ++k) {
                const osg::Vec3d p = osg::Vec3d((*v)[f.corners[t + k]]) * m;
                tri[k] = {p.x(), p.y(), p.z()};
            }
            probe_.finestTriangles.push_back(tri);
            for (const std::string& name : names_)
                note(probe_.named[name], tri);
            if (!placement().empty())
                note(probe_.placements[placement()], tri);
        }
    }

    static void note(OsgNamedNode& n, const std::array<std::array<double, 3>, 3>& tri)
    {
        ++n.triangles;
        for (const auto& p : tri)
            for (int c = 0; c < 3; ++c) {
                n.min[c] = std::min(n.min[c], p[c]);
                n.max[c] = std::max(n.max[c], p[c]);
            }
    }

    // The outermost name on the path that is not the model's.
    std::string placement() const
    {
        for (const std::string& name : names_)
            if (!isFrame(name))
                return name;
        return {};
    }

    // The model's root and the clusters of hierarchical LOD ("cluster 1.2": a space no VRML
    // name holds), with the LOD nodes OSG makes of their records ("newLOD", "LOD child0"),
    // frame the placements.
    bool isFrame(const std::string& name) const
    {
        return isModelName(name) || name.rfind("cluster ", 0) == 0 || name == "newLOD" ||
               name.rfind("LOD child", 0) == 0;
    }

    // The header's ID holds 7 characters of the model's name; the root Group all of it.
    bool isModelName(const std::string& name) const
    {
        return name == modelName_ || (name.size() == 7 && modelName_.compare(0, 7, name) == 0);
    }

    OsgAssemblyProbe& probe_;
    std::string modelName_;
    std::vector<osg::Matrixd> matrices_;
    std::vector<std::string> names_;
    std::set<const osg::Node*> shared_, lods_, subgraphs_;
};

}  // namespace

OsgAssemblyProbe probeAssemblyWithOsg(const std::string& path, const std::string& modelName)
{
    OsgAssemblyProbe probe;
    osg::ref_ptr<osgDB::Options> options = new osgDB::Options;
    options->setObjectCacheHint(osgDB::Options::CACHE_NONE);
    const auto t0 = std::chrono::steady_clock::now();
    osg::ref_ptr<osg::Node> root = osgDB::readRefNodeFile(path, options.get());
    probe.loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!root)
        return probe;
    probe.loaded = true;
    AssemblyCollector collector(probe, modelName);
    root->accept(collector);
    collector.finish();
    return probe;
}

}  // namespace cadlod::test
