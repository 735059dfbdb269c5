// Invariants every imported scene must keep, whatever the input: the fuzz targets abort
// (a finding) when one is broken.
#pragma once

#include "vrml/scene.h"

#include <cmath>
#include <cstddef>
#include <cstdlib>

namespace cadlod::fuzz {

inline void requireValidScene(const vrml::Scene& scene)
{
    for (const auto& part : scene.parts) {
        if (part.triangles.size() % 3 != 0) std::abort();
        for (auto index : part.triangles)
            if (std::size_t(index) >= part.positions.size()) std::abort();
        for (const auto& p : part.positions)
            for (float c : p)
                if (!std::isfinite(c)) std::abort();
    }
}

}  // namespace cadlod::fuzz
