// A LOD chain planned by screen-space error (design.md §5): what a VR engine needs, from
// the distance where the model fills the viewport out to where it is a few pixels high.
//
// Level k is meant for the distance d_k = d_first * ratio^(k-1), from d_first = d_fill / 32
// (d_fill: where the model's diagonal spans the viewport height; a viewer may come closer,
// and an over-tessellated CAD part loses most of its triangles there already). A distance
// whose mesh is less than 10 % lighter than the last level's adds no level. Its budget is
// the error that projects to the pixel error there. Halfway between two planned distances
// (a factor of √ratio) the model is copied too; the copy becomes a level only where the
// next level's measured error overshoots, landing more than the ratio beyond the last
// level's, so that the chain has no gap wider than the ratio where it can fill one.
// Collapse sessions run with that budget as their maximum error, one per piece of the
// model (collapse_buckets.h: whole connected components, side by side), each for the whole
// chain (the quadrics carry the whole history, so errors do not restart at each level);
// there features (part borders too, when they are kept) and whole small components give
// way as soon as breaking them costs less than the budget (simplify.h). Collapses are
// ranked by their quadric error, but held to the budget by the distance they open too
// (far_field.h: from level 0's points to the faces they make, and back from those faces to
// level 0): how far the quadric error is from that distance varies from one collapse to
// the next, and a bound on the quadric error alone had to allow for the worst of them. From
// where the model is kFarFieldPixels high, the pieces are in the far field: operations are
// ranked by that distance too, since the quadrics' error no longer tells how far a few
// hundred faces stand from thousands. The pieces together are then taken as level k and
// measured against level 0 (symmetric Hausdorff) while the sessions go on to the next level
// (the caller's RunTogether may run both at once); the ratio between the measured error
// and the largest distance opened steers the distance bound from the level after next, so
// an estimate that falls short of what a viewer sees is corrected level by level.
// Where the model is `proxyPixels` high, a proxy is made: one axis-aligned box per remaining connected component (a box per part): the box of its
// vertices or of its surface without what sticks out (a pin, a leg), whichever measures
// closer. Collapse levels go on beyond it only while the box's measured error is still
// above the budget and they are heavier than the box (a jack's deep socket keeps its box
// far off). Where the model is a couple of pixels high, a tetrahedron in each box follows
// (inscribed, or in the box grown about its centre, whichever measures closest), and last
// one tetrahedron for the whole model.
//
// Every level's range comes from its measured error (lod_plan.h): it is drawn from where
// that error projects to the pixel error, until the next level's does. The last level is
// drawn for ever unless `cullPixels` is set.
#pragma once

#include "lod/collapse_buckets.h"
#include "mesh/components.h"
#include "lod/lod_builder.h"
#include "simplify/non_manifold_split.h"
#include "support/run_together.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <iterator>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace cadlod {

struct LodChainOptions {
    ViewParams view;                  // camera and pixel error
    double distanceRatio = 2.0;       // between the distances of consecutive levels
    double proxyPixels = 8.0;         // the box proxy serves from where the model is this many px high
    double cullPixels = 0.0;          // > 0: not drawn once the model is smaller than this many px
    std::size_t hausdorffSamples = 0; // face samples per side; 0: as many as level-0 faces, 100 000 to 500 000
    SimplifyParams simplify;          // placement and protection; the budget is set per level
    int setId = 1;
    RunTogether runTogether;          // measuring a level beside the next collapses; empty: in sequence
};

// The box proxy is tried with these shares of each component's area left out at both ends
// of each axis (trimmedBox), and the one with the smallest measured error is kept: 0 is the
// box of the component's vertices.
inline constexpr double kBoxTrims[] = {0.0, 0.02, 0.05, 0.1};
// The least compactness a collapse of a chain level may leave a face with (the simplifier's
// shape guard, simplify_params.h), before the far field, where a session held to its
// distance is judged by the distance alone (cad_edge_collapse.h).
inline constexpr double kChainMinCompactness = 0.05;
// The share of the simplifier's feature penalty that chain levels use (see buildLodChain).
inline constexpr double kChainFeaturePenaltyShare = 0.5;
// Where the model is this many pixels high (its diagonal), the pieces go into the far field
// (far_field.h): from there on they rank operations by the distance they open and are held
// to the budget by it. Tried at 16 to 256 on the chain bench (docs/benchmarks.md).
inline constexpr double kFarFieldPixels = 64.0;
// Where the model is this many pixels high, a tetrahedron per component replaces its box.
inline constexpr double kTetrahedronPixels = 2.0;
// The tetrahedra are tried inscribed in their boxes and in the boxes grown by these factors
// about their centres, and the one with the smallest measured error is kept. Inscribed in a
// cube, a tetrahedron leaves four corners a third of the diagonal off; grown 1.5 times, those
// corners and its own vertices sticking out stand a quarter of the diagonal off each.
inline constexpr double kTetrahedronScales[] = {1.0, 1.25, 1.5};
// Switch-in distance of the last level when the model is never culled.
inline constexpr double kNeverCulled = 1e30;
// The first level is planned this many times closer than where the model fills the view.
inline constexpr double kCloseUpFactor = 32.0;
// A coarse level is sampled with at most this many points per face (besides its vertices)
// when measured against level 0: its points stand far from level 0, where each lookup is
// slow, and a few dozen per face find the largest distance of a flat triangle to the
// surface it replaces (MeshLab's Hausdorff filter samples one point per vertex).
inline constexpr std::size_t kBackwardSamplesPerFace = 256;
// ...but never fewer than this many in all: a level of a few dozen faces, each large, would
// otherwise be sampled too sparsely to find its largest distance within the 5 % that an
// independent re-measurement may find beyond it.
inline constexpr std::size_t kMinBackwardSamples = 32768;
// ...and at most this many (or as many as level 0 has, where that is more, or what the
// caller asked for). A coarse level's largest distance may stand over a narrow strip of one
// large face, which random points find only by luck: 100 000 points missed one of a robot's
// levels by 22 % where a million found it (chain_bench --verify).
inline constexpr std::size_t kBackwardSamplesCap = 400000;

namespace detail {

inline double tanHalfFov(const ViewParams& view) { return std::tan(0.5 * view.fovYDegrees * M_PI / 180.0); }

// The geometric error that projects to the pixel error at distance d.
inline double errorBudgetAt(double d, const ViewParams& view)
{
    return view.pixelThreshold * 2.0 * d * tanHalfFov(view) / view.viewportHeightPx;
}

// Where a length `size` spans `pixels` pixels of the viewport height.
inline double distanceForPixels(double size, double pixels, const ViewParams& view)
{
    return size * view.viewportHeightPx / (2.0 * tanHalfFov(view) * pixels);
}

// What a proxy is made from: a box, and the part and colour of the faces it stands for.
struct ProxyBox {
    vcg::Box3d box;
    int part = 0;
    vcg::Color4b color = vcg::Color4b(vcg::Color4b::Gray);

    bool operator==(const ProxyBox& o) const
    {
        return box.min == o.box.min && box.max == o.box.max && part == o.part && color == o.color;
    }
};

// The part and colour of component `c`'s first face, with the box `box`.
template <class MeshType>
ProxyBox proxyBoxOf(MeshType& m, const Component<MeshType>& c, const vcg::Box3d& box)
{
    ProxyBox b;
    b.box = box;
    const auto* first = c.faces.front();
    if (hasParts(m))
        b.part = facePartHandle(m)[first];
    if (vcg::tri::HasPerFaceColor(m))
        b.color = first->cC();
    return b;
}

// `boxes`, each grown by `factor` about its centre.
inline std::vector<ProxyBox> grownBoxes(std::vector<ProxyBox> boxes, double factor)
{
    for (ProxyBox& b : boxes) {
        const vcg::Point3d c = b.box.Center(), half = b.box.Dim() * (0.5 * factor);
        b.box = vcg::Box3d(c - half, c + half);
    }
    return boxes;
}

// Replaces `m` by one closed shape per box, `append(m, box, part, colour)` making it.
template <class MeshType, class AppendShape>
void replaceByProxies(MeshType& m, const std::vector<ProxyBox>& boxes, const AppendShape& append)
{
    deleteEverything(m);
    for (const ProxyBox& b : boxes)
        append(m, b.box, b.part, b.color);
}

// The box of component `c`'s surface without its outermost `share` of area at either end of
// each axis. A pin or a leg sticking out of a body holds little of the area, and the box of
// the rest stands closer for the body: the box of all its vertices is off by the pin's length
// over the whole bottom face. Each face counts as its corners and its centroid, a quarter of
// its area each. share 0, or nothing left: the box of its vertices.
template <class MeshType>
vcg::Box3d trimmedBox(const Component<MeshType>& c, double share)
{
    if (!(share > 0))
        return c.box;
    struct Weighted {
        vcg::Point3d p;
        double w;
    };
    std::vector<Weighted> points;
    points.reserve(4 * c.faces.size());
    double total = 0.0;
    for (const auto* f : c.faces) {
        const vcg::Point3d a = vcg::Point3d::Construct(f->cP(0)), b = vcg::Point3d::Construct(f->cP(1)),
                           d = vcg::Point3d::Construct(f->cP(2));
        const double w = 0.125 * ((b - a) ^ (d - a)).Norm();
        for (const vcg::Point3d& p : {a, b, d, (a + b + d) / 3.0})
            points.push_back({p, w});
        total += 4.0 * w;
    }
    if (!(total > 0))
        return c.box;
    vcg::Box3d box;
    for (int axis = 0; axis < 3; ++axis) {
        std::sort(points.begin(), points.end(),
                  [axis](const Weighted& x, const Weighted& y) { return x.p[axis] < y.p[axis]; });
        double below = 0.0;
        std::size_t lo = 0;
        while (lo + 1 < points.size() && below + points[lo].w <= share * total)
            below += points[lo++].w;
        double above = 0.0;
        std::size_t hi = points.size() - 1;
        while (hi > lo && above + points[hi].w <= share * total)
            above += points[hi--].w;
        box.min[axis] = points[lo].p[axis];
        box.max[axis] = points[hi].p[axis];
    }
    return box;
}

// The connected components of `m` at least `minSize` large; the smaller ones, which no proxy
// stands for, are counted in `stats`.
template <class MeshType>
std::vector<Component<MeshType>> componentsToKeep(MeshType& m, double minSize, SimplifyStats& stats)
{
    vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    std::vector<Component<MeshType>> kept;
    for (Component<MeshType>& c : connectedComponents(m)) {
        if (c.size() < minSize) {
            ++stats.removedComponents;
            stats.largestRemovedComponent = std::max(stats.largestRemovedComponent, c.size());
            continue;
        }
        kept.push_back(std::move(c));
    }
    return kept;
}

// One box per component of `m` in `kept`, trimmed by `trim` (see trimmedBox), with the
// component's part and colour.
template <class MeshType>
std::vector<ProxyBox> proxyBoxes(MeshType& m, const std::vector<Component<MeshType>>& kept, double trim)
{
    std::vector<ProxyBox> boxes;
    for (const Component<MeshType>& c : kept)
        boxes.push_back(proxyBoxOf(m, c, trimmedBox(c, trim)));
    return boxes;
}

// The box of each connected component of `m` at least `minSize` large, with its part and
// colour; the smaller ones, which no proxy stands for, are counted in `stats`.
template <class MeshType>
std::vector<ProxyBox> boxPerComponent(MeshType& m, double minSize, SimplifyStats& stats)
{
    return proxyBoxes(m, componentsToKeep(m, minSize, stats), 0.0);
}

// The box of all of a model's live vertices, with the part and colour of its largest
// component: what one proxy for the whole model is made from (null box: no faces).
template <class MeshType>
ProxyBox modelBox(MeshType& m)
{
    vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    const auto components = connectedComponents(m);
    return components.empty() ? ProxyBox() : proxyBoxOf(m, components.back(), liveVertexBox(m));
}

}  // namespace detail

// `newLevel(k)` returns an empty mesh for level k (k >= 1), as for buildLodSet; `working`
// is an empty mesh with what cadlod::simplify needs, left in an unspecified state.
// `newScratch` returns more such meshes, for the pieces of the model simplified side by
// side (collapse_buckets.h); they may go once the call returns. Empty: default-constructed
// meshes of the chain's own (enough where MeshType has no optional components to enable).
// The result has the same form as buildLodSet's; result.steps holds, per kept level, the
// collapse statistics up to it, whose `relaxed` lines say what gave way since the level
// before (and, for a large piece, that it started as two halves).
template <class MeshType>
LodSetResult buildLodChain(MeshType& original, MeshType& working, const LodChainOptions& options,
                           const std::function<MeshType&(int)>& newLevel, vcg::CallBackPos* progress = nullptr,
                           std::function<MeshType&()> newScratch = {})
{
    std::deque<MeshType> ownScratch;
    if (!newScratch)
        newScratch = [&]() -> MeshType& { return ownScratch.emplace_back(); };
    LodSetResult result;
    const ViewParams& view = options.view;
    if (!(view.fovYDegrees > 0 && view.fovYDegrees < 180) || !(view.viewportHeightPx >= 1) ||
        !(view.pixelThreshold > 0) || !(options.distanceRatio > 1) || !(options.proxyPixels > 0)) {
        result.error = "the field of view must be in (0, 180) degrees, the viewport at least 1 px, the pixel error "
                       "and the proxy size positive, and the distance ratio above 1";
        return result;
    }

    LodLevel level0;
    level0.setId = options.setId;
    level0.faces = original.fn;
    const vcg::Box3d box = liveVertexBox(original);
    if (box.IsNull() || original.fn == 0) {
        result.error = "the mesh has no faces";
        return result;
    }
    level0.center = {box.Center()[0], box.Center()[1], box.Center()[2]};
    result.modelSize = box.Diag();
    result.levels.push_back(level0);
    result.compactness.push_back(meshCompactness(original));
    std::vector<MeshType*> meshes{&original};

    const std::size_t samples =
        options.hausdorffSamples ? options.hausdorffSamples : std::clamp<std::size_t>(std::size_t(original.fn), 100000, 500000);
    const RunTogether together = options.runTogether ? options.runTogether : RunTogether(runInSequence);
    // Level 0's points and index are made beside the first collapses, before anything is
    // measured.
    DistanceToLevelZero<MeshType> distanceToOriginal(original, samples, result.modelSize, together);
    struct Measures {
        SymmetricHausdorff distance;
        CompactnessStats compactness;
    };
    const std::size_t backwardCap = options.hausdorffSamples ? samples : std::max(samples, kBackwardSamplesCap);
    auto measure = [&](MeshType& mesh) {
        Measures m;
        const std::size_t backwardSamples =
            std::min(backwardCap, std::max(kMinBackwardSamples, kBackwardSamplesPerFace * std::size_t(mesh.fn)));
        together([&] { m.distance = distanceToOriginal(mesh, backwardSamples); },
                 [&] { m.compactness = meshCompactness(mesh); });
        return m;
    };
    auto addLevel = [&](MeshType& mesh, const SimplifyStats& stats, const Measures& measured) {
        const SymmetricHausdorff& h = measured.distance;
        LodLevel level = level0;
        level.level = int(result.levels.size());
        level.faces = mesh.fn;
        level.reduction = 1.0 - double(mesh.fn) / original.fn;
        level.hausdorffMax = h.max();
        level.hausdorffMean = h.mean();
        result.levels.push_back(level);
        result.distance.push_back(h);
        result.compactness.push_back(measured.compactness);
        result.steps.push_back(stats);
        meshes.push_back(&mesh);
    };

    // The model, dealt into pieces that collapse sessions simplify side by side, level
    // after level (the quadrics carry the whole history).
    detail::copyWithParts(working, original);
    vcg::tri::Allocator<MeshType>::CompactEveryVector(working);
    SimplifyParams params = options.simplify;
    params.targetFaces = 0;
    params.reductionPerc = 0.0;
    params.maxError = 1.0;  // set per level below; here only to pass validation
    // Each level is bound by its measured error where it is drawn, so a face of a thin part
    // that ends up nearer the part's far side is within that error of it. The input-surface
    // check (input_surface.h) would only keep thin parts (a chip's leads) heavy in every level.
    params.facingCheck = false;
    // A level's budget is a Hausdorff distance, which the same weight for every face reaches
    // with fewer faces; large faces weighing more serve shading at a fixed face count.
    params.largeFaceWeight = 0.0;
    params.shadingWeight = 0.0;  // so does pricing turned faces
    params.minCompactness = kChainMinCompactness;
    // The pieces keep the input's points for the far field (kFarFieldPixels), whose levels
    // are what most of a scene's objects draw.
    params.farFieldWithinBound = true;
    // Breaking a feature costs its own quadric error (the feature's constraint planes are in
    // it) times the penalty. The penalty ranks feature breaks behind collapses of the same
    // error, which keeps creases crisp at a fixed face count; under a Hausdorff budget it
    // keeps a level heavier than its error needs. Half of it (0 stays a hard lock) is what
    // served the chains best (docs/benchmarks.md).
    params.featurePenalty *= kChainFeaturePenaltyShare;
    SimplifyStats stats;
    stats.facesBefore = working.fn;
    // A level is held to its measured error, not to the input's topology: the faces at a
    // non-manifold edge, whose vertices no collapse may move, are cut apart into fans.
    cutNonManifoldEdges(working, params, stats);
    std::string why;
    if (!detail::validateParams(params, why)) {
        result.error = why;
        return result;
    }
    CollapseBuckets<MeshType> pieces(newScratch);
    if (!pieces.prepare(working, params, why, together)) {
        result.error = why;
        return result;
    }
    working.Clear();
    stats.ok = true;
    stats.diagonal = result.modelSize;
    pieces.holdToDistanceBeforeFarField();

    const double dFill = detail::distanceForPixels(result.modelSize, view.viewportHeightPx, view);
    const double dProxy = detail::distanceForPixels(result.modelSize, options.proxyPixels, view);
    const int plannedLevels =
        std::max(1, int(std::ceil(std::log(dProxy * kCloseUpFactor / dFill) / std::log(options.distanceRatio))));
    // How much the measured Hausdorff distance exceeds the largest collapse error (an RMS
    // distance to the merged planes), learnt level by level.
    double hausdorffPerCollapseError = 2.0;
    // ...and the largest distance opened in the far field, where the pieces are held to it.
    double hausdorffPerFarFieldDistance = 1.0;
    // A level copied out of the pieces into a snapshot, measured while their sessions go on
    // to the next one. So the next budget uses the ratio learnt up to the level before it,
    // one level late; that rule does not depend on how the two run, so neither does the
    // chain. Halfway (in distance ratio) between two planned levels the pieces are copied
    // too, into `between`: when the level after it lands more than the distance ratio beyond
    // the level before (its measured error overshot the budget), the snapshot is measured
    // and becomes a level of its own, so no gap in the chain is wider than the ratio allows
    // where the sessions passed through a mesh that fills it. Otherwise it is let go
    // unmeasured.
    struct Snapshot {
        MeshType* mesh = nullptr;  // a scratch mesh, copied into a level mesh when kept
        SimplifyStats stats;  // its largestError: the largest collapse error up to it
        double largestDistance = 0.0;  // ...and the largest distance opened in the far field
        bool farField = false;         // every piece was in the far field
        Measures measured;
        bool taken = false;
    };
    Snapshot pending, between;
    pending.mesh = &newScratch();
    between.mesh = &newScratch();
    auto take = [&](Snapshot& s) {
        pieces.appendTo(*s.mesh);
        s.stats = stats;
        s.stats.facesAfter = s.mesh->fn;
        s.stats.largestError = pieces.largestError();
        s.largestDistance = pieces.largestDistance();
        s.farField = pieces.inFarField();
        s.taken = true;
        stats.relaxed.clear();
    };
    auto measurePending = [&] {
        distanceToOriginal.prepare();
        if (pending.taken)
            pending.measured = measure(*pending.mesh);
    };
    auto keep = [&](Snapshot& s) {
        MeshType& mesh = newLevel(int(result.levels.size()));
        detail::copyWithParts(mesh, *s.mesh);
        s.mesh->Clear();
        s.taken = false;
        addLevel(mesh, s.stats, s.measured);
    };
    // The halfway copy as a level of its own (only the pending level is measured beside
    // the collapses).
    auto keepBetween = [&] {
        between.measured = measure(*between.mesh);
        keep(between);
    };
    auto settlePending = [&] {
        if (!pending.taken)
            return;
        const double measured = pending.measured.distance.max();
        const double lastError = std::max(result.levels.back().hausdorffMax, kRelativeErrorFloor * result.modelSize);
        if (between.taken && measured > options.distanceRatio * lastError) {
            char line[200];
            std::snprintf(line, sizeof line,
                          "added halfway to the next level, whose error (%.4g %% of the diagonal) is more than the "
                          "distance ratio beyond the last level's (%.4g %%)",
                          100 * measured / result.modelSize, 100 * lastError / result.modelSize);
            between.stats.relaxed.push_back(line);
            keepBetween();
        } else if (between.taken) {  // what gave way before it is the pending level's to tell
            auto& lines = pending.stats.relaxed;
            lines.insert(lines.begin(), between.stats.relaxed.begin(), between.stats.relaxed.end());
        }
        between.mesh->Clear();
        between.taken = false;
        const double collapseError = pending.stats.largestError;
        if (measured > 0 && pending.largestDistance > 0)
            hausdorffPerFarFieldDistance = std::clamp(measured / pending.largestDistance, 1.0, 20.0);
        if (!pending.farField && measured > 0 && collapseError > 0)
            hausdorffPerCollapseError = std::clamp(measured / collapseError, 1.0, 20.0);
        keep(pending);
    };

    // The box per component is made where the model is proxyPixels high, from the
    // components left there, and measured at once. A part whose box is far from it (a
    // jack's deep socket, a switch's plunger) would otherwise draw its last collapse level
    // until the box's own error is within the pixel error, which may be several times
    // farther. So the collapse levels go on past that distance while the box does not yet
    // serve there and they are still heavier than it, up to where the model is a couple of
    // pixels high; the selection of useful levels keeps whichever of them serves.
    const double dTetrahedron = detail::distanceForPixels(result.modelSize, kTetrahedronPixels, view);
    const double dFarField = detail::distanceForPixels(result.modelSize, kFarFieldPixels, view);
    struct BoxProxy {
        MeshType* mesh = nullptr;
        Measures measured;
        double trim = 0.0;  // the share of area left out at each end (trimmedBox)
    } boxProxy;
    // Of the proxies `make(m, k)` builds into `m` for k in [0, count), the one measuring
    // closest (the first of equals): its k and its measures. `m` holds the last one tried.
    auto closestProxy = [&](MeshType& m, std::size_t count, const auto& make) {
        std::pair<std::size_t, Measures> best{0, Measures()};
        for (std::size_t k = 0; k < count; ++k) {
            make(m, k);
            const Measures measured = measure(m);
            if (k == 0 || measured.distance.max() < best.second.distance.max())
                best = {k, measured};
        }
        return best;
    };
    // The box per component is tried as the box of its vertices and trimmed of thin
    // protrusions (kBoxTrims); the one with the smallest measured error is kept.
    auto takeBox = [&] {
        boxProxy.mesh = &newScratch();
        MeshType& candidate = newScratch();
        stats.errorBound = detail::errorBudgetAt(dProxy, view);
        together(measurePending, [&] { pieces.appendTo(*boxProxy.mesh); });
        settlePending();
        if (progress)
            progress(100 * plannedLevels / (plannedLevels + 1), "Measuring the box proxy");
        const auto kept = detail::componentsToKeep(*boxProxy.mesh, stats.errorBound, stats);
        // A trim that cuts nothing off makes the boxes a smaller one made: they are measured
        // once (most parts have nothing sticking out).
        std::vector<std::vector<detail::ProxyBox>> trimmed;
        std::vector<double> trims;
        for (double trim : kBoxTrims) {
            std::vector<detail::ProxyBox> boxes = detail::proxyBoxes(*boxProxy.mesh, kept, trim);
            if (std::find(trimmed.begin(), trimmed.end(), boxes) != trimmed.end())
                continue;
            trimmed.push_back(std::move(boxes));
            trims.push_back(trim);
        }
        const auto [best, measured] = closestProxy(candidate, trimmed.size(), [&](MeshType& m, std::size_t k) {
            detail::replaceByProxies(m, trimmed[k], appendBox<MeshType>);
        });
        boxProxy.trim = trims[best];
        boxProxy.measured = measured;
        detail::replaceByProxies(*boxProxy.mesh, trimmed[best], appendBox<MeshType>);
        candidate.Clear();
    };
    auto boxServes = [&](double d) {
        return boxProxy.mesh->fn == 0 || boxProxy.measured.distance.max() <= detail::errorBudgetAt(d, view) ||
               pieces.faces() <= boxProxy.mesh->fn;
    };
    // The distances of the planned levels, each followed by the one halfway to the next.
    const double halfStep = std::sqrt(options.distanceRatio);
    bool planned = true;
    int k = 0;
    for (double d = dFill / kCloseUpFactor;; d *= halfStep, planned = !planned, k += planned ? 1 : 0) {
        if (d >= dProxy) {
            if (!boxProxy.mesh)
                takeBox();
            if (d >= dTetrahedron || boxServes(d))
                break;
        }
        const double budget = detail::errorBudgetAt(d, view);
        const bool farField = d >= dFarField;
        if (farField)
            pieces.startFarField();
        if (progress) {
            char text[96];
            std::snprintf(text, sizeof text, "Simplifying level %d, seen from %.3g model units", k + 1, d);
            progress(100 * std::min(k, plannedLevels) / (plannedLevels + 1), text);
        }
        // Before the far field a collapse is held to the budget both by its quadric error and
        // by the distance it opens (CollapseContext::checksDistance), which the measured error
        // is steered by; only the halves of a large piece, which do not measure distances,
        // are held to the quadric error scaled by the ratio learnt for it.
        const double halvesBound = budget / hausdorffPerCollapseError;
        const double bound = farField ? halvesBound : budget;
        const double distanceBound = budget / hausdorffPerFarFieldDistance;
        stats.targetFaces = 0;
        stats.errorBound = farField ? std::max(bound, distanceBound) : bound;
        const int before = pieces.faces();
        together(measurePending, [&] { pieces.collapse(bound, distanceBound, together, halvesBound); });
        settlePending();
        pieces.addStatsTo(stats);
        const int previous = result.levels.back().faces;
        const int faces = pieces.faces();
        if (faces >= before || faces > 0.9 * previous)
            continue;  // too little lighter than the last level to be worth one
        if (boxProxy.mesh && faces <= boxProxy.mesh->fn)
            break;  // no lighter than the box, which keeps every component's extent
        if (!planned && between.taken) {
            // The last halfway copy had no planned level after it that was lighter: it is the
            // level for the distances since, not a copy to let go.
            keepBetween();
        }
        take(planned ? pending : between);
    }
    together(measurePending, [] {});
    settlePending();
    // A copy halfway past the last planned level has no level after it to overshoot: it is
    // the lightest mesh the sessions reached, and a level like any other (the selection of
    // useful levels drops it where the box serves better).
    if (between.taken)
        keepBetween();
    pieces.release();

    // The proxies, each when it is lighter than the last level: the box per component, then,
    // where the model is a couple of pixels high, a tetrahedron in each box (the fewest
    // triangles that still enclose a volume), and then one for the whole model. Each
    // is drawn from where its measured error is within the pixel error, like any level.
    auto lighterThanLastLevel = [&](std::size_t faces) {
        return faces > 0 && faces < std::size_t(result.levels.back().faces);
    };
    auto addProxy = [&](const std::string& what, int facesEach, const Measures* measured, const std::string& how = "") {
        if (!lighterThanLastLevel(std::size_t(working.fn)))
            return;
        if (progress)
            progress(100 * plannedLevels / (plannedLevels + 1), ("Measuring the " + what + " proxy").c_str());
        MeshType& proxy = newLevel(int(result.levels.size()));
        detail::copyWithParts(proxy, working);
        stats.facesAfter = proxy.fn;
        stats.relaxed.push_back(what + " proxy: one " + what + " per connected component (" +
                                std::to_string(proxy.fn / facesEach) + ")" + how);
        addLevel(proxy, stats, measured ? *measured : measure(proxy));
    };
    detail::copyWithParts(working, *boxProxy.mesh);
    boxProxy.mesh->Clear();
    const std::string trimmed =
        boxProxy.trim > 0 ? ", each without the outermost " + std::to_string(int(std::lround(100 * boxProxy.trim))) +
                                " % of its area at either end of each axis (a pin or leg sticking out)"
                          : "";
    addProxy("box", 12, &boxProxy.measured, trimmed);
    // A tetrahedron in each of `boxes`, grown by whichever of kTetrahedronScales measures
    // closest, into `m`; `grownBy` tells the factor for the log. Nothing is measured where
    // addProxy would not keep them.
    std::string grownBy;
    auto tetrahedraInto = [&](MeshType& m, const std::vector<detail::ProxyBox>& boxes) {
        auto make = [&](MeshType& into, std::size_t k) {
            detail::replaceByProxies(into, detail::grownBoxes(boxes, kTetrahedronScales[k]), appendTetrahedron<MeshType>);
        };
        std::pair<std::size_t, Measures> best{0, Measures()};
        if (lighterThanLastLevel(4 * boxes.size()))
            best = closestProxy(m, std::size(kTetrahedronScales), make);
        make(m, best.first);
        const double scale = kTetrahedronScales[best.first];
        char line[96] = "";
        if (scale != 1.0)
            std::snprintf(line, sizeof line, ", each in its box grown %.3g times", scale);
        grownBy = line;
        return best.second;
    };
    if (options.proxyPixels > kTetrahedronPixels) {
        stats.relaxed.clear();
        stats.errorBound = detail::errorBudgetAt(dTetrahedron, view);
        const detail::ProxyBox whole = detail::modelBox(working);
        const std::vector<detail::ProxyBox> boxes = detail::boxPerComponent(working, stats.errorBound, stats);
        Measures measured = tetrahedraInto(working, boxes);
        addProxy("tetrahedron", 4, &measured, grownBy);
        // Last, one tetrahedron for all of it (also when every part was below the budget).
        if (working.fn != 4 && !whole.box.IsNull()) {
            stats.relaxed.clear();
            measured = tetrahedraInto(working, {whole});
            addProxy("model tetrahedron", 4, &measured, grownBy);
        }
    }

    result.measureSeconds = distanceToOriginal.seconds();
    detail::keepUsefulLevels(result, meshes);
    const double errorFloor = std::max(kRelativeErrorFloor * result.modelSize, 1e-12);
    assignSwitchDistances(result.levels, result.modelSize, view, errorFloor);
    result.levels.back().switchIn =
        options.cullPixels > 0
            ? std::max(result.levels.back().switchOut,
                       detail::distanceForPixels(result.modelSize, options.cullPixels, view))
            : kNeverCulled;
    for (std::size_t i = 0; i < meshes.size(); ++i)
        lodLevelHandle(*meshes[i])() = result.levels[i];
    if (progress)
        progress(100, "LOD chain done");
    return result;
}

}  // namespace cadlod
