// Small helpers shared by the simplifier's unit tests.
#pragma once

#include "cad_meshes.h"
#include "test_mesh.h"

#include "measure/compactness.h"
#include "measure/hausdorff.h"
#include "simplify/best_of_trials.h"

#include <gtest/gtest.h>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/append.h>

#include <algorithm>

namespace cadlod::test {

// The symmetric Hausdorff distance from `result` to `input`, % of the input's diagonal,
// measured with other samples than the weight trials' own (seeds 1 and 2, 100 000 per side).
inline double hausdorffPercent(TestMesh& input, TestMesh& result)
{
    const double forward = oneSidedHausdorff(input, result, 100000, 1).max;
    const double backward = oneSidedHausdorff(result, input, 100000, 2).max;
    return 100 * std::max(forward, backward) / liveDiagonal(input);
}

// A part simplified, against the part as built: what the tests compare.
struct Reduction {
    SimplifyStats stats;
    int faces = 0;
    double slivers = 0.0;   // share of faces with compactness < 0.1
    double distance = 0.0;  // hausdorffPercent
};

// `make`'s part (a CadBuilder recipe) simplified with `p`.
template <class Make>
Reduction reduceWith(const Make& make, const SimplifyParams& p)
{
    TestMesh input, m;
    buildInputAndCopy(make, input, m);
    Reduction r;
    r.stats = bestOfTrials(m, p);
    EXPECT_TRUE(r.stats.ok) << r.stats.message;
    r.faces = m.fn;
    r.slivers = meshCompactness(m).shareBelow01;
    r.distance = hausdorffPercent(input, m);
    return r;
}

inline void copyMesh(TestMesh& dst, TestMesh& src)
{
    vcg::tri::Append<TestMesh, TestMesh>::MeshCopy(dst, src);
    vcg::tri::UpdateBounding<TestMesh>::Box(dst);
}

inline void makeShaft(TestMesh& m, int segments, int rings = 1)
{
    CadBuilder b;
    revolve(b, shaftProfile(), shaftSpec(segments, rings));
    b.build(m);
}

// An open tube: a cylinder of long strips without caps (two boundary circles).
inline void makeTube(TestMesh& m, int segments, int rings = 1)
{
    CadBuilder b;
    RevolveSpec s;
    s.segments = segments;
    s.cylinderRings = rings;
    revolve(b, {{0, 10}, {60, 10}}, s);
    b.build(m);
}

inline SimplifyParams targetParams(int faces)
{
    SimplifyParams p;
    p.targetFaces = faces;
    return p;
}

}  // namespace cadlod::test
