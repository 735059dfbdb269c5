// The shading price (SimplifyParams::shadingWeight, shadingAngle): a collapse that turns faces
// more than the shading angle from the faces they were in the input also pays for their area.
// Judged as a viewer sees it, by the shading measure of bench/shading (docs/shading_measure.md):
// on generated CAD parts where a far reduction must either flatten a curved surface or give up
// small details, the price leaves fewer pixels shaded differently from the input.
#include "cad_meshes.h"
#include "indexed_mesh.h"
#include "simplify_test_util.h"
#include "test_mesh.h"

#include "simplify/best_of_trials.h"

#include <gtest/gtest.h>

#include <functional>

using namespace cadlod;
using namespace cadlod::test;

namespace {

// The share of pixels a viewer sees differ from the input after a reduction by `percent`.
double visibleAfter(const std::function<void(CadBuilder&)>& make, double percent, double shadingWeight, int* faces)
{
    TestMesh input, m;
    buildInputAndCopy(make, input, m);
    SimplifyParams p;
    p.reductionPerc = percent;
    p.shadingWeight = shadingWeight;
    p.weightTrialsMaxFaces = 0;  // the price alone, at one plane weight (weight_trials.h),
    p.sliverCountShare = 2.0;    // and without the sliver count, which on the board at 75 % takes
                                 // collapses the price would choose (test_sliver_count.cpp)
    const SimplifyStats s = bestOfTrials(m, p);
    EXPECT_TRUE(s.ok) << s.message;
    *faces = m.fn;
    const shading::IndexedMesh a = toIndexed(input), r = toIndexed(m);
    return shading::compare(a.ref(), r.ref()).visiblePercent;
}

}  // namespace

// The assembly's shaft and the board's capacitors are cylinders of long strips: at 75 % the
// geometry alone takes their facets (each costs a hair of sagitta) and they show flat bands;
// with the price the reduction goes where fewer pixels change shade. Elsewhere the price must
// cost no visible shading: no case is more than 5 % worse (relative) with it than without.
TEST(SimplifyShadingPrice, FewerPixelsShadedDifferently)
{
    struct Case {
        const char* name;
        std::function<void(CadBuilder&)> make;
        double percent;
        double mostWithOverWithout;  // the visible share with the price over the share without
    };
    const Case cases[] = {
        {"assembly", [](CadBuilder& b) { assembly(b, 48); }, 75.0, 0.8},
        {"circuit board", [](CadBuilder& b) { circuitBoard(b); }, 75.0, 0.95},
        {"assembly", [](CadBuilder& b) { assembly(b, 48); }, 90.0, 1.05},
        {"circuit board", [](CadBuilder& b) { circuitBoard(b); }, 90.0, 1.05},
        {"shaft", [](CadBuilder& b) { revolve(b, shaftProfile(), shaftSpec(96, 4)); }, 95.0, 1.05},
        {"gull-wing chip", [](CadBuilder& b) { gullWingChip(b, 8); }, 90.0, 1.05},
    };
    for (const Case& c : cases) {
        int withFaces = 0, withoutFaces = 0;
        const double with = visibleAfter(c.make, c.percent, SimplifyParams{}.shadingWeight, &withFaces);
        const double without = visibleAfter(c.make, c.percent, 0.0, &withoutFaces);
        EXPECT_EQ(withFaces, withoutFaces) << c.name << " at " << c.percent << " %: the same face count";
        EXPECT_LE(with, c.mostWithOverWithout * without)
            << c.name << " at " << c.percent << " %: " << with << " % of the pixels with the price, " << without
            << " % without";
    }
}

// A negative weight or a shading angle out of range is refused with a reason.
TEST(SimplifyShadingPrice, RefusesWeightsOutOfRange)
{
    TestMesh m;
    makeShaft(m, 24);
    SimplifyParams p;
    p.reductionPerc = 50;
    p.shadingWeight = -1;
    SimplifyStats s = bestOfTrials(m, p);
    EXPECT_FALSE(s.ok);
    EXPECT_NE(s.message.find("shading"), std::string::npos) << s.message;
    p.shadingWeight = 1e-5;
    p.shadingAngle = 200;
    s = bestOfTrials(m, p);
    EXPECT_FALSE(s.ok);
    EXPECT_NE(s.message.find("shading angle"), std::string::npos) << s.message;
}
