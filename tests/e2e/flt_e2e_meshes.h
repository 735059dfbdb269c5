// Test meshes for the OpenFlight end-to-end tests, and their triangles in the
// comparable form of tests/openflight/model_fixtures.h.
#pragma once

#include "model_fixtures.h"
#include "test_mesh.h"

#include <vcg/complex/algorithms/create/platonic.h>
#include <vcg/complex/algorithms/update/normal.h>

namespace cadlod::test {

// A torus (closed, curved: its normals matter) with normalized per-vertex normals.
inline void makeTorusMesh(TestMesh& m)
{
    vcg::tri::Torus(m, 3.0f, 1.0f, 48, 24);
    vcg::tri::UpdateNormal<TestMesh>::PerVertexNormalizedPerFaceNormalized(m);
}

inline std::vector<FlatTriangle> meshTriangles(const TestMesh& m)
{
    std::vector<FlatTriangle> out;
    for (const auto& f : m.face) {
        if (f.IsD())
            continue;
        FlatTriangle t;
        for (int k = 0; k < 3; ++k)
            for (int c = 0; c < 3; ++c) {
                t.p[k][c] = f.cV(k)->cP()[c];
                t.n[k][c] = f.cV(k)->cN()[c];
            }
        t.canonicalize();
        out.push_back(t);
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace cadlod::test
