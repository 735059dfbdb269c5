// Symmetric Hausdorff distance between two vcglib triangle meshes, sampled the way
// MeshLab's "Hausdorff Distance" filter does: every vertex of the sampled mesh plus
// area-uniform random points on its faces (fixed seed: same meshes, same numbers), each
// measured to the closest point of the other mesh, found through a bounding-volume tree of
// its faces (triangle_tree.h). Needs no normals, marks or adjacency; deleted elements are
// ignored.
#pragma once

#include "support/run_together.h"
#include "measure/triangle_tree.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

namespace cadlod {

// Chunks a one-sided distance is measured in when it may run on several cores.
inline constexpr std::size_t kHausdorffChunks = 16;

struct HausdorffStats {
    double max = 0.0;   // model units
    double mean = 0.0;
    double rms = 0.0;
    std::size_t samples = 0;
};

struct SymmetricHausdorff {
    HausdorffStats forward;   // samples of A measured to B
    HausdorffStats backward;  // samples of B measured to A
    double diagonal = 0.0;    // bbox diagonal of A
    double max() const { return std::max(forward.max, backward.max); }
    double mean() const
    {
        const std::size_t n = forward.samples + backward.samples;
        return n ? (forward.mean * forward.samples + backward.mean * backward.samples) / n : 0.0;
    }
    double rms() const
    {
        const std::size_t n = forward.samples + backward.samples;
        return n ? std::sqrt((forward.rms * forward.rms * forward.samples +
                              backward.rms * backward.rms * backward.samples) / n)
                 : 0.0;
    }
    double maxFraction() const { return diagonal > 0 ? max() / diagonal : 0.0; }
    double meanFraction() const { return diagonal > 0 ? mean() / diagonal : 0.0; }
};

// Bounding box of the live vertices, in double (null when there are none).
template <class MeshType>
vcg::Box3d liveVertexBox(const MeshType& m)
{
    vcg::Box3d box;
    for (const auto& v : m.vert)
        if (!v.IsD())
            box.Add(vcg::Point3d::Construct(v.cP()));
    return box;
}

template <class MeshType>
double liveDiagonal(const MeshType& m)
{
    const vcg::Box3d box = liveVertexBox(m);
    return box.IsNull() ? 0.0 : box.Diag();
}

namespace detail {

// Closest live face of a mesh to query points (a TriangleTree over its faces).
template <class MeshType>
class ClosestFace
{
public:
    using FaceType = typename MeshType::FaceType;

    explicit ClosestFace(MeshType& m) : faces_(liveFaces(m)), tree_(TriangleTree::of(m, faces_))
    {
        for (const FaceType* f : faces_)
            for (int j = 0; j < 3; ++j)
                bounds_.Add(vcg::Point3d::Construct(f->cP(j)));
        maxDist_ = bounds_.IsNull() ? 1.0 : 4.0 * bounds_.Diag() + 1.0;
    }
    bool empty() const { return faces_.empty(); }
    // The box of the indexed faces.
    const vcg::Box3d& bounds() const { return bounds_; }

    // Closest face (null if none) and the distance to it; points farther than a few
    // diagonals away are reported at that cap.
    FaceType* find(const vcg::Point3d& p, double& distance) const
    {
        const std::int64_t i = tree_.closest(p, maxDist_, distance);
        return i >= 0 ? faces_[std::size_t(i)] : nullptr;
    }

    // The same, searching only for faces closer than `hint` (a face near p, e.g. the one
    // found for the point before): nearby lookups in a row prune most of the tree.
    FaceType* find(const vcg::Point3d& p, double& distance, std::int64_t& hint) const
    {
        if (hint < 0 || std::size_t(hint) >= faces_.size()) {
            hint = tree_.closest(p, maxDist_, distance);
        } else {
            const double bound = tree_.distance(std::size_t(hint), p);
            const std::int64_t i = tree_.closest(p, bound * (1 + 1e-12) + 1e-300, distance);
            if (i >= 0)
                hint = i;
            else
                distance = bound;
        }
        return hint >= 0 ? faces_[std::size_t(hint)] : nullptr;
    }

    using RecentFaces = TriangleTree::RecentHits;

    // Whether some face lies within `radius` of p, trying the recent ones first: true proves
    // that p's distance is at most `radius`.
    bool within(const vcg::Point3d& p, double radius, RecentFaces& recent) const
    {
        return tree_.anyWithin(p, radius, recent) >= 0;
    }

    // The closest of the faces `accept` takes.
    template <class Accept>
    FaceType* find(const vcg::Point3d& p, double& distance, Accept accept) const
    {
        const std::int64_t i =
            tree_.closest(p, maxDist_, distance, [&](std::size_t k) { return accept(*faces_[k]); });
        return i >= 0 ? faces_[std::size_t(i)] : nullptr;
    }

private:
    std::vector<FaceType*> faces_;
    TriangleTree tree_;
    vcg::Box3d bounds_;
    double maxDist_ = 1.0;
};

// Running max, sum and sum of squares of distances.
struct DistanceSums {
    double max = 0.0, sum = 0.0, sumSquares = 0.0;
    std::size_t count = 0;
    void add(double d)
    {
        max = std::max(max, d);
        sum += d;
        sumSquares += d * d;
        ++count;
    }
    // A distance that counts toward the maximum only (see raiseMaxByOtherPoints).
    void raiseMax(double d) { max = std::max(max, d); }
    void add(const DistanceSums& o)
    {
        max = std::max(max, o.max);
        sum += o.sum;
        sumSquares += o.sumSquares;
        count += o.count;
    }
};

}  // namespace detail

// The points a one-sided Hausdorff distance measures on a mesh: every live vertex (first,
// their indices in `vertexIndex`), then area-uniform random points, face by face
// (neighbouring lookups in a row are fast), and with `everyFace` each face's centroid and
// edge midpoints: area-uniform points miss the small faces of a coarse mesh, and one of
// them, spanning a gap, may stand farthest from the other surface.
struct HausdorffSamples {
    std::vector<vcg::Point3d> points;
    std::vector<std::size_t> vertexIndex;  // mesh.vert index of points[i], i < vertexIndex.size()
    std::size_t vertexCount = 0;           // mesh.vert.size()
};

namespace detail {

// The position of (u, v) in [0, 1]² along the Z-order curve, at 16 bits per coordinate.
inline std::uint32_t mortonOrder(double u, double v)
{
    auto spread = [](std::uint32_t x) {
        x = (x | (x << 8)) & 0x00FF00FFu;
        x = (x | (x << 4)) & 0x0F0F0F0Fu;
        x = (x | (x << 2)) & 0x33333333u;
        return (x | (x << 1)) & 0x55555555u;
    };
    auto quantize = [](double t) { return std::uint32_t(std::clamp(t, 0.0, 1.0) * 65535.0); };
    return spread(quantize(u)) | spread(quantize(v)) << 1;
}

// The index std::lower_bound finds in `cumulative` (the faces' cumulative areas) for a pick,
// searched only between two entries of a guide table: for each of as many evenly spaced
// values as there are faces, the first face whose cumulative area reaches it: a binary
// search over every face for every point would take a large share of a small model's LOD
// chain.
class AreaGuide
{
public:
    explicit AreaGuide(const std::vector<double>& cumulative) : cumulative_(cumulative)
    {
        const std::size_t n = cumulative.size();
        total_ = n ? cumulative.back() : 0.0;
        first_.resize(n + 2);
        std::size_t k = 0;  // both rise: one pass (a binary search per entry costs what the picks save)
        for (std::size_t j = 0; j < first_.size(); ++j) {
            while (k < n && cumulative[k] < boundary(j))
                ++k;
            first_[j] = k;
        }
    }

    std::size_t operator()(double pick) const
    {
        const std::size_t last = first_.size() - 2;
        std::size_t j = total_ > 0 ? std::size_t(std::clamp(pick / total_ * double(last), 0.0, double(last))) : 0;
        // The division may round across a boundary: step to the bucket that holds the pick.
        while (j > 0 && boundary(j) > pick)
            --j;
        while (j < last && boundary(j + 1) <= pick)
            ++j;
        const auto begin = cumulative_.begin() + std::ptrdiff_t(first_[j]);
        const auto end = cumulative_.begin() + std::ptrdiff_t(std::min(first_[j + 1] + 1, cumulative_.size()));
        return std::size_t(std::lower_bound(begin, end, pick) - cumulative_.begin());
    }

private:
    double boundary(std::size_t j) const
    {
        const std::size_t last = first_.size() - 2;
        return last ? total_ * double(j) / double(last) : 0.0;
    }

    const std::vector<double>& cumulative_;
    std::vector<std::size_t> first_;  // first_[j]: the first face reaching boundary(j)
    double total_ = 0.0;
};

// `picks` (each with a `face` below `faces` and an `order`) face by face, in face order,
// and along each face by `order`: a counting sort by face, then a short sort per face (a
// sort of all the points at once would cost far more).
template <class Sample>
std::vector<Sample> groupedByFace(const std::vector<Sample>& picks, std::size_t faces)
{
    std::vector<std::size_t> start(faces + 1, 0);
    for (const Sample& s : picks)
        ++start[s.face + 1];
    for (std::size_t f = 0; f < faces; ++f)
        start[f + 1] += start[f];
    std::vector<Sample> grouped(picks.size());
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (const Sample& s : picks)
        grouped[next[s.face]++] = s;
    for (std::size_t f = 0; f < faces; ++f)
        if (start[f + 1] - start[f] > 1)
            std::sort(grouped.begin() + std::ptrdiff_t(start[f]), grouped.begin() + std::ptrdiff_t(start[f + 1]),
                      [](const Sample& x, const Sample& y) { return x.order < y.order; });
    return grouped;
}

// A point on one of a list of faces: its index in the list, the weights (u, v) of the
// face's corners 1 and 2, and its place along the face (groupedByFace).
struct SurfacePick {
    std::size_t face = 0;
    double u = 0, v = 0;
    std::uint32_t order = 0;
};

// `count` area-uniform points on `faces`, face by face and along each face in order
// (neighbouring lookups in a row are fast); a fixed seed gives the same points.
template <class FacePointer>
std::vector<SurfacePick> areaUniformPicks(const std::vector<FacePointer>& faces, std::size_t count, unsigned seed)
{
    std::vector<double> cumulativeArea;
    cumulativeArea.reserve(faces.size());
    double total = 0.0;
    for (const auto* f : faces) {
        const vcg::Point3d a = vcg::Point3d::Construct(f->cP(0));
        total += 0.5 * ((vcg::Point3d::Construct(f->cP(1)) - a) ^ (vcg::Point3d::Construct(f->cP(2)) - a)).Norm();
        cumulativeArea.push_back(total);
    }
    std::vector<SurfacePick> picks;
    if (!(total > 0))
        return picks;
    const AreaGuide faceAt(cumulativeArea);
    picks.reserve(count);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (std::size_t i = 0; i < count; ++i) {
        const double pick = unit(rng) * total;
        const std::size_t k = std::min(faces.size() - 1, faceAt(pick));
        double u = unit(rng), v = unit(rng);
        if (u + v > 1) {
            u = 1 - u;
            v = 1 - v;
        }
        picks.push_back({k, u, v, mortonOrder(u, v)});
    }
    return groupedByFace(picks, faces.size());
}

}  // namespace detail

// `sampled(face)`, when given, picks the faces the random points and the per-face points are
// spread over (the vertices are all taken): a face known to lie on the other surface stands
// at distance 0 all over, and leaving it out puts its share of the points where they tell.
// With `everyFace` and `edgePieces` > 2, each face's edges are also split into that many
// pieces: the largest distance from a coarse mesh to a finer one lies on an edge as often
// as not, next to a corner where a long face leaves the surface under it (a far LOD level's
// 40-unit face stood 3.56 off at a tenth of its edge from a corner, where the random points
// and the midpoints found 3.24: LodChain.LargePiecesStartAsTwoHalvesWithTheSameChainOnTwoThreads).
template <class MeshFrom, class FaceFilter = std::nullptr_t>
HausdorffSamples hausdorffSamples(MeshFrom& from, std::size_t faceSamples, unsigned seed, bool everyFace = false,
                                  const FaceFilter& sampled = nullptr, int edgePieces = 0)
{
    HausdorffSamples result;
    std::vector<vcg::Point3d>& points = result.points;
    result.vertexCount = from.vert.size();
    auto sources = detail::liveFaces(from);
    if constexpr (!std::is_same_v<FaceFilter, std::nullptr_t>)
        sources.erase(std::remove_if(sources.begin(), sources.end(), [&](const auto* f) { return !sampled(*f); }),
                      sources.end());
    if (sources.empty())
        return result;
    for (std::size_t i = 0; i < from.vert.size(); ++i)
        if (!from.vert[i].IsD()) {
            result.vertexIndex.push_back(i);
            points.push_back(vcg::Point3d::Construct(from.vert[i].cP()));
        }
    const std::vector<detail::SurfacePick> picks = detail::areaUniformPicks(sources, faceSamples, seed);
    points.reserve(points.size() + picks.size());
    for (const detail::SurfacePick& sample : picks) {
        const auto* f = sources[sample.face];
        const vcg::Point3d a = vcg::Point3d::Construct(f->cP(0));
        const vcg::Point3d b = vcg::Point3d::Construct(f->cP(1));
        const vcg::Point3d c = vcg::Point3d::Construct(f->cP(2));
        points.push_back(a + (b - a) * sample.u + (c - a) * sample.v);
    }
    if (everyFace)
        for (const auto* f : sources) {
            const vcg::Point3d a = vcg::Point3d::Construct(f->cP(0));
            const vcg::Point3d b = vcg::Point3d::Construct(f->cP(1));
            const vcg::Point3d c = vcg::Point3d::Construct(f->cP(2));
            points.insert(points.end(), {(a + b + c) / 3.0, (a + b) / 2.0, (b + c) / 2.0, (c + a) / 2.0});
            if (edgePieces > 2)
                for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
                    for (int k = 1; k < edgePieces; ++k)
                        if (2 * k != edgePieces)
                            points.push_back(p + (q - p) * (double(k) / edgePieces));
        }
    return result;
}

namespace detail {

// `task(i)` for every i in [begin, end), handed to `together` in halves.
template <class Task>
void splitInHalves(std::size_t begin, std::size_t end, const RunTogether& together, const Task& task)
{
    if (end - begin == 1) {
        task(begin);
        return;
    }
    const std::size_t middle = begin + (end - begin) / 2;
    together([&] { splitInHalves(begin, middle, together, task); }, [&] { splitInHalves(middle, end, together, task); });
}

// Whether points[i] of the range starting at `begin` is one the mean is taken from.
inline bool countsForMean(std::size_t i, std::size_t begin, std::size_t meanEvery)
{
    return (i - begin) % meanEvery == 0;
}

// The first pass over points[begin, end): distances to `closest` of the points the mean is
// taken from (every meanEvery-th; all of them with meanEvery 1), looked up in full, into
// `distance` (same indexing).
template <class MeshTo>
DistanceSums measureMeanPoints(const std::vector<vcg::Point3d>& points, std::size_t begin, std::size_t end,
                               const ClosestFace<MeshTo>& closest, std::vector<double>& distance,
                               std::size_t meanEvery)
{
    DistanceSums sums;
    std::int64_t hint = -1;
    for (std::size_t i = begin; i < end; i += meanEvery) {
        double d = 0.0;
        closest.find(points[i], d, hint);
        distance[i] = d;
        sums.add(d);
    }
    return sums;
}

// Points come in runs that lie close together (a face's points in a row, in order along it:
// hausdorffSamples). No point of a run can raise `max` when some face lies within `max`
// less the run's reach (half its box's diagonal) of the box's centre: each point is at most
// that reach farther from that face. Then one test stands for the run: on a coarse level,
// whose largest distance spans many of level 0's points, most runs.
inline constexpr std::size_t kPointsPerRun = 64;

template <class MeshTo>
bool runWithin(const std::vector<vcg::Point3d>& points, std::size_t begin, std::size_t end,
               const ClosestFace<MeshTo>& closest, double max, typename ClosestFace<MeshTo>::RecentFaces& recent)
{
    vcg::Box3d box;
    for (std::size_t i = begin; i < end; ++i)
        box.Add(points[i]);
    const double reach = 0.5 * box.Diag() * (1 + 1e-9);  // the margin covers rounding
    return reach < max && closest.within(box.Center(), max - reach, recent);
}

// The second pass: the largest distance of the other points that exceeds `floor` (a
// distance the first pass found, so the maximum stays exact), or `floor`. A point is looked
// up in full only when no face lies within the largest distance found so far
// (ClosestFace::within): consecutive points lie near the same face, so most take one
// triangle test, and a run of them that cannot raise it is passed over in one (runWithin).
// Starting from the first pass's largest distance over all the points, and not from zero in
// each chunk, most of them pass that test.
template <class MeshTo>
double raiseMaxByOtherPoints(const std::vector<vcg::Point3d>& points, std::size_t begin, std::size_t end,
                             const ClosestFace<MeshTo>& closest, std::size_t meanEvery, double floor)
{
    double max = floor;
    typename ClosestFace<MeshTo>::RecentFaces recent;
    for (std::size_t run = begin; run < end; run += kPointsPerRun) {
        const std::size_t runEnd = std::min(end, run + kPointsPerRun);
        if (runWithin(points, run, runEnd, closest, max, recent))
            continue;
        for (std::size_t i = run; i < runEnd; ++i) {
            if (countsForMean(i, begin, meanEvery) || closest.within(points[i], max, recent))
                continue;
            double d = 0.0;
            std::int64_t found = -1;
            closest.find(points[i], d, found);
            recent.add(found);
            max = std::max(max, d);
        }
    }
    return max;
}

}  // namespace detail

// Distances from sample points (hausdorffSamples) to a mesh indexed by `closest`
// (detail::ClosestFace, built once when many meshes are measured against the same one).
// `vertexDistances`, when given, receives the distance of every vertex the points were
// taken from (indexed like that mesh's vert; deleted vertices get 0). With `together`, the
// points are measured in kHausdorffChunks fixed chunks, split in halves for it to run at
// once (points far from the other surface take longer to look up, so a few chunks per
// core keep the cores busy); the sums are added in chunk order, so the figures do not
// depend on how they ran. `meanEvery` > 1: the maximum from every point, the mean and RMS
// from every meanEvery-th (`samples` counts those), which are looked up first, in full
// (detail::measureMeanPoints); then vertexDistances holds only theirs. The others are looked
// up only where they could raise the maximum (detail::raiseMaxByOtherPoints).
template <class MeshTo>
HausdorffStats distancesToSurface(const HausdorffSamples& samples, const detail::ClosestFace<MeshTo>& closest,
                                  std::vector<double>* vertexDistances = nullptr, const RunTogether& together = {},
                                  std::size_t meanEvery = 1)
{
    meanEvery = std::max<std::size_t>(meanEvery, 1);
    HausdorffStats s;
    if (vertexDistances)
        vertexDistances->assign(samples.vertexCount, 0.0);
    if (closest.empty() || samples.points.empty())
        return s;

    const std::vector<vcg::Point3d>& points = samples.points;
    std::vector<double> distance(points.size(), 0.0);
    const std::size_t chunks = together ? kHausdorffChunks : 1;
    auto chunkBegin = [&](std::size_t c) { return points.size() * c / chunks; };
    auto forEachChunk = [&](const auto& task) {
        if (together)
            detail::splitInHalves(0, chunks, together, task);
        else
            task(0);
    };
    std::array<detail::DistanceSums, kHausdorffChunks> chunkSums;
    forEachChunk([&](std::size_t c) {
        chunkSums[c] = detail::measureMeanPoints(points, chunkBegin(c), chunkBegin(c + 1), closest, distance, meanEvery);
    });
    detail::DistanceSums sums;
    for (std::size_t c = 0; c < chunks; ++c)
        sums.add(chunkSums[c]);
    if (meanEvery > 1) {
        std::array<double, kHausdorffChunks> chunkMax{};
        const double floor = sums.max;
        forEachChunk([&](std::size_t c) {
            chunkMax[c] =
                detail::raiseMaxByOtherPoints(points, chunkBegin(c), chunkBegin(c + 1), closest, meanEvery, floor);
        });
        for (std::size_t c = 0; c < chunks; ++c)
            sums.raiseMax(chunkMax[c]);
    }
    if (vertexDistances)
        for (std::size_t i = 0; i < samples.vertexIndex.size(); ++i)
            (*vertexDistances)[samples.vertexIndex[i]] = distance[i];

    s.max = sums.max;
    s.samples = sums.count;
    s.mean = s.samples ? sums.sum / double(s.samples) : 0.0;
    s.rms = s.samples ? std::sqrt(sums.sumSquares / double(s.samples)) : 0.0;
    return s;
}

// Distances from `faceSamples` area-uniform points on `from` (plus its vertices) to the
// mesh `closest` indexes; see distancesToSurface.
template <class MeshFrom, class MeshTo>
HausdorffStats oneSidedHausdorff(MeshFrom& from, detail::ClosestFace<MeshTo>& closest, std::size_t faceSamples,
                                 unsigned seed = 1, std::vector<double>* vertexDistances = nullptr,
                                 const RunTogether& together = {}, std::size_t meanEvery = 1, bool everyFace = false)
{
    return distancesToSurface(hausdorffSamples(from, faceSamples, seed, everyFace), closest, vertexDistances, together,
                              meanEvery);
}

template <class MeshFrom, class MeshTo>
HausdorffStats oneSidedHausdorff(MeshFrom& from, MeshTo& to, std::size_t faceSamples, unsigned seed = 1,
                                 std::vector<double>* vertexDistances = nullptr, const RunTogether& together = {})
{
    detail::ClosestFace<MeshTo> closest(to);
    return oneSidedHausdorff(from, closest, faceSamples, seed, vertexDistances, together);
}

// Both directions; fractions are of A's bounding-box diagonal.
template <class MeshA, class MeshB>
SymmetricHausdorff symmetricHausdorff(MeshA& a, MeshB& b, std::size_t faceSamplesPerSide)
{
    SymmetricHausdorff h;
    h.forward = oneSidedHausdorff(a, b, faceSamplesPerSide, 1);
    h.backward = oneSidedHausdorff(b, a, faceSamplesPerSide, 2);
    h.diagonal = liveDiagonal(a);
    return h;
}

}  // namespace cadlod
