// A vcglib test mesh as the shading measure's IndexedMesh (bench/shading): its live vertices
// and faces, for the tests and benchmarks that render a result against its input.
#pragma once

#include "shading_error.h"
#include "test_mesh.h"

#include <cstdint>
#include <vector>

namespace cadlod::test {

inline shading::IndexedMesh toIndexed(const TestMesh& m)
{
    shading::IndexedMesh out;
    std::vector<std::uint32_t> index(m.vert.size(), 0);
    for (std::size_t v = 0; v < m.vert.size(); ++v)
        if (!m.vert[v].IsD()) {
            index[v] = std::uint32_t(out.xyz.size() / 3);
            for (int k = 0; k < 3; ++k)
                out.xyz.push_back(double(m.vert[v].cP()[k]));
        }
    for (const auto& f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k)
                out.tri.push_back(index[f.cV(k) - &m.vert[0]]);
    return out;
}

}  // namespace cadlod::test
