// The surface a simplification started from, kept so that a collapse can be checked
// against it before it runs: no face it makes may be turned over 90° away from the input
// surface nearest to it.
//
// The per-collapse normal checks of cad_edge_collapse.h compare a face with itself (before
// the collapse, and in the input). They cannot see a face that keeps its own orientation
// but moves across a thin part, or cuts across the bend of a thin strip (a chip's lead, a
// sheet-metal flange): its nearest input surface is then the far side, which faces the other
// way. A viewer sees such a face lit as the wrong side. Only the input itself can tell.
//
// The test is the one the benchmarks count flipped faces with (tests/simplify/mesh_checks.h):
// at the face's centroid, the nearest input face, or failing that one facing the same side
// no farther away than a tie of 1e-5 of the diagonal (where input surfaces touch: a chip
// standing on a board). Every part of an assembly counts: where two parts fit tightly (a
// pin in a bore, closer than the tessellation's chord error), a face of the pin carried
// nearer the bore's wall than its own surface is lit as the bore's inside is, and that is
// the face the benchmarks compare it with. Counting only the face's own part would let such
// collapses run unpriced.
#pragma once

#include "measure/triangle_tree.h"

#include <vcg/space/point3.h>

#include <cstdint>
#include <vector>

namespace cadlod {

class InputSurface
{
public:
    // The live faces of `m`, in the coordinates they have now. `diagonal`: the model's.
    template <class MeshType>
    InputSurface(const MeshType& m, double diagonal)
        : tree_(TriangleTree::of(m, detail::liveFaces(m))), tie_(1e-5 * diagonal), maxDistance_(4 * diagonal + 1)
    {
        nearestFace_.assign(m.face.size(), -1);
        std::int32_t next = 0;
        for (std::size_t i = 0; i < m.face.size(); ++i)
            if (!m.face[i].IsD())
                nearestFace_[i] = next++;
    }

    // Whether a face at `centroid` with unit normal `normal` faces the same side as the
    // input surface nearest to it. `face`: the face's index in the mesh the surface was made
    // of. Faces keep their index through collapses and move a little at a time, so the
    // input face found nearest last time (at first, the face itself) is remembered: when it
    // faces the same side, only a nearer face can say otherwise, and a search bounded by it
    // prunes most of the tree.
    bool facesAlong(std::size_t face, const vcg::Point3d& centroid, const vcg::Point3d& normal)
    {
        if (tree_.empty())
            return true;
        double bound = maxDistance_;
        const std::int32_t hint = face < nearestFace_.size() ? nearestFace_[face] : -1;
        if (hint >= 0 && sameSide(std::size_t(hint), normal)) {
            bound = tree_.distance(std::size_t(hint), centroid) - tie_;
            if (!(bound > 0))
                return true;
        }
        double nearest = 0;
        const std::int64_t i = tree_.closest(centroid, bound, nearest);
        if (i < 0)
            return true;
        if (face < nearestFace_.size())
            nearestFace_[face] = std::int32_t(i);
        if (sameSide(std::size_t(i), normal))
            return true;
        double aligned = 0;
        return tree_.closest(centroid, nearest + tie_, aligned,
                             [&](std::size_t k) { return sameSide(k, normal); }) >= 0;
    }

    // The distance from p to the input surface.
    double distance(const vcg::Point3d& p) const
    {
        double d = 0;
        return tree_.closest(p, maxDistance_, d) >= 0 ? d : 0.0;
    }

    // The distance from p to the input surface where it is beyond `known`; otherwise
    // `known`. Most points lie within it, and any one face within it proves that: the walk
    // stops there, where finding the closest would go on. Points come in a row and lie near
    // each other (a new face's centroid and edge midpoints): the input faces found within for
    // the ones before are tried first.
    using RecentFaces = TriangleTree::RecentHits;
    double distanceBeyond(const vcg::Point3d& p, double known, RecentFaces& recent) const
    {
        if (known > 0 && tree_.anyWithin(p, known, recent) >= 0)
            return known;
        return distance(p);
    }

    // Face `face` (new: a tunnel's cap) lies where face `like` does: its search starts there.
    void adopt(std::size_t face, std::size_t like)
    {
        if (face < nearestFace_.size() && like < nearestFace_.size())
            nearestFace_[face] = nearestFace_[like];
    }

    // How many live faces of `m` face away from the input surface nearest to them, each
    // looked up afresh (`m` need not be the mesh the surface was made of).
    template <class MeshType>
    int turnedFaces(const MeshType& m)
    {
        int turned = 0;
        for (const auto& f : m.face) {
            if (f.IsD())
                continue;
            const vcg::Point3d a = vcg::Point3d::Construct(f.cP(0)), b = vcg::Point3d::Construct(f.cP(1)),
                               c = vcg::Point3d::Construct(f.cP(2));
            const vcg::Point3d n = (b - a) ^ (c - a);
            const double len = n.Norm();
            if (len > 0 && !facesAlong(kNoHint, (a + b + c) / 3.0, n / len))
                ++turned;
        }
        return turned;
    }

    static constexpr std::size_t kNoHint = std::size_t(-1);

private:
    // The sign is all that counts: the input face's normal need not be unit.
    bool sameSide(std::size_t face, const vcg::Point3d& normal) const
    {
        const TriangleTree::Triangle t = tree_.triangle(face);
        return ((t[1] - t[0]) ^ (t[2] - t[0])) * normal >= 0;
    }

    TriangleTree tree_;
    std::vector<std::int32_t> nearestFace_;  // per mesh face: the input face found nearest last, -1: none
    double tie_;
    double maxDistance_;
};

}  // namespace cadlod
