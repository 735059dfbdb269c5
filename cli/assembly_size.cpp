#include "assembly_size.h"

#include "lod/cluster_tree.h"  // Box3

#include <vector>

namespace cadlod::cli {
namespace {

// Each geometry's box in its own frame, its child placements included: one pass over the
// distinct geometry however many times it is placed.
class FrameBoxes {
public:
    explicit FrameBoxes(const vrml::Assembly& assembly)
        : assembly_(assembly), boxes_(assembly.geometries.size()), state_(assembly.geometries.size(), State::Unseen)
    {
    }

    const Box3& of(std::size_t g)
    {
        if (state_[g] != State::Unseen)  // done, or a geometry that holds itself: no more of it
            return boxes_[g];
        state_[g] = State::Open;
        const vrml::Geometry& geometry = assembly_.geometries[g];
        for (const vrml::Part& part : geometry.parts)
            for (const auto& p : part.positions)
                boxes_[g].add(std::array<double, 3>{p[0], p[1], p[2]});
        for (const vrml::ChildPlacement& child : geometry.children)
            addMoved(of(child.geometry), child.relative, boxes_[g]);
        state_[g] = State::Done;
        return boxes_[g];
    }

private:
    enum class State { Unseen, Open, Done };

    static void addMoved(const Box3& box, const vrml::Mat4& matrix, Box3& into)
    {
        if (box.empty())
            return;
        for (int corner = 0; corner < 8; ++corner) {
            const vrml::Vec3 p = matrix.transformPoint({corner & 1 ? box.hi[0] : box.lo[0],
                                                        corner & 2 ? box.hi[1] : box.lo[1],
                                                        corner & 4 ? box.hi[2] : box.lo[2]});
            into.add(std::array<double, 3>{p.x, p.y, p.z});
        }
    }

    const vrml::Assembly& assembly_;
    std::vector<Box3> boxes_;
    std::vector<State> state_;
};

}  // namespace

double placedDiagonal(const vrml::Assembly& assembly)
{
    if (assembly.empty())
        return 0.0;
    FrameBoxes boxes(assembly);
    const Box3& world = boxes.of(0);  // the root's frame is the world
    return world.empty() ? 0.0 : 2.0 * world.halfDiagonal();
}

}  // namespace cadlod::cli
