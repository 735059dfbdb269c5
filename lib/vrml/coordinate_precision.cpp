#include "vrml/coordinate_precision.h"

#include "mesh/float_spacing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace cadlod::vrml {
namespace {

// The box of one CAD part's vertices (all its colours) and how far they reach from the origin.
struct Extent {
    std::string name;
    Vec3f low{std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
    Vec3f high{-std::numeric_limits<float>::max(), -std::numeric_limits<float>::max(),
               -std::numeric_limits<float>::max()};
    double farthest = 0;  // the largest coordinate, in magnitude

    void add(const Part& part)
    {
        if (name.empty())
            name = part.name;
        for (const Vec3f& p : part.positions)
            for (int a = 0; a < 3; ++a) {
                low[a] = std::min(low[a], p[a]);
                high[a] = std::max(high[a], p[a]);
                farthest = std::max(farthest, double(std::abs(p[a])));
            }
    }
    double size() const
    {
        double s = 0;
        for (int a = 0; a < 3; ++a)
            s += (double(high[a]) - low[a]) * (double(high[a]) - low[a]);
        return std::sqrt(s);
    }
    // The float spacing where the part stands over its size; above kReadableVertexSpacing it
    // is read coarsely. Flat or empty parts have no size to compare with.
    double coarseness() const { return size() > 0 ? floatSpacing(farthest) / size() : 0; }
};

// One extent per CAD part: the parts of one owner together, each geometry of an assembly whole.
std::vector<Extent> extentsOf(const Scene& scene)
{
    std::vector<Extent> extents;
    std::map<int, std::size_t> byOwner;
    for (const Part& part : scene.parts) {
        if (part.owner < 0) {
            extents.emplace_back().add(part);
            continue;
        }
        const auto [at, fresh] = byOwner.emplace(part.owner, extents.size());
        if (fresh)
            extents.emplace_back();
        extents[at->second].add(part);
    }
    for (const Geometry& geometry : scene.assembly.geometries) {
        if (geometry.parts.empty())
            continue;
        Extent& extent = extents.emplace_back();
        extent.name = geometry.name;
        for (const Part& part : geometry.parts)
            extent.add(part);
    }
    return extents;
}

}  // namespace

void warnOfCoarseCoordinates(Scene& scene, const std::string& fileName)
{
    std::size_t coarse = 0;
    const Extent* worst = nullptr;
    const std::vector<Extent> extents = extentsOf(scene);
    for (const Extent& e : extents) {
        if (e.coarseness() <= kReadableVertexSpacing)
            continue;
        ++coarse;
        if (!worst || e.coarseness() > worst->coarseness())
            worst = &e;
    }
    if (!worst)
        return;
    char text[600];
    std::snprintf(text, sizeof text,
                  "%zu part%s stand%s so far from the origin that the 32-bit numbers the model is read into are "
                  "spaced wider than %g of %s size, up to %.2g (%s): %s read only to within that spacing. Export "
                  "the model nearer the origin, or its parts about their own origin under a Transform",
                  coarse, coarse == 1 ? "" : "s", coarse == 1 ? "s" : "", kReadableVertexSpacing,
                  coarse == 1 ? "its" : "their", worst->coarseness(), worst->name.c_str(),
                  coarse == 1 ? "it is" : "they are");
    scene.diagnostics.warn("coarse coordinates", fileName, text);
}

}  // namespace cadlod::vrml
