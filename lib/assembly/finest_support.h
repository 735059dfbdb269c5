// What the triangles of a part's coarse levels stand for on its finest level (part_chunks.h):
// each finest triangle is stood for by the coarse triangle nearest its centroid on every
// level, so a chunk that holds the coarse triangles standing for its finest ones covers, on
// every level, the surface its finest level does.
#pragma once

#include "openflight/lod_model.h"  // flt::Level

#include <cstdint>
#include <vector>

namespace cadlod {

// The finest level's triangles: where each lies and how far it spans along each axis.
class FinestTriangles {
public:
    explicit FinestTriangles(const flt::Level& finest);

    std::size_t size() const { return centroids_.size(); }
    const flt::Vec3d& centroid(std::uint32_t i) const { return centroids_[i]; }
    const flt::Vec3f& extent(std::uint32_t i) const { return extents_[i]; }

private:
    std::vector<flt::Vec3d> centroids_;
    std::vector<flt::Vec3f> extents_;
};

// A level's triangles, each with the finest triangles it stands for (a finest triangle:
// itself), as indices into FinestTriangles.
struct SupportedLevel {
    struct Support {
        std::vector<std::uint32_t> start{0};  // triangle t's are finest[start[t], start[t + 1])
        std::vector<std::uint32_t> finest;
    };
    flt::Level level;
    std::vector<Support> support;  // one per part
    double error = 0;              // how far the level may stand from the finest
};

// `levels` (finest first) with what each triangle stands for, `errors[k]` the error of level k.
std::vector<SupportedLevel> supported(const std::vector<flt::Level>& levels, const std::vector<double>& errors,
                                      const FinestTriangles& finest);

}  // namespace cadlod
