// What OpenSceneGraph draws of an LOD model from one eye point (design.md §8): every LOD
// node picks its children by the eye's distance to its centre in its own frame, as OSG's
// cull does. For each drawable: the switch distance s of the LOD child it is drawn by
// (scaled to the model), and n, the distance from the eye to its nearest vertex; s / n is
// the error a viewer reads off the switch distance. For each placement (the outermost
// named node below the model's frame: its root, clusters and OSG's LOD nodes), how many
// times it is drawn, by itself or by a cluster proxy standing for it. And the widest gap on
// screen: how far points of the finest geometry are from everything drawn, in pixels at
// their own distance; a level within its error leaves none wider than that error, a chunk
// or part missing where its neighbours have coarsened leaves a hole as wide as it is.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace cadlod::test {

using Point3 = std::array<double, 3>;

// The gaps on screen from one eye point (OsgViewProbe::drawFrom with an OsgGapQuery).
struct OsgGaps {
    double widestPx = 0;    // the widest over the samples
    std::size_t wider = 0;  // samples whose gap is wider than asked
};

// For each of `samples`, its gap: the distance to the nearest triangle drawn, over the size
// of a pixel `pixelRadians` wide at the sample's distance from the eye; counted where wider
// than `widerThanPx`.
struct OsgGapQuery {
    const std::vector<Point3>* samples = nullptr;
    double pixelRadians = 0;
    double widerThanPx = 0;
};

struct OsgView {
    double worstApparentPx = 0;    // max s / n over the drawables drawn by a level with s > 0
    std::size_t triangles = 0;
    std::size_t drawables = 0;
    std::size_t proxyDrawables = 0;  // of the drawables, those of cluster proxies
    std::map<std::string, std::size_t> drawnPlacements;  // drawn by itself or by a proxy
    std::map<std::string, std::size_t> trianglesByLevel;  // by the name of the LOD node drawn
    OsgGaps gaps;                                        // only when asked
};

// The LOD children of one node (sharing a parent and a centre).
struct OsgLodRanges {
    std::vector<std::pair<double, double>> ranges;  // [min, max) per child, in child order
};

class OsgViewProbe {
public:
    OsgViewProbe(const std::string& path, const std::string& modelName);
    bool loaded() const;
    OsgView drawFrom(const Point3& eye, const OsgGapQuery* gaps = nullptr) const;
    std::vector<OsgLodRanges> lodNodes() const;
    std::array<Point3, 2> bounds() const;
    std::size_t finestTriangles() const;  // every LOD node at its child drawn from up close
    // Points on the finest geometry (every LOD node at its child drawn from up close), in the
    // model's frame: the centroids of its triangles, of at most `most` of them evenly spread.
    std::vector<Point3> finestSamples(std::size_t most) const;
    ~OsgViewProbe();

private:
    struct Impl;
    Impl* impl_;
};

}  // namespace cadlod::test
