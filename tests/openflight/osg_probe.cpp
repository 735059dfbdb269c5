#include "osg_probe.h"

#include <osg/CullFace>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/NodeVisitor>
#include <osg/TriangleIndexFunctor>
#include <osgDB/ReadFile>

namespace cadlod::test {
namespace {

struct IndexCollector {
    std::vector<unsigned> indices;
    void operator()(unsigned a, unsigned b, unsigned c)
    {
        indices.insert(indices.end(), {a, b, c});
    }
};

std::array<float, 3> toArray(const osg::Vec3& v) { return {v.x(), v.y(), v.z()}; }

class Collector : public osg::NodeVisitor {
public:
    explicit Collector(OsgProbe& probe) : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), probe_(probe) {}

    void apply(osg::Node& node) override
    {
        noteName(node);
        noteState(node.getStateSet());
        traverse(node);
    }

    void apply(osg::LOD& lod) override
    {
        noteName(lod);
        for (unsigned i = 0; i < lod.getNumChildren(); ++i) {
            OsgLodChild child;
            if (i < lod.getNumRanges()) {
                child.minRange = lod.getMinRange(i);
                child.maxRange = lod.getMaxRange(i);
            }
            child.center = toArray(lod.getCenter());
            probe_.lods.push_back(child);
            const std::size_t slot = probe_.lods.size() - 1;
            const int saved = currentLod_;
            currentLod_ = int(slot);
            lod.getChild(i)->accept(*this);
            currentLod_ = saved;
        }
    }

    void apply(osg::Geode& geode) override
    {
        noteName(geode);
        noteState(geode.getStateSet());
        for (unsigned i = 0; i < geode.getNumDrawables(); ++i)
            if (osg::Geometry* g = geode.getDrawable(i)->asGeometry()) {
                noteState(g->getStateSet());
                collect(*g);
            }
    }

private:
    void noteName(osg::Node& node)
    {
        if (node.getName().empty())
            return;
        probe_.names.push_back(node.getName());
        if (currentLod_ >= 0)
            probe_.lods[std::size_t(currentLod_)].names.push_back(node.getName());
    }

    void noteState(const osg::StateSet* s)
    {
        if (!s)
            return;
        if (s->getAttribute(osg::StateAttribute::CULLFACE) &&
            (s->getMode(GL_CULL_FACE) & osg::StateAttribute::ON))
            probe_.cullsBackFaces = true;
        if (s->getMode(GL_CULL_FACE) == osg::StateAttribute::OFF)
            probe_.disablesCulling = true;
    }

    void collect(osg::Geometry& g)
    {
        const auto* v = dynamic_cast<const osg::Vec3Array*>(g.getVertexArray());
        if (!v)
            return;
        const auto* n = dynamic_cast<const osg::Vec3Array*>(g.getNormalArray());
        const bool perVertexNormals = n && n->getBinding() == osg::Array::BIND_PER_VERTEX && n->size() == v->size();
        const auto* c = dynamic_cast<const osg::Vec4Array*>(g.getColorArray());
        osg::TriangleIndexFunctor<IndexCollector> f;
        g.accept(f);
        std::vector<OsgTriangle>& out = currentLod_ >= 0 ? probe_.lods[std::size_t(currentLod_)].triangles
                                                         : probe_.outsideLods;
        for (std::size_t t = 0; t + 2 < f.indices.size(); t += 3) {
            OsgTriangle tri;
            for (int k = 0; k < 3; ++k) {
                const unsigned i = f.indices[t + k];
                tri.position[k] = toArray((*v)[i]);
                if (perVertexNormals)
                    tri.normal[k] = toArray((*n)[i]);
            }
            if (tri.position[0] == tri.position[1] || tri.position[1] == tri.position[2] ||
                tri.position[0] == tri.position[2])
                continue;  // degenerate: strip joints
            tri.hasNormals = perVertexNormals;
            if (c && !c->empty()) {
                const osg::Vec4& col = c->size() == v->size() ? (*c)[f.indices[t]] : (*c)[0];
                tri.color = {col.r(), col.g(), col.b(), col.a()};
                if (c->size() == v->size() && c->getBinding() == osg::Array::BIND_PER_VERTEX) {
                    tri.hasCornerColors = true;
                    for (int k = 0; k < 3; ++k) {
                        const osg::Vec4& ck = (*c)[f.indices[t + k]];
                        tri.cornerColor[k] = {ck.r(), ck.g(), ck.b(), ck.a()};
                    }
                }
            }
            out.push_back(tri);
        }
    }

    OsgProbe& probe_;
    int currentLod_ = -1;
};

}  // namespace

OsgProbe probeWithOsg(const std::string& path, const std::string& options)
{
    OsgProbe probe;
    osg::ref_ptr<osgDB::Options> opts = new osgDB::Options(options);
    opts->setObjectCacheHint(osgDB::Options::CACHE_NONE);  // tests rewrite files of the same name
    osg::ref_ptr<osg::Node> root = osgDB::readRefNodeFile(path, opts.get());
    if (!root)
        return probe;
    probe.loaded = true;
    Collector collector(probe);
    root->accept(collector);
    return probe;
}

}  // namespace cadlod::test
