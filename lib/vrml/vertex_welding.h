// Exact welding of coincident vertices across all parts of a scene: CAD exporters write
// a body as many face sets (one per face or material) that repeat the same points.
// Returns, for every scene vertex in part order, the index of its welded vertex.
#pragma once

#include "vrml/scene.h"

#include <cstdint>
#include <vector>

namespace cadlod::vrml {

struct Welding {
    std::vector<uint32_t> weldedIndex;  // per scene vertex, parts concatenated
    uint32_t weldedCount = 0;
};

Welding weldCoincidentVertices(const Scene& scene);

}  // namespace cadlod::vrml
