// What every simplified mesh must satisfy, whatever came in: live faces point at live
// vertices inside the vertex vector, the counters match, no live vertex is NaN unless it
// already was.
#pragma once

#include "test_mesh.h"

#include <gtest/gtest.h>

#include <cmath>

namespace cadlod::test {

inline void expectValidMesh(const TestMesh& m, bool inputHadNonFinite = false)
{
    int liveFaces = 0, liveVertices = 0;
    for (const auto& v : m.vert)
        if (!v.IsD()) {
            ++liveVertices;
            if (!inputHadNonFinite) {
                for (int k = 0; k < 3; ++k) {
                    ASSERT_TRUE(std::isfinite(v.cP()[k])) << "vertex " << (&v - &m.vert[0]);
                }
            }
        }
    for (const auto& f : m.face) {
        if (f.IsD()) continue;
        ++liveFaces;
        for (int j = 0; j < 3; ++j) {
            const auto* v = f.cV(j);
            ASSERT_TRUE(v >= &m.vert.front() && v <= &m.vert.back()) << "face " << (&f - &m.face[0]);
            ASSERT_FALSE(v->IsD()) << "face " << (&f - &m.face[0]) << " uses a deleted vertex";
        }
    }
    EXPECT_EQ(liveFaces, m.fn);
    EXPECT_EQ(liveVertices, m.vn);
}

}  // namespace cadlod::test
