// How buildLodChain (lod_chain.h) makes a chain, step by step: it checks the options, sets
// up level 0 and its measure, deals the model into pieces for the collapse sessions, then
// walks the planned distances (and the ones halfway between them), collapsing the pieces
// toward each distance's budget, keeping or dropping what they reach, and ends with the
// proxies and the levels' switch distances.
#pragma once

#include "lod/chain_level_measure.h"
#include "lod/collapse_buckets.h"
#include "lod/copy_with_parts.h"
#include "lod/lod_builder.h"
#include "lod/lod_chain.h"
#include "lod/lod_plan.h"
#include "lod/lod_proxies.h"
#include "lod/useful_levels.h"
#include "measure/compactness.h"
#include "measure/hausdorff.h"
#include "mesh/layer_metadata.h"
#include "simplify/non_manifold_split.h"
#include "simplify/simplify.h"
#include "support/run_together.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <functional>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cadlod {

// The share of the simplifier's feature penalty that chain levels use (see
// LodChainBuilder::chainParams).
inline constexpr double kChainFeaturePenaltyShare = 0.5;

// One chain in the making (buildLodChain's arguments, see there). build() runs the steps
// once; the builder lives for that call.
template <class MeshType>
class LodChainBuilder
{
public:
    LodChainBuilder(MeshType& original, MeshType& working, const LodChainOptions& options,
                    const std::function<MeshType&(int)>& newLevel, vcg::CallBackPos* progress,
                    std::function<MeshType&()> newScratch)
        : original_(original), working_(working), options_(options), view_(options.view), newLevel_(newLevel),
          progress_(progress),
          newScratch_(newScratch ? std::move(newScratch) : std::function<MeshType&()>(ownScratchMaker())),
          together_(options.runTogether ? options.runTogether : RunTogether(runInSequence)), pieces_(newScratch_)
    {
    }
    LodChainBuilder(const LodChainBuilder&) = delete;
    LodChainBuilder& operator=(const LodChainBuilder&) = delete;

    LodSetResult build()
    {
        if (!validateOptions() || !setUpLevelZero() || !dealIntoPieces())
            return std::move(result_);
        planDistances();
        pending_.mesh = &newScratch_();
        between_.mesh = &newScratch_();
        collapseLevels();
        addProxies();
        finish();
        return std::move(result_);
    }

private:
    using Measures = ChainLevelMeasures;
    // A level copied out of the pieces into a snapshot, measured while their sessions go on
    // to the next one. So the next budget uses the ratio learnt up to the level before it,
    // one level late; that rule does not depend on how the two run, so neither does the
    // chain. Halfway (in distance ratio) between two planned levels the pieces are copied
    // too, into `between_`: when the level after it lands more than the distance ratio beyond
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
    // The box per component, made where the model is proxyPixels high (takeBoxProxy).
    struct BoxProxy {
        MeshType* mesh = nullptr;
        Measures measured;
        double trim = 0.0;  // the share of area left out at each end (trimmedBox)
    };

    // Empty newScratch: default-constructed meshes the builder owns.
    auto ownScratchMaker()
    {
        return [this]() -> MeshType& { return ownScratch_.emplace_back(); };
    }

    bool validateOptions()
    {
        if (!(view_.fovYDegrees > 0 && view_.fovYDegrees < 180) || !(view_.viewportHeightPx >= 1) ||
            !(view_.pixelThreshold > 0) || !(options_.distanceRatio > 1) || !(options_.proxyPixels > 0)) {
            result_.error = "the field of view must be in (0, 180) degrees, the viewport at least 1 px, the pixel "
                            "error and the proxy size positive, and the distance ratio above 1";
            return false;
        }
        return true;
    }

    // Level 0 (the original) as the chain's first level, and the measure of every later level
    // against it.
    bool setUpLevelZero()
    {
        level0_.setId = options_.setId;
        level0_.faces = original_.fn;
        const vcg::Box3d box = liveVertexBox(original_);
        if (box.IsNull() || original_.fn == 0) {
            result_.error = "the mesh has no faces";
            return false;
        }
        level0_.center = {box.Center()[0], box.Center()[1], box.Center()[2]};
        result_.modelSize = box.Diag();
        result_.levels.push_back(level0_);
        result_.compactness.push_back(meshCompactness(original_));
        meshes_.push_back(&original_);

        // Level 0's points and index are made beside the first collapses, before anything is
        // measured.
        measure_.emplace(original_, options_.hausdorffSamples, result_.modelSize, together_);
        return true;
    }

    // What the collapse sessions of every level share; the budget is set per level.
    SimplifyParams chainParams() const
    {
        SimplifyParams params = options_.simplify;
        params.targetFaces = 0;
        params.reductionPerc = 0.0;
        params.maxError = 1.0;  // set per level; here only to pass validation
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
        return params;
    }

    // The model, dealt into pieces that collapse sessions simplify side by side, level
    // after level (the quadrics carry the whole history).
    bool dealIntoPieces()
    {
        detail::copyWithParts(working_, original_);
        vcg::tri::Allocator<MeshType>::CompactEveryVector(working_);
        params_ = chainParams();
        stats_.facesBefore = working_.fn;
        // A level is held to its measured error, not to the input's topology: the faces at a
        // non-manifold edge, whose vertices no collapse may move, are cut apart into fans.
        cutNonManifoldEdges(working_, params_, stats_);
        std::string why;
        if (!detail::validateParams(params_, why) || !pieces_.prepare(working_, params_, why, together_)) {
            result_.error = why;
            return false;
        }
        working_.Clear();
        stats_.ok = true;
        stats_.diagonal = result_.modelSize;
        pieces_.holdToDistanceBeforeFarField();
        return true;
    }

    // The distances where the chain's regimes change, and how many levels are planned
    // before the box proxy (for the progress).
    void planDistances()
    {
        const double size = result_.modelSize;
        dFill_ = detail::distanceForPixels(size, view_.viewportHeightPx, view_);
        dProxy_ = detail::distanceForPixels(size, options_.proxyPixels, view_);
        plannedLevels_ = std::max(
            1, int(std::ceil(std::log(dProxy_ / firstDistance()) / std::log(options_.distanceRatio))));
        dTetrahedron_ = detail::distanceForPixels(size, kTetrahedronPixels, view_);
        dFarField_ = detail::distanceForPixels(size, kFarFieldPixels, view_);
    }

    double firstDistance() const { return std::max(dFill_ / kCloseUpFactor, options_.nearestDistance); }

    // The distances of the planned levels, each followed by the one halfway to the next,
    // until the box proxy serves (or the tetrahedra take over).
    void collapseLevels()
    {
        const double halfStep = std::sqrt(options_.distanceRatio);
        bool planned = true;
        int k = 0;
        for (double d = firstDistance();; d *= halfStep, planned = !planned, k += planned ? 1 : 0) {
            if (options_.farthestDistance > 0 && d > options_.farthestDistance)
                break;
            if (d >= dProxy_) {
                if (!boxProxy_.mesh)
                    takeBoxProxy();
                if (d >= dTetrahedron_ || boxServes(d))
                    break;
            }
            if (!collapseToward(d, planned, k))
                break;
        }
        together_([this] { measurePending(); }, [] {});
        settlePending();
        // A copy halfway past the last planned level has no level after it to overshoot: it is
        // the lightest mesh the sessions reached, and a level like any other (the selection of
        // useful levels drops it where the box serves better).
        if (between_.taken)
            keepBetween();
        pieces_.release();
    }

    // Collapses the pieces to the budget of distance `d` (level k + 1, or halfway past it
    // where not `planned`), beside measuring the pending level. False: the chain's
    // collapse levels end here.
    bool collapseToward(double d, bool planned, int k)
    {
        const double budget = detail::errorBudgetAt(d, view_);
        const bool farField = d >= dFarField_;
        if (farField)
            pieces_.startFarField();
        if (progress_ && planned) {  // the step halfway to the next level is part of it
            char text[120];
            // Named by its distance alone (never with an exponent): the chain also keeps levels
            // halfway between the planned ones and past the box proxy, which a planned count
            // would leave out.
            const double shown = d * options_.distanceScale;
            std::snprintf(text, sizeof text,
                          shown >= 1000 ? "Simplifying for %.0f %s and beyond" : "Simplifying for %.3g %s and beyond",
                          shown, options_.distanceUnit.c_str());
            progress_(100 * std::min(k, plannedLevels_) / (plannedLevels_ + 1), text);
        }
        // Before the far field a collapse is held to the budget both by its quadric error and
        // by the distance it opens (CollapseContext::checksDistance), which the measured error
        // is steered by; only the halves of a large piece, which do not measure distances,
        // are held to the quadric error scaled by the ratio learnt for it.
        const double halvesBound = budget / hausdorffPerCollapseError_;
        const double bound = farField ? halvesBound : budget;
        const double distanceBound = budget / hausdorffPerFarFieldDistance_;
        stats_.targetFaces = 0;
        stats_.errorBound = farField ? std::max(bound, distanceBound) : bound;
        const int before = pieces_.faces();
        together_([this] { measurePending(); },
                  [&] { pieces_.collapse(bound, distanceBound, together_, halvesBound); });
        settlePending();
        pieces_.addStatsTo(stats_);
        return keepOrDropCollapsed(before, planned);
    }

    // Takes what the pieces reached as the next level (or halfway copy), unless it is too
    // little lighter than the last level. False: it is no lighter than the box proxy.
    bool keepOrDropCollapsed(int before, bool planned)
    {
        const int previous = result_.levels.back().faces;
        const int faces = pieces_.faces();
        if (faces >= before || faces > 0.9 * previous)
            return true;  // too little lighter than the last level to be worth one
        if (boxProxy_.mesh && faces <= boxProxy_.mesh->fn)
            return false;  // no lighter than the box, which keeps every component's extent
        if (!planned && between_.taken) {
            // The last halfway copy had no planned level after it that was lighter: it is the
            // level for the distances since, not a copy to let go.
            keepBetween();
        }
        takeSnapshot(planned ? pending_ : between_);
        return true;
    }

    void takeSnapshot(Snapshot& s)
    {
        pieces_.appendTo(*s.mesh);
        s.stats = stats_;
        s.stats.facesAfter = s.mesh->fn;
        s.stats.largestError = pieces_.largestError();
        s.largestDistance = pieces_.largestDistance();
        s.farField = pieces_.inFarField();
        s.taken = true;
        stats_.relaxed.clear();
    }

    // Run beside the collapses: level 0's index (the first time), and the pending level.
    void measurePending()
    {
        measure_->prepare();
        if (pending_.taken)
            pending_.measured = measure(*pending_.mesh);
    }

    // The pending level, once measured: the halfway copy before it is kept or let go, the
    // ratios that steer the next bounds are learnt from it, and it becomes a level.
    void settlePending()
    {
        if (!pending_.taken)
            return;
        const double measured = pending_.measured.distance.max();
        keepOrDropBetween(measured);
        learnErrorRatios(measured);
        keepSnapshot(pending_);
    }

    // The halfway copy is kept where the pending level's `measured` error lands more than
    // the distance ratio beyond the last level's.
    void keepOrDropBetween(double measured)
    {
        const double lastError =
            std::max(result_.levels.back().hausdorffMax, kRelativeErrorFloor * result_.modelSize);
        if (between_.taken && measured > options_.distanceRatio * lastError) {
            char line[200];
            std::snprintf(line, sizeof line,
                          "added halfway to the next level, whose error (%.4g %% of the diagonal) is more than the "
                          "distance ratio beyond the last level's (%.4g %%)",
                          100 * measured / result_.modelSize, 100 * lastError / result_.modelSize);
            between_.stats.relaxed.push_back(line);
            keepBetween();
        } else if (between_.taken) {  // what gave way before it is the pending level's to tell
            auto& lines = pending_.stats.relaxed;
            lines.insert(lines.begin(), between_.stats.relaxed.begin(), between_.stats.relaxed.end());
        }
        between_.mesh->Clear();
        between_.taken = false;
    }

    // How much the measured Hausdorff distance exceeds the largest collapse error (an RMS
    // distance to the merged planes), and the largest distance opened in the far field,
    // where the pieces are held to it: learnt level by level from the pending level.
    void learnErrorRatios(double measured)
    {
        const double collapseError = pending_.stats.largestError;
        if (measured > 0 && pending_.largestDistance > 0)
            hausdorffPerFarFieldDistance_ = std::clamp(measured / pending_.largestDistance, 1.0, 20.0);
        if (!pending_.farField && measured > 0 && collapseError > 0)
            hausdorffPerCollapseError_ = std::clamp(measured / collapseError, 1.0, 20.0);
    }

    // The halfway copy as a level of its own (only the pending level is measured beside
    // the collapses).
    void keepBetween()
    {
        between_.measured = measure(*between_.mesh);
        keepSnapshot(between_);
    }

    void keepSnapshot(Snapshot& s)
    {
        MeshType& mesh = newLevel_(int(result_.levels.size()));
        detail::copyWithParts(mesh, *s.mesh);
        s.mesh->Clear();
        s.taken = false;
        addLevel(mesh, s.stats, s.measured);
    }

    Measures measure(MeshType& mesh) { return (*measure_)(mesh); }

    void addLevel(MeshType& mesh, const SimplifyStats& stats, const Measures& measured)
    {
        const SymmetricHausdorff& h = measured.distance;
        LodLevel level = level0_;
        level.level = int(result_.levels.size());
        level.faces = mesh.fn;
        level.reduction = 1.0 - double(mesh.fn) / original_.fn;
        level.hausdorffMax = h.max();
        level.hausdorffMean = h.mean();
        result_.levels.push_back(level);
        result_.distance.push_back(h);
        result_.compactness.push_back(measured.compactness);
        result_.steps.push_back(stats);
        meshes_.push_back(&mesh);
    }

    // The box per component is made where the model is proxyPixels high, from the
    // components left there, and measured at once. A part whose box is far from it (a
    // jack's deep socket, a switch's plunger) would otherwise draw its last collapse level
    // until the box's own error is within the pixel error, which may be several times
    // farther. So the collapse levels go on past that distance while the box does not yet
    // serve there and they are still heavier than it, up to where the model is a couple of
    // pixels high; the selection of useful levels keeps whichever of them serves.
    // The box is tried as the box of its component's vertices and trimmed of thin
    // protrusions (kBoxTrims); the one with the smallest measured error is kept.
    void takeBoxProxy()
    {
        boxProxy_.mesh = &newScratch_();
        MeshType& candidate = newScratch_();
        stats_.errorBound = detail::errorBudgetAt(dProxy_, view_);
        together_([this] { measurePending(); }, [&] { pieces_.appendTo(*boxProxy_.mesh); });
        settlePending();
        if (progress_)
            progress_(100 * plannedLevels_ / (plannedLevels_ + 1), "Measuring the box proxy");
        const auto kept = detail::componentsToKeep(*boxProxy_.mesh, stats_.errorBound, stats_);
        const std::vector<detail::TrimmedProxyBoxes> trimmed = detail::distinctTrimmedBoxes(*boxProxy_.mesh, kept);
        const auto [best, measured] = closestProxy(candidate, trimmed.size(), [&](MeshType& m, std::size_t k) {
            detail::replaceByProxies(m, trimmed[k].boxes, appendBox<MeshType>);
        });
        boxProxy_.trim = trimmed[best].trim;
        boxProxy_.measured = measured;
        detail::replaceByProxies(*boxProxy_.mesh, trimmed[best].boxes, appendBox<MeshType>);
        candidate.Clear();
    }

    bool boxServes(double d)
    {
        return boxProxy_.mesh->fn == 0 || boxProxy_.measured.distance.max() <= detail::errorBudgetAt(d, view_) ||
               pieces_.faces() <= boxProxy_.mesh->fn;
    }

    // Of the proxies `make(m, k)` builds into `m` for k in [0, count), the one measuring
    // closest (the first of equals): its k and its measures. `m` holds the last one tried.
    template <class MakeProxy>
    std::pair<std::size_t, Measures> closestProxy(MeshType& m, std::size_t count, const MakeProxy& make)
    {
        std::pair<std::size_t, Measures> best{0, Measures()};
        for (std::size_t k = 0; k < count; ++k) {
            make(m, k);
            const Measures measured = measure(m);
            if (k == 0 || measured.distance.max() < best.second.distance.max())
                best = {k, measured};
        }
        return best;
    }

    // The proxies, each when it is lighter than the last level: the box per component, then,
    // where the model is a couple of pixels high, a tetrahedron in each box (the fewest
    // triangles that still enclose a volume), and then one for the whole model. Each
    // is drawn from where its measured error is within the pixel error, like any level.
    void addProxies()
    {
        if (!boxProxy_.mesh)
            return;  // the chain stopped at options_.farthestDistance, nearer than the box serves
        addBoxProxy();
        if (options_.proxyPixels > kTetrahedronPixels)
            addTetrahedronProxies();
    }

    void addBoxProxy()
    {
        detail::copyWithParts(working_, *boxProxy_.mesh);
        boxProxy_.mesh->Clear();
        const std::string trimmed =
            boxProxy_.trim > 0
                ? ", each without the outermost " + std::to_string(int(std::lround(100 * boxProxy_.trim))) +
                      " % of its area at either end of each axis (a pin or leg sticking out)"
                : "";
        addProxy("box", 12, boxProxy_.measured, trimmed);
    }

    void addTetrahedronProxies()
    {
        stats_.relaxed.clear();
        stats_.errorBound = detail::errorBudgetAt(dTetrahedron_, view_);
        const detail::ProxyBox whole = detail::modelBox(working_);
        const std::vector<detail::ProxyBox> boxes = detail::boxPerComponent(working_, stats_.errorBound, stats_);
        const auto [measured, grownBy] = tetrahedraInto(working_, boxes);
        addProxy("tetrahedron", 4, measured, grownBy);
        // Last, one tetrahedron for all of it (also when every part was below the budget).
        if (working_.fn != 4 && !whole.box.IsNull()) {
            stats_.relaxed.clear();
            const auto [wholeMeasured, wholeGrownBy] = tetrahedraInto(working_, {whole});
            addProxy("model tetrahedron", 4, wholeMeasured, wholeGrownBy);
        }
    }

    // A tetrahedron in each of `boxes`, grown by whichever of kTetrahedronScales measures
    // closest, into `m`: its measures, and the factor for the log. Nothing is measured where
    // addProxy would not keep them.
    std::pair<Measures, std::string> tetrahedraInto(MeshType& m, const std::vector<detail::ProxyBox>& boxes)
    {
        auto make = [&](MeshType& into, std::size_t k) {
            detail::replaceByProxies(into, detail::grownBoxes(boxes, kTetrahedronScales[k]),
                                     appendTetrahedron<MeshType>);
        };
        std::pair<std::size_t, Measures> best{0, Measures()};
        if (lighterThanLastLevel(4 * boxes.size()))
            best = closestProxy(m, std::size(kTetrahedronScales), make);
        make(m, best.first);
        const double scale = kTetrahedronScales[best.first];
        char line[96] = "";
        if (scale != 1.0)
            std::snprintf(line, sizeof line, ", each in its box grown %.3g times", scale);
        return {best.second, line};
    }

    bool lighterThanLastLevel(std::size_t faces) const
    {
        return faces > 0 && faces < std::size_t(result_.levels.back().faces);
    }

    // `working_` as the proxy level `what` (`facesEach` faces per component) measuring
    // `measured`, if it is lighter than the last level; `how` ends its log line.
    void addProxy(const std::string& what, int facesEach, const Measures& measured, const std::string& how)
    {
        if (!lighterThanLastLevel(std::size_t(working_.fn)))
            return;
        if (progress_)
            progress_(100 * plannedLevels_ / (plannedLevels_ + 1), ("Measuring the " + what + " proxy").c_str());
        MeshType& proxy = newLevel_(int(result_.levels.size()));
        detail::copyWithParts(proxy, working_);
        stats_.facesAfter = proxy.fn;
        stats_.relaxed.push_back(what + " proxy: one " + what + " per connected component (" +
                                 std::to_string(proxy.fn / facesEach) + ")" + how);
        addLevel(proxy, stats_, measured);
    }

    // The levels that serve, their switch distances, and each level mesh's LodLevel.
    void finish()
    {
        result_.measureSeconds = measure_->seconds();
        detail::keepUsefulLevels(result_, meshes_);
        const double errorFloor = std::max(kRelativeErrorFloor * result_.modelSize, 1e-12);
        assignSwitchDistances(result_.levels, result_.modelSize, view_, errorFloor);
        result_.levels.back().switchIn =
            options_.cullPixels > 0
                ? std::max(result_.levels.back().switchOut,
                           detail::distanceForPixels(result_.modelSize, options_.cullPixels, view_))
                : kNeverCulled;
        for (std::size_t i = 0; i < meshes_.size(); ++i)
            lodLevelHandle(*meshes_[i])() = result_.levels[i];
        if (progress_)
            progress_(100, "LOD chain done");
    }

    // The caller's.
    MeshType& original_;
    MeshType& working_;
    const LodChainOptions& options_;
    const ViewParams& view_;
    const std::function<MeshType&(int)>& newLevel_;
    vcg::CallBackPos* progress_;
    // Declared before the pieces, whose meshes they may be, so that they outlive them.
    std::deque<MeshType> ownScratch_;
    std::function<MeshType&()> newScratch_;
    RunTogether together_;

    LodSetResult result_;
    LodLevel level0_;
    std::vector<MeshType*> meshes_;  // parallel to result_.levels
    std::optional<ChainLevelMeasure<MeshType>> measure_;  // against level 0
    SimplifyParams params_;
    SimplifyStats stats_;  // the collapses' statistics since the last level taken
    CollapseBuckets<MeshType> pieces_;

    double dFill_ = 0.0;        // where the model fills the viewport height
    double dProxy_ = 0.0;       // where it is proxyPixels high: the box proxy
    double dTetrahedron_ = 0.0; // where it is kTetrahedronPixels high: the tetrahedra
    double dFarField_ = 0.0;    // where it is kFarFieldPixels high: the far field
    int plannedLevels_ = 1;
    // The measured error over the largest collapse error, and over the largest distance
    // opened in the far field (learnErrorRatios).
    double hausdorffPerCollapseError_ = 2.0;
    double hausdorffPerFarFieldDistance_ = 1.0;
    Snapshot pending_, between_;
    BoxProxy boxProxy_;
};

template <class MeshType>
LodSetResult buildLodChain(MeshType& original, MeshType& working, const LodChainOptions& options,
                           const std::function<MeshType&(int)>& newLevel, vcg::CallBackPos* progress,
                           std::function<MeshType&()> newScratch)
{
    return LodChainBuilder<MeshType>(original, working, options, newLevel, progress, std::move(newScratch)).build();
}

}  // namespace cadlod
