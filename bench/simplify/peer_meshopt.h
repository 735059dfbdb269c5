// meshoptimizer's simplifier (meshopt_simplify) on a vcglib mesh: indices and positions
// out, simplified indices back in. Target error 1 (no error bound): it stops at the count.
#pragma once

#include <meshoptimizer.h>

#include <vcg/complex/complex.h>

#include <vector>

namespace cadlod::bench {

// Simplifies until `targetFaces` or until the next collapse would exceed `targetError`
// (meshoptimizer's relative error: a fraction of the mesh extent); returns the error it
// reports for the result.
template <class MeshType>
float meshoptSimplify(MeshType& m, int targetFaces, float targetError)
{
    std::vector<float> positions;
    positions.reserve(3 * m.vert.size());
    for (const auto& v : m.vert)
        for (int k = 0; k < 3; ++k)
            positions.push_back(float(v.cP()[k]));
    std::vector<unsigned> indices;
    indices.reserve(3 * m.fn);
    for (const auto& f : m.face)
        if (!f.IsD())
            for (int j = 0; j < 3; ++j)
                indices.push_back(unsigned(f.cV(j) - &m.vert[0]));
    std::vector<unsigned> out(indices.size());
    float resultError = 0.0f;
    const size_t n = meshopt_simplify(out.data(), indices.data(), indices.size(), positions.data(), m.vert.size(),
                                      3 * sizeof(float), 3 * size_t(targetFaces), targetError, 0, &resultError);
    for (auto& f : m.face)
        if (!f.IsD())
            vcg::tri::Allocator<MeshType>::DeleteFace(m, f);
    auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, n / 3);
    for (size_t i = 0; i < n; i += 3, ++fi)
        for (int j = 0; j < 3; ++j)
            fi->V(j) = &m.vert[out[i + j]];
    return resultError;
}

template <class MeshType>
void meshoptSimplify(MeshType& m, int targetFaces)
{
    meshoptSimplify(m, targetFaces, 1.0f);
}

}  // namespace cadlod::bench
