// CAD protection: boundaries stay on the boundary polyline, creases stay sharp and in
// place, no folded faces, part borders kept.
#include "mesh_checks.h"
#include "simplify_test_util.h"

#include <gtest/gtest.h>

#include <vcg/space/segment3.h>

using namespace cadlod;
using namespace cadlod::test;

namespace {

using Segment = vcg::Segment3<double>;

double distanceToSegments(const vcg::Point3d& p, const std::vector<Segment>& segments)
{
    double best = std::numeric_limits<double>::max();
    for (const Segment& s : segments) {
        vcg::Point3d closest;
        double d;
        vcg::SegmentPointDistance(s, p, closest, d);
        best = std::min(best, d);
    }
    return best;
}

vcg::Point3d at(const TestMesh& m, int i) { return vcg::Point3d::Construct(m.vert[i].cP()); }

std::vector<Segment> boundarySegments(const TestMesh& m)
{
    std::vector<Segment> s;
    for (const auto& e : edgeUse(m))
        if (e.second == 1)
            s.emplace_back(at(m, e.first.first), at(m, e.first.second));
    return s;
}

// Edges whose two faces meet at more than `angleDeg`.
std::vector<Segment> creaseSegments(TestMesh& m, double angleDeg)
{
    struct HalfEdge { int a, b; vcg::Point3d n; };
    std::vector<HalfEdge> half;
    for (auto& f : m.face)
        if (!f.IsD())
            for (int j = 0; j < 3; ++j) {
                const int a = int(f.V(j) - &m.vert[0]), b = int(f.V((j + 1) % 3) - &m.vert[0]);
                half.push_back({std::min(a, b), std::max(a, b), unitNormal(f)});
            }
    std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return std::make_pair(x.a, x.b) < std::make_pair(y.a, y.b);
    });
    std::vector<Segment> creases;
    const double cosLimit = std::cos(angleDeg * M_PI / 180);
    for (std::size_t i = 0; i + 1 < half.size(); ++i)
        if (half[i].a == half[i + 1].a && half[i].b == half[i + 1].b && half[i].n * half[i + 1].n < cosLimit)
            creases.emplace_back(at(m, half[i].a), at(m, half[i].b));
    return creases;
}

double totalLength(const std::vector<Segment>& segments)
{
    double sum = 0;
    for (const Segment& s : segments)
        sum += s.Length();
    return sum;
}

}  // namespace

TEST(SimplifyProtection, BoundaryVerticesStayOnTheBoundaryPolyline)
{
    TestMesh original, m;
    makeTube(original, 200, 4);
    copyMesh(m, original);
    const std::vector<Segment> before = boundarySegments(original);
    ASSERT_EQ(before.size(), 400u);
    const SimplifyStats s = bestOfTrials(m, targetParams(original.fn / 4));
    ASSERT_TRUE(s.ok) << s.message;
    ASSERT_NEAR(m.fn, original.fn / 4, 2) << s.message << " flip " << s.rejectedFlip << " shape "
                                          << s.rejectedCompactness << " feature " << s.rejectedFeature << " topo "
                                          << s.rejectedTopology;
    const std::vector<Segment> after = boundarySegments(m);
    ASSERT_FALSE(after.empty());
    const double tolerance = 1e-5 * original.bbox.Diag();
    for (const Segment& seg : after) {
        EXPECT_LE(distanceToSegments(seg.P0(), before), tolerance);
        EXPECT_LE(distanceToSegments(seg.P1(), before), tolerance);
    }
    // The two circles are still closed loops (every boundary vertex has two boundary edges).
    std::map<vcg::Point3d, int> degree;
    for (const Segment& seg : after) {
        ++degree[seg.P0()];
        ++degree[seg.P1()];
    }
    for (const auto& d : degree)
        EXPECT_EQ(d.second, 2);
}

namespace {

// Area of the boundary loops at height z, seen from the axis (they are convex around it).
double holeArea(const TestMesh& m, double z)
{
    double area = 0;
    for (const Segment& seg : boundarySegments(m))
        if (std::abs(seg.P0()[2] - z) < 1e-3 && std::abs(seg.P1()[2] - z) < 1e-3)
            area += 0.5 * std::abs(seg.P0()[0] * seg.P1()[1] - seg.P0()[1] * seg.P1()[0]);
    return area;
}

}  // namespace

// The shaft's centre holes (radius 2) are rims of 1200 short edges on flat end faces
// whose triangles are 7 long: at 90 % the holes must keep their size (a 45-gon still
// has 99.7 % of the circle's area), not close up into a few chords.
TEST(SimplifyProtection, HolesInFlatFacesKeepTheirSize)
{
    TestMesh original, m;
    CadBuilder b;
    revolve(b, shaftProfile(2.0), shaftSpec(1200));
    b.build(original);
    copyMesh(m, original);
    const SimplifyStats s = bestOfTrials(m, targetParams(original.fn / 10));
    ASSERT_TRUE(s.ok) << s.message;
    ASSERT_NEAR(m.fn, original.fn / 10, 2) << s.message;
    for (const double z : {0.0, 101.0}) {
        ASSERT_GT(holeArea(original, z), 0.99 * M_PI * 4) << "z " << z;
        EXPECT_GT(holeArea(m, z), 0.99 * holeArea(original, z)) << "z " << z;
    }
}

TEST(SimplifyProtection, StraightCreasesStayExactlyInPlace)
{
    TestMesh original, m;
    CadBuilder b;
    stripPlate(b, 100, 40, 5, 100);
    b.build(original);
    copyMesh(m, original);
    const std::vector<Segment> before = creaseSegments(original, 30);
    const SimplifyStats s = bestOfTrials(m, targetParams(original.fn / 10));
    ASSERT_TRUE(s.ok) << s.message;
    EXPECT_GT(s.featureEdges, 0);
    const std::vector<Segment> after = creaseSegments(m, 30);
    const double diag = original.bbox.Diag();
    for (const Segment& seg : after) {
        EXPECT_LE(distanceToSegments(seg.P0(), before), 1e-6 * diag);
        EXPECT_LE(distanceToSegments(seg.P1(), before), 1e-6 * diag);
    }
    EXPECT_NEAR(totalLength(after), totalLength(before), 1e-5 * totalLength(before));  // the 12 box edges
}

TEST(SimplifyProtection, CurvedCreasesStaySharpAndClose)
{
    // Without the keyway: where it runs out into the end chamfer the surface is warped,
    // and any coarse triangulation of it has sharp edges of its own.
    TestMesh original, m;
    CadBuilder b;
    RevolveSpec spec = shaftSpec(256);
    spec.keywayHalfAngle = 0;
    revolve(b, shaftProfile(), spec);
    b.build(original);
    copyMesh(m, original);
    const std::vector<Segment> before = creaseSegments(original, 30);
    const SimplifyStats s = bestOfTrials(m, targetParams(original.fn / 8));
    ASSERT_TRUE(s.ok) << s.message;
    const std::vector<Segment> after = creaseSegments(m, 30);
    const double diag = original.bbox.Diag();
    // Merging segments of a circle shortens it by the chord error only.
    EXPECT_NEAR(totalLength(after), totalLength(before), 0.01 * totalLength(before));
    for (const Segment& seg : after)
        EXPECT_LE(distanceToSegments(seg.MidPoint(), before), 2e-3 * diag);
    for (const Segment& seg : before)
        EXPECT_LE(distanceToSegments(seg.MidPoint(), after), 2e-3 * diag);
}

TEST(SimplifyProtection, NoFoldedFacesUnderAggressiveReduction)
{
    for (int variant = 0; variant < 2; ++variant) {
        TestMesh original, m;
        CadBuilder b;
        if (variant == 0)
            revolve(b, shaftProfile(), shaftSpec(300, 3));
        else
            assembly(b, 200);
        b.build(original, variant == 1);
        copyMesh(m, original);
        const SimplifyStats s = bestOfTrials(m, targetParams(original.fn / 10));
        ASSERT_TRUE(s.ok) << s.message;
        EXPECT_EQ(foldedFaces(m, original, 60.0), 0) << "variant " << variant;
        EXPECT_EQ(nonManifoldEdges(m), 0) << "variant " << variant;
    }
}

TEST(SimplifyProtection, PartBordersAreKeptWhenAsked)
{
    // Two coplanar parts sharing a straight border: with keepPartBorders the border must
    // stay a straight line at its place although the plane itself is free to simplify.
    CadBuilder b;
    const int n = 40;
    std::vector<int> grid((n + 1) * (n + 1));
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            grid[y * (n + 1) + x] = b.addPoint(x, y + 0.3 * std::sin(x * 1.7), 0);  // wavy rows
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            b.currentPart = x < n / 2 ? 0 : 1;
            const int a = grid[y * (n + 1) + x], c = grid[(y + 1) * (n + 1) + x + 1];
            b.addTriangle(a, grid[y * (n + 1) + x + 1], c);
            b.addTriangle(a, c, grid[(y + 1) * (n + 1) + x]);
        }
    TestMesh m;
    b.build(m, true);
    const int before = m.fn;
    SimplifyParams params = targetParams(m.fn / 10);
    params.keepPartBorders = true;
    const SimplifyStats s = bestOfTrials(m, params);
    ASSERT_TRUE(s.ok) << s.message;
    EXPECT_LT(m.fn, before / 2);  // the plane did simplify
    EXPECT_GE(s.featureEdges, n);  // the border column
    auto part = cadlod::facePartHandle(m);
    const double border = n / 2;
    auto onBorder = [&](const vcg::Point3f& p) { return std::abs(p[0] - border) < 1e-4; };
    // Border length each part's faces still cover: edges with both ends on x = n/2.
    double borderLength[2] = {0, 0};
    for (auto& f : m.face) {
        if (f.IsD())
            continue;
        ASSERT_TRUE(part[f] == 0 || part[f] == 1);
        for (int j = 0; j < 3; ++j) {
            // Every face lies wholly on its part's side of the border.
            const double x = f.cP(j)[0];
            if (part[f] == 0)
                EXPECT_LE(x, border + 1e-4);
            else
                EXPECT_GE(x, border - 1e-4);
            const vcg::Point3f& p = f.cP(j);
            const vcg::Point3f& q = f.cP((j + 1) % 3);
            if (onBorder(p) && onBorder(q))
                borderLength[part[f]] += vcg::Distance(p, q);
        }
    }
    // The border is still the whole straight line, on both sides: no collapse moved a
    // border vertex off it or opened it (the rows are wavy, so the line's ends are where
    // the wave puts them; its length is the n rows).
    EXPECT_NEAR(borderLength[0], n, 1e-3);
    EXPECT_NEAR(borderLength[1], n, 1e-3);
}

// A body split into one part per face, as KiCad's VRML exports split theirs (one
// IndexedFaceSet per B-rep face, welded on import): a capped cylinder whose side is two
// half-cylinder parts, with a cap part at each end. `colour` gives the half at y < 0 its
// own colour.
static void splitCylinder(TestMesh& m, bool colour)
{
    CadBuilder b;
    RevolveSpec spec;
    spec.segments = 64;
    spec.cylinderRings = 8;
    revolve(b, {{0, 0}, {0, 10}, {30, 10}, {30, 0}}, spec);
    for (std::size_t t = 0; t < b.triangles.size(); ++t) {
        double y = 0, z = 0;
        for (int k : b.triangles[t]) {
            y += b.points[k][1] / 3;
            z += b.points[k][2] / 3;
        }
        b.part[t] = z < 1e-9 ? 0 : z > 30 - 1e-9 ? 3 : y >= 0 ? 1 : 2;
    }
    b.build(m, true);
    auto part = facePartHandle(m);
    for (auto& f : m.face)
        f.C() = colour && part[f] == 2 ? vcg::Color4b(200, 30, 30, 255) : vcg::Color4b(128, 128, 128, 255);
}

TEST(SimplifyProtection, APartBorderIsAFeatureByDefaultOnlyWhereItIsACreaseOrAColourChange)
{
    const int rimEdges = 2 * 64;  // the caps meet the side at 90 degrees
    const int seamEdges = 2 * 8;  // the half-cylinders meet flush, one column each side
    struct Case {
        bool colour, keepPartBorders;
        int features;
    };
    for (const Case c : {Case{false, false, rimEdges}, Case{true, false, rimEdges + seamEdges},
                         Case{false, true, rimEdges + seamEdges}}) {
        TestMesh m;
        splitCylinder(m, c.colour);
        const int before = m.fn;
        SimplifyParams params = targetParams(m.fn / 4);  // the defaults, but for the face target
        if (c.keepPartBorders)
            params.keepPartBorders = true;
        const SimplifyStats s = bestOfTrials(m, params);
        ASSERT_TRUE(s.ok) << s.message;
        EXPECT_EQ(s.featureEdges, c.features) << "colour " << c.colour << ", part borders " << c.keepPartBorders;
        EXPECT_LE(m.fn, before / 4);
        // Every part keeps faces of its own, and its id.
        auto part = facePartHandle(m);
        int faces[4] = {0, 0, 0, 0};
        for (auto& f : m.face)
            if (!f.IsD()) {
                ASSERT_TRUE(part[f] >= 0 && part[f] < 4);
                ++faces[part[f]];
            }
        for (int k = 0; k < 4; ++k)
            EXPECT_GT(faces[k], 0) << "part " << k;
    }
}
