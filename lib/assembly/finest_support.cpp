#include "assembly/finest_support.h"

#include "measure/triangle_tree.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace cadlod {
namespace {

flt::Vec3d centroidOf(const flt::Part& part, const flt::Triangle& t)
{
    flt::Vec3d c{};
    for (int a = 0; a < 3; ++a)
        c[a] = (part.positions[t[0]][a] + part.positions[t[1]][a] + part.positions[t[2]][a]) / 3.0;
    return c;
}

flt::Vec3f extentOf(const flt::Part& part, const flt::Triangle& t)
{
    flt::Vec3f extent{};
    for (int a = 0; a < 3; ++a) {
        const double p = part.positions[t[0]][a], q = part.positions[t[1]][a], r = part.positions[t[2]][a];
        extent[a] = float(std::max({p, q, r}) - std::min({p, q, r}));
    }
    return extent;
}

// A level's triangles in one tree, their corners in single precision about `origin` (which
// keeps the precision of site coordinates), numbered part after part.
TriangleTree treeOf(const flt::Level& level, const flt::Vec3d& origin)
{
    std::vector<vcg::Point3f> vertices;
    std::vector<TriangleTree::Corners> corners;
    for (const flt::Part& part : level.parts) {
        const auto first = std::uint32_t(vertices.size());
        for (const flt::Vec3d& p : part.positions)
            vertices.emplace_back(float(p[0] - origin[0]), float(p[1] - origin[1]), float(p[2] - origin[2]));
        for (const flt::Triangle& t : part.triangles)
            corners.push_back({first + t[0], first + t[1], first + t[2]});
    }
    return TriangleTree(std::move(vertices), std::move(corners));
}

// The index in treeOf(level) of the triangle nearest `p`.
std::uint32_t nearestIn(const TriangleTree& tree, const flt::Vec3d& p, const flt::Vec3d& origin)
{
    double distance = 0;
    const std::int64_t i = tree.closest(vcg::Point3d(p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]),
                                        std::numeric_limits<double>::infinity(), distance);
    return std::uint32_t(std::max<std::int64_t>(i, 0));
}

// What each triangle of coarse level `level` stands for: the finest triangles whose
// centroid it is the nearest triangle to, so that wherever a finest triangle was, the coarse
// triangles of its chunk cover it; or, where it is nearest to none, the finest triangle
// nearest its own centroid.
SupportedLevel supportOf(const flt::Level& level, const FinestTriangles& finest, const TriangleTree& finestTree,
                         const flt::Vec3d& origin)
{
    const TriangleTree tree = treeOf(level, origin);
    std::vector<std::uint32_t> nearest(finest.size());
    tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, std::uint32_t(finest.size())),
                      [&](const tbb::blocked_range<std::uint32_t>& range) {
                          for (std::uint32_t f = range.begin(); f != range.end(); ++f)
                              nearest[f] = nearestIn(tree, finest.centroid(f), origin);
                      });
    std::vector<std::vector<std::uint32_t>> standsFor(level.triangleCount());
    for (std::uint32_t f = 0; f < finest.size(); ++f)
        standsFor[nearest[f]].push_back(f);
    SupportedLevel out{level, {}};
    std::size_t i = 0;
    for (const flt::Part& part : level.parts) {
        SupportedLevel::Support& support = out.support.emplace_back();
        for (const flt::Triangle& t : part.triangles) {
            std::vector<std::uint32_t>& own = standsFor[i++];
            if (own.empty())
                own.push_back(nearestIn(finestTree, centroidOf(part, t), origin));
            support.finest.insert(support.finest.end(), own.begin(), own.end());
            support.start.push_back(std::uint32_t(support.finest.size()));
        }
    }
    return out;
}

}  // namespace

FinestTriangles::FinestTriangles(const flt::Level& finest)
{
    for (const flt::Part& part : finest.parts)
        for (const flt::Triangle& t : part.triangles) {
            centroids_.push_back(centroidOf(part, t));
            extents_.push_back(extentOf(part, t));
        }
}

std::vector<SupportedLevel> supported(const std::vector<flt::Level>& levels, const std::vector<double>& errors,
                                      const FinestTriangles& finest)
{
    const flt::Vec3d origin = levels.front().center;
    const TriangleTree finestTree = treeOf(levels.front(), origin);
    std::vector<SupportedLevel> out;
    SupportedLevel& first = out.emplace_back(SupportedLevel{levels.front(), {}});
    std::uint32_t next = 0;
    for (const flt::Part& part : levels.front().parts) {
        SupportedLevel::Support& support = first.support.emplace_back();
        for (std::size_t t = 0; t < part.triangles.size(); ++t) {
            support.finest.push_back(next++);
            support.start.push_back(std::uint32_t(support.finest.size()));
        }
    }
    for (std::size_t k = 1; k < levels.size(); ++k) {
        out.push_back(supportOf(levels[k], finest, finestTree, origin));
        out.back().error = errors[k];
    }
    return out;
}

}  // namespace cadlod
