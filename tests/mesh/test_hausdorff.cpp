// The closest-face lookup behind every Hausdorff figure (reports, LOD errors, tests):
// it must agree with a brute-force search everywhere, including points a float step
// inside the far sides of the search grid's box, which float rounding maps one cell past
// the end of vcglib's grid (an assertion, or an out-of-bounds read with NDEBUG: found
// when a simplified mesh stuck out of the original by just the grid's margin).
#include "measure/hausdorff.h"
#include "test_mesh.h"

#include <vcg/space/distance3.h>

#include <gtest/gtest.h>

#include <vcg/complex/algorithms/create/platonic.h>

#include <cmath>
#include <limits>
#include <random>

using namespace cadlod;
using cadlod::test::TestMesh;
using cadlod::test::addFaces;

namespace {

// A sphere around the origin: there a float step at the box's far side is small against
// the box's size, which is when the division by the cell size rounds up to the end.
void offsetSphere(TestMesh& m, float scale = 7.3f)
{
    vcg::tri::Sphere(m, 2);
    for (auto& v : m.vert)
        v.P() = v.P() * scale + vcg::Point3f(0.25f, -0.5f, 0.125f);
    vcg::tri::UpdateBounding<TestMesh>::Box(m);
}

// vcglib's own point-triangle distance over every face: an independent oracle.
double bruteForce(TestMesh& m, const vcg::Point3d& p)
{
    double best = std::numeric_limits<double>::max();
    for (auto& f : m.face) {
        const vcg::Triangle3<double> t(vcg::Point3d::Construct(f.cP(0)), vcg::Point3d::Construct(f.cP(1)),
                                       vcg::Point3d::Construct(f.cP(2)));
        double d = 0;
        vcg::Point3d closest;
        vcg::TrianglePointDistance(t, p, d, closest);
        best = std::min(best, d);
    }
    return best;
}

// Points a few float steps inside the far corner and sides of a box, and on them.
std::vector<vcg::Point3d> pointsAtTheEdgeOf(const vcg::Box3f& box)
{
    std::vector<vcg::Point3d> points;
    for (int steps = 0; steps < 4; ++steps) {
        vcg::Point3f p = box.max;
        for (int k = 0; k < steps; ++k)
            for (int j = 0; j < 3; ++j)
                p[j] = std::nextafter(p[j], -std::numeric_limits<float>::infinity());
        points.push_back(vcg::Point3d::Construct(p));
        points.push_back(vcg::Point3d(p[0], box.Center()[1], box.Center()[2]));
        points.push_back(vcg::Point3d(box.Center()[0], p[1], box.Center()[2]));
        points.push_back(vcg::Point3d(box.Center()[0], box.Center()[1], p[2]));
    }
    return points;
}

// The offset sphere, and a copy of it whose every vertex is moved away from the centre by the
// factor `scale(vertex - centre)`.
template <class Scale>
void sphereAndScaledCopy(TestMesh& sphere, TestMesh& copy, Scale scale)
{
    offsetSphere(sphere);
    offsetSphere(copy);
    const vcg::Point3f centre = sphere.bbox.Center();
    for (auto& v : copy.vert)
        v.P() = centre + (v.P() - centre) * scale(v.P() - centre);
}

}  // namespace

TEST(ClosestFace, AgreesWithBruteForceUpToAndBeyondTheMeshBox)
{
    for (int i = 0; i < 60; ++i) {  // many sizes: whether the division rounds up depends on them
        TestMesh m;
        offsetSphere(m, 1.0f + 0.37f * float(i));
        detail::ClosestFace<TestMesh> closest(m);
        // The edges of the faces' box, and of the one vcglib's grid would build (grown by
        // diagonal / face count).
        std::vector<vcg::Point3d> points = pointsAtTheEdgeOf(vcg::Box3f::Construct(closest.bounds()));
        vcg::Box3f vcgBox = m.bbox;
        vcgBox.Offset(m.bbox.Diag() / float(m.fn));
        for (const vcg::Point3d& p : pointsAtTheEdgeOf(vcgBox))
            points.push_back(p);
        std::mt19937 rng(7 + i);
        const vcg::Point3d c = vcg::Point3d::Construct(m.bbox.Center());
        std::uniform_real_distribution<double> spread(-1.5 * m.bbox.Diag(), 1.5 * m.bbox.Diag());
        for (int k = 0; k < 20; ++k)
            points.push_back(c + vcg::Point3d(spread(rng), spread(rng), spread(rng)));
        for (const vcg::Point3d& p : points) {
            double d = -1;
            ASSERT_NE(closest.find(p, d), nullptr);
            ASSERT_NEAR(d, bruteForce(m, p), 1e-4 * m.bbox.Diag()) << p[0] << " " << p[1] << " " << p[2];
        }
    }
}

TEST(ClosestFace, HausdorffOfAMeshJustLargerThanTheOtherIsItsOffset)
{
    TestMesh inner, outer;
    sphereAndScaledCopy(inner, outer, [](const vcg::Point3f&) { return 1.001f; });
    const HausdorffStats h = oneSidedHausdorff(outer, inner, 20000);
    EXPECT_NEAR(h.max, 0.001 * 7.3, 1e-4);
}

TEST(Hausdorff, MeasuredInChunksOnTwoThreadsItGivesTheSameFigures)
{
    TestMesh inner, outer;
    sphereAndScaledCopy(inner, outer, [](const vcg::Point3f& fromCentre) {
        return 1.0f + 0.01f * std::abs(fromCentre[0]) / 7.3f;  // uneven offset
    });
    std::vector<double> serialVertices, threadedVertices, wholeVertices;
    const HausdorffStats whole = oneSidedHausdorff(outer, inner, 20000, 1, &wholeVertices);
    const HausdorffStats serial = oneSidedHausdorff(outer, inner, 20000, 1, &serialVertices, runInSequence);
    const HausdorffStats threaded = oneSidedHausdorff(outer, inner, 20000, 1, &threadedVertices, runOnTwoThreads);
    // Chunks added in a fixed order: bit for bit the same however they ran.
    EXPECT_EQ(serial.max, threaded.max);
    EXPECT_EQ(serial.mean, threaded.mean);
    EXPECT_EQ(serial.rms, threaded.rms);
    EXPECT_EQ(serialVertices, threadedVertices);
    // And the same points as one pass: the same largest distance, sums up to rounding.
    EXPECT_EQ(whole.samples, threaded.samples);
    EXPECT_EQ(whole.max, threaded.max);
    EXPECT_NEAR(whole.mean, threaded.mean, 1e-12 * whole.mean);
    EXPECT_EQ(wholeVertices, threadedVertices);
    EXPECT_GT(threaded.max, 0.005 * 7.3);
}

TEST(ClosestFace, WithinAgreesWithBruteForce)
{
    TestMesh m;
    offsetSphere(m);
    detail::ClosestFace<TestMesh> closest(m);
    std::mt19937 rng(11);
    const vcg::Point3d c = vcg::Point3d::Construct(m.bbox.Center());
    std::uniform_real_distribution<double> spread(-m.bbox.Diag(), m.bbox.Diag());
    int inside = 0, outside = 0;
    // The faces found for earlier points and radii are tried first: they must not let a
    // smaller radius pass.
    detail::ClosestFace<TestMesh>::RecentFaces recent;
    for (int k = 0; k < 400; ++k) {
        const vcg::Point3d p = c + vcg::Point3d(spread(rng), spread(rng), spread(rng));
        const double d = bruteForce(m, p);
        for (const double radius : {2.0 * d, 1.001 * d, 0.999 * d, 0.5 * d}) {
            const bool within = closest.within(p, radius, recent);
            EXPECT_EQ(within, radius >= d) << "point " << k << " radius " << radius << " distance " << d;
            (within ? inside : outside)++;
        }
    }
    EXPECT_GT(inside, 0);
    EXPECT_GT(outside, 0);
}

// The chain measures its levels looking up in full only the points that could raise the
// largest distance (and every meanEvery-th, for the mean): the largest distance must be the
// one every point looked up in full finds, on two threads too.
TEST(Hausdorff, LookingUpOnlyWhatCouldRaiseTheMaximumKeepsItExact)
{
    TestMesh inner, outer;
    sphereAndScaledCopy(inner, outer, [](const vcg::Point3f& fromCentre) {
        return 1.0f + 0.02f * std::abs(fromCentre[1] * fromCentre[2]) / (7.3f * 7.3f);  // uneven offset
    });
    for (const auto& [from, to] : {std::pair<TestMesh*, TestMesh*>{&outer, &inner}, {&inner, &outer}}) {
        detail::ClosestFace<TestMesh> closest(*to);
        const HausdorffSamples samples = hausdorffSamples(*from, 30000, 3);
        const HausdorffStats full = distancesToSurface(samples, closest);
        for (const std::size_t every : {2, 8, 32}) {
            const HausdorffStats fast = distancesToSurface(samples, closest, nullptr, {}, every);
            const HausdorffStats threaded = distancesToSurface(samples, closest, nullptr, runOnTwoThreads, every);
            EXPECT_EQ(fast.max, full.max) << every;
            EXPECT_EQ(threaded.max, full.max) << every;
            EXPECT_EQ(fast.samples, (samples.points.size() + every - 1) / every);
            EXPECT_NEAR(fast.mean, full.mean, 0.1 * full.mean) << every;  // a subset's mean
        }
        EXPECT_GT(full.max, 0.003 * 7.3);
    }
}

// A face filter spreads the random points and each face's centroid and edge midpoints over
// the faces it picks only; every vertex is still taken.
TEST(Hausdorff, SamplesGoOnlyToTheFacesTheFilterPicks)
{
    TestMesh sphere;
    offsetSphere(sphere);
    const float middle = sphere.bbox.Center()[2];
    auto above = [&](const auto& f) {
        return f.cP(0)[2] > middle && f.cP(1)[2] > middle && f.cP(2)[2] > middle;
    };
    std::size_t picked = 0;
    for (const auto& f : sphere.face)
        picked += above(f) ? 1 : 0;
    ASSERT_GT(picked, 0u);
    ASSERT_LT(picked, std::size_t(sphere.fn));
    const HausdorffSamples samples = hausdorffSamples(sphere, 5000, 3, true, above);
    ASSERT_EQ(samples.vertexIndex.size(), std::size_t(sphere.vn));
    EXPECT_EQ(samples.points.size(), std::size_t(sphere.vn) + 5000 + 4 * picked);
    for (std::size_t i = samples.vertexIndex.size(); i < samples.points.size(); ++i)
        ASSERT_GT(samples.points[i][2], middle) << i;
}

// The random points come face by face (lookups in a row then start near the face found
// last), in the order of the faces, and each face's share is its area's, as drawn.
TEST(Hausdorff, RandomPointsComeFaceByFaceInProportionToArea)
{
    TestMesh sphere;
    offsetSphere(sphere);
    const std::size_t n = 200000;
    const HausdorffSamples samples = hausdorffSamples(sphere, n, 9);
    ASSERT_EQ(samples.points.size(), std::size_t(sphere.vn) + n);
    // The face each point lies on: the closest, with the point at distance 0.
    detail::ClosestFace<TestMesh> closest(sphere);
    std::vector<std::size_t> count(sphere.face.size(), 0);
    std::size_t previous = 0, runs = 0;
    for (std::size_t i = samples.vertexIndex.size(); i < samples.points.size(); ++i) {
        double d = -1;
        const auto* f = closest.find(samples.points[i], d);
        ASSERT_NE(f, nullptr);
        ASSERT_LT(d, 1e-5);
        const std::size_t face = std::size_t(f - &sphere.face[0]);
        ++count[face];
        if (face != previous)
            ++runs;
        previous = face;
    }
    // About one run of points per face, not one per point (a point on an edge may be found
    // on the face beside it).
    EXPECT_LE(runs, 2 * sphere.face.size());
    double total = 0;
    for (const auto& f : sphere.face)
        total += vcg::DoubleArea(f) / 2;
    for (std::size_t k = 0; k < sphere.face.size(); ++k) {
        const double expected = double(n) * vcg::DoubleArea(sphere.face[k]) / 2 / total;
        EXPECT_NEAR(double(count[k]), expected, 6 * std::sqrt(expected) + 2) << k;
    }
}

// The area-weighted pick of a face finds what a binary search over all the faces finds, for
// picks on the guide's bucket boundaries, on faces' cumulative areas, and past the end, with
// faces of zero area and of areas a million times apart.
TEST(Hausdorff, AreaGuidePicksTheFaceABinarySearchPicks)
{
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const std::size_t n : {1, 2, 3, 7, 100, 1000}) {
        std::vector<double> cumulative;
        double total = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const double r = unit(rng);
            total += r < 0.1 ? 0.0 : (r < 0.2 ? 1e6 * r : r);
            cumulative.push_back(total);
        }
        const detail::AreaGuide guide(cumulative);
        std::vector<double> picks{0.0, total, std::nextafter(total, 0.0), 1.5 * total};
        for (std::size_t j = 0; j <= n; ++j)
            for (const double x : {total * double(j) / double(n), std::nextafter(total * double(j) / double(n), 0.0),
                                   std::nextafter(total * double(j) / double(n), 2 * total)})
                picks.push_back(x);
        for (const double c : cumulative)
            picks.insert(picks.end(), {c, std::nextafter(c, 0.0), std::nextafter(c, 2 * total)});
        for (int k = 0; k < 2000; ++k)
            picks.push_back(unit(rng) * total);
        for (const double pick : picks) {
            const std::size_t expected =
                std::size_t(std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
            ASSERT_EQ(guide(pick), expected) << "n " << n << " pick " << pick << " total " << total;
        }
    }
}

// A long face whose surface underneath has a gap near one corner: the face stands off the
// other surface most at a point of its edge next to that corner, where neither its
// vertices, its centroid nor its edge midpoints lie. Points splitting each edge in eight
// find it.
TEST(Hausdorff, EdgePiecesFindTheLargestDistanceNextToACorner)
{
    TestMesh face, under;
    addFaces(face, {{0, 0, 0}, {40, 0, 0}, {0, 15, 0}}, {{0, 1, 2}});
    // The same face without the wedge from (33, 0) and (37, 0) to its third corner.
    addFaces(under, {{0, 0, 0}, {33, 0, 0}, {37, 0, 0}, {40, 0, 0}, {0, 15, 0}}, {{0, 1, 4}, {2, 3, 4}});
    const detail::ClosestFace<TestMesh> closest(under);

    double dense = 0;  // along the edge (0,0)-(40,0), every 0.01
    for (int i = 0; i <= 4000; ++i) {
        double d = 0;
        closest.find(vcg::Point3d(i * 0.01, 0, 0), d);
        dense = std::max(dense, d);
    }
    ASSERT_GT(dense, 0.5);

    const HausdorffStats without = distancesToSurface(hausdorffSamples(face, 0, 1, true), closest);
    const HausdorffStats with = distancesToSurface(hausdorffSamples(face, 0, 1, true, nullptr, 8), closest);
    EXPECT_LT(without.max, 0.1 * dense);  // every vertex, the centroid and the midpoints lie on it
    EXPECT_GE(with.max, 0.6 * dense);     // (35, 0, 0), the seventh of eight pieces: 0.75 of 1.09
    EXPECT_LE(with.max, dense + 1e-9);
}

// A run of points is passed over in one test only when none of them could raise the largest
// distance: checked against vcglib's point-triangle distance on runs of points scattered
// around points of a sphere, some with one point standing off it, for maxima below and above
// their distances.
TEST(Hausdorff, ARunOfPointsIsPassedOverOnlyWhenNoneCouldRaiseTheMaximum)
{
    TestMesh m;
    offsetSphere(m);
    const detail::ClosestFace<TestMesh> closest(m);
    const HausdorffSamples onSphere = hausdorffSamples(m, 200, 5);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> scatter(-0.05, 0.05), lift(0.0, 0.4), chance(0.0, 1.0);
    int passedOver = 0, lookedAt = 0;
    for (const vcg::Point3d& centre : onSphere.points) {
        std::vector<vcg::Point3d> run;
        for (int i = 0; i < 64; ++i)
            run.push_back(centre + vcg::Point3d(scatter(rng), scatter(rng), scatter(rng)));
        if (chance(rng) < 0.3)  // one point stands off the surface
            run[std::size_t(rng() % 64)] += vcg::Point3d(lift(rng), lift(rng), lift(rng));
        double farthest = 0;
        for (const vcg::Point3d& p : run)
            farthest = std::max(farthest, bruteForce(m, p));
        const double max = farthest * (0.5 + chance(rng));
        detail::ClosestFace<TestMesh>::RecentFaces recent;
        if (detail::runWithin(run, 0, run.size(), closest, max, recent)) {
            ++passedOver;
            EXPECT_LE(farthest, max * (1 + 1e-9)) << centre[0] << " " << centre[1] << " " << centre[2];
        } else {
            ++lookedAt;
        }
    }
    EXPECT_GT(passedOver, 10);  // the test sees both outcomes
    EXPECT_GT(lookedAt, 10);
}
