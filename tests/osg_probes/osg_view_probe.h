// What OpenSceneGraph draws of an LOD model from one eye point (design.md §8): every LOD
// node picks its children by the eye's distance to its centre in its own frame, as OSG's
// cull does. For each drawable: the switch distance s of the LOD child it is drawn by
// (scaled to the model), and n, the distance from the eye to its nearest vertex; s / n is
// the error a viewer reads off the switch distance. For each placement (the outermost
// named node below the model's frame: its root, clusters and OSG's LOD nodes), how many
// times it is drawn, by itself or by a cluster proxy standing for it.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace cadlod::test {

using Point3 = std::array<double, 3>;

struct OsgView {
    double worstApparentPx = 0;    // max s / n over the drawables drawn by a level with s > 0
    std::size_t triangles = 0;
    std::size_t drawables = 0;
    std::size_t proxyDrawables = 0;  // of the drawables, those of cluster proxies
    std::map<std::string, std::size_t> drawnPlacements;  // drawn by itself or by a proxy
};

// The LOD children of one node (sharing a parent and a centre).
struct OsgLodRanges {
    std::vector<std::pair<double, double>> ranges;  // [min, max) per child, in child order
};

class OsgViewProbe {
public:
    OsgViewProbe(const std::string& path, const std::string& modelName);
    bool loaded() const;
    OsgView drawFrom(const Point3& eye) const;
    std::vector<OsgLodRanges> lodNodes() const;
    std::array<Point3, 2> bounds() const;
    std::size_t finestTriangles() const;  // every LOD node at its child drawn from up close
    ~OsgViewProbe();

private:
    struct Impl;
    Impl* impl_;
};

}  // namespace cadlod::test
