// Walking an OSG scene graph as it is drawn: each node with its placement (the product of
// the transforms above it), each geometry by the triangles that have an area.
#pragma once

#include <osg/Geometry>
#include <osg/NodeVisitor>
#include <osg/Transform>
#include <osg/TriangleIndexFunctor>

#include <vector>

namespace cadlod::test {

// A visitor of every child that knows where the node it visits is placed.
class PlacedVisitor : public osg::NodeVisitor {
public:
    PlacedVisitor() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) { matrices_.push_back(osg::Matrixd::identity()); }

    using osg::NodeVisitor::apply;
    void apply(osg::Transform& t) override
    {
        osg::Matrixd local;
        t.computeLocalToWorldMatrix(local, this);
        matrices_.push_back(local * matrices_.back());
        traverse(t);
        matrices_.pop_back();
    }

protected:
    const osg::Matrixd& placed() const { return matrices_.back(); }

private:
    std::vector<osg::Matrixd> matrices_;
};

namespace detail {

template <class Visit>
struct TriangleCorners {
    const osg::Vec3Array* vertices = nullptr;
    Visit* visit = nullptr;
    void operator()(unsigned a, unsigned b, unsigned c)
    {
        const osg::Vec3 &pa = (*vertices)[a], &pb = (*vertices)[b], &pc = (*vertices)[c];
        if (pa != pb && pb != pc && pa != pc)
            (*visit)(pa, pb, pc);
    }
};

}  // namespace detail

// Calls visit(a, b, c) with the corners, in the geometry's own frame, of each triangle of `g`
// that has an area: not those with two corners at one point, such as a triangle strip's joins,
// which draw nothing and whose centroid may lie off the surface.
template <class Visit>
void forEachTriangle(const osg::Geometry& g, Visit visit)
{
    const auto* vertices = dynamic_cast<const osg::Vec3Array*>(g.getVertexArray());
    if (!vertices)
        return;
    osg::TriangleIndexFunctor<detail::TriangleCorners<Visit>> corners;
    corners.vertices = vertices;
    corners.visit = &visit;
    g.accept(corners);
}

}  // namespace cadlod::test
