#include "assembly/hierarchical_lod.h"

#include "assembly/cluster_copies.h"
#include "assembly/merged_levels.h"
#include "assembly/parallel_tasks.h"

#include "lod/lod_chain.h"
#include "lod/nearest_point.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace cadlod {
namespace {

using flt::Vec3d;

// The box, in the model, of a part's finest level where a placement puts it.
Box3 placedBox(const flt::Level& level, const flt::Mat4d& m)
{
    Box3 local, placed;
    for (const flt::Part& part : level.parts)
        for (const Vec3d& p : part.positions)
            local.add(p);
    if (local.empty())
        return placed;
    for (int corner = 0; corner < 8; ++corner)
        placed.add(flt::transformed(m, {corner & 1 ? local.hi[0] : local.lo[0],
                                        corner & 2 ? local.hi[1] : local.lo[1],
                                        corner & 4 ? local.hi[2] : local.lo[2]}));
    return placed;
}

// A level a cluster may be drawn as: in model coordinates, its error against the parts it
// stands for, and how far its vertices reach from the cluster's centre.
struct Candidate {
    flt::Level level;
    double error = 0;
    double reach = 0;
    double drawnFrom = 0;  // where it may first be drawn when not by its error (0: by its error)
};

struct ClusterWork {
    Vec3d centre{};
    double radius = 0;
    std::vector<Candidate> candidates;  // finest first; empty: drawn as what it holds
    // The candidates worth drawing, and from which distance to the centre each is drawn.
    std::vector<std::size_t> selected;
    std::vector<double> from;
    std::size_t mergedTriangles = 0;  // the simplified proxies' input
};

// What drawing a level costs: its triangles, and its draw calls weighed as triangles.
double drawCost(const flt::Level& level)
{
    return double(level.triangleCount()) + kDrawCallTriangles * double(drawables(level));
}

// Two clusters are copies when every part of one lies this share of the model's diagonal or
// nearer where the other has it: far finer than a viewer could tell, far coarser than the
// rounding of a file's numbers.
constexpr double kCopyTolerance = 1e-6;

class HierarchyBuilder {
public:
    HierarchyBuilder(AssemblyConversion& c, const HierarchyOptions& options, const PartWelding& welding,
                     const BuildProxyChain& buildProxyChain, const ProgressSpans& progress)
        : c_(c), options_(options), welding_(welding), buildProxyChain_(buildProxyChain), progress_(progress)
    {
    }

    HierarchyStats build()
    {
        drawPartsInOneCall();
        if (c_.model.placements.size() < 2)
            return stats_;  // one placed part: nothing to cluster
        std::vector<Box3> boxes;
        for (const flt::PartPlacement& p : c_.model.placements)
            boxes.push_back(placedBox(c_.model.definitions[p.definition].levels.front(), p.matrix));
        const std::vector<ClusterNode> tree = buildClusterTree(boxes, options_.tree, assemblyPaths());
        const double diagonal = tree.empty() ? 0.0 : 2.0 * tree.front().box.halfDiagonal();
        SharedCopies shared = shareCopies(tree, c_.model.placements, boxes, partReaches(), kCopyTolerance * diagonal);
        nodes_ = std::move(shared.nodes);
        copies_ = std::move(shared.copies);
        work_.resize(nodes_.size());
        for (std::size_t n = 0; n < nodes_.size(); ++n)
            centreOn(n);
        parent_.assign(nodes_.size(), 0);
        for (std::size_t n = 0; n < nodes_.size(); ++n)
            for (std::size_t child : nodes_[n].children)
                parent_[child] = n;
        drawnAlike_.assign(nodes_.size(), {});
        for (std::size_t n = 0; n < nodes_.size(); ++n)
            drawnAlike_[copies_[n].original].push_back(n);
        makeProxiesChildrenFirst();
        c_.model.clusters.resize(nodes_.size());
        if (!nodes_.empty())
            placeCluster(0, kNeverCulled, "cluster 1");
        work_.clear();
        stats_.clusters = nodes_.size();
        stats_.proxyShapes = c_.model.proxyShapes.size();
        stats_.proxyTriangles = c_.model.proxyTriangles();
        return stats_;
    }

private:
    // An original's centre and radius are its box's; a copy's are its original's, moved, as
    // its proxies are: a copy turned by other than quarter turns has a larger box.
    void centreOn(std::size_t n)
    {
        const std::size_t original = copies_[n].original;
        if (original == n) {
            work_[n].centre = nodes_[n].box.center();
            work_[n].radius = nodes_[n].box.halfDiagonal();
            return;
        }
        work_[n].centre = flt::transformed(copies_[n].move, work_[original].centre);
        work_[n].radius = work_[original].radius;
    }

    // Every level of every part (and of its chunks) one drawable: near the eye the parts are
    // drawn one by one, and their colours would multiply the draw calls.
    void drawPartsInOneCall()
    {
        for (flt::PartDefinition& definition : c_.model.definitions) {
            for (flt::Level& level : definition.levels)
                level = asOneDrawable(std::move(level), definition.name);
            flt::forEachChunkLevel(definition.chunks,
                                   [&](flt::Level& level) { level = asOneDrawable(std::move(level), definition.name); });
        }
    }

    // Where a level of this error and reach is switched in, at the cluster's nearest point.
    double switchDistance(double error, double reach) const
    {
        return switchAtNearestPoint(projectedErrorDistance(error, options_.view), reach);
    }

    // Where each placement is in the assembly, from its name ("Rack_2/Board_1/U1": Rack_2,
    // Board_1, then U1), each name a number. A placement's own name is in its path: a board
    // placed as "Rack_2/Board_1" belongs with the parts placed under it.
    AssemblyPaths assemblyPaths() const
    {
        std::map<std::string, std::size_t> numbers;
        AssemblyPaths paths;
        for (const flt::PartPlacement& p : c_.model.placements) {
            std::vector<std::size_t>& path = paths.emplace_back();
            for (std::size_t from = 0, slash = 0; slash != std::string::npos; from = slash + 1) {
                slash = p.name.find('/', from);
                path.push_back(numbers.emplace(p.name.substr(from, slash - from), numbers.size()).first->second);
            }
        }
        return paths;
    }

    // How far each part's vertices lie from its own origin, at any level.
    std::vector<double> partReaches() const
    {
        std::vector<double> reach;
        for (const flt::PartDefinition& definition : c_.model.definitions) {
            double r = 0;
            for (const flt::Level& level : definition.levels)
                r = std::max(r, level.reachFrom({0, 0, 0}));
            reach.push_back(r);
        }
        return reach;
    }

    // A cluster's proxies are made from its children's: the clusters of one height (the
    // longest way down to a leaf) are made at once, the lowest first; then the copies of
    // that height get theirs moved.
    void makeProxiesChildrenFirst()
    {
        std::vector<std::size_t> height(nodes_.size(), 0);
        for (std::size_t n = nodes_.size(); n-- > 0;)  // a child's index is above its parent's
            for (std::size_t child : nodes_[n].children)
                height[n] = std::max(height[n], height[child] + 1);
        std::vector<std::vector<std::size_t>> made(nodes_.empty() ? 0 : height.front() + 1), moved(made.size());
        for (std::size_t n = nodes_.size(); n-- > 0;)
            (copies_[n].original == n ? made : moved)[height[n]].push_back(n);
        std::size_t toMake = 0, before = 0;
        for (const std::vector<std::size_t>& same : made)
            toMake += same.size();
        for (std::size_t h = 0; h < made.size(); ++h) {
            const std::vector<std::size_t>& same = made[h];
            runTasks(
                same.size(),
                [&](std::size_t i, const ProgressSpans& progress) {
                    makeProxies(same[i], before + i, toMake, progress);
                },
                progress_);
            before += same.size();
            for (std::size_t n : moved[h])
                moveCopy(n);
        }
        for (const ClusterWork& work : work_)
            stats_.inputTriangles += work.mergedTriangles;
    }

    // Cluster n's proxies: its original's, moved (and turned or mirrored) as its parts are
    // (candidatesOf, moveOf), drawn from the same distances to its centre. Their chain went on
    // to where the last of the original's copies' parents takes over (farthestDrawn).
    void moveCopy(std::size_t n)
    {
        const ClusterWork& from = work_[copies_[n].original];
        work_[n].selected = from.selected;
        work_[n].from = from.from;
        ++stats_.copied;
        stats_.turned += copies_[n].turned() && !copies_[n].mirrored();
        stats_.mirrored += copies_[n].mirrored();
    }

    // Cluster n's proxy candidates, where moveOf(n) puts them: a copy's are its original's.
    const std::vector<Candidate>& candidatesOf(std::size_t n) const { return work_[copies_[n].original].candidates; }
    const flt::Mat4d& moveOf(std::size_t n) const { return copies_[n].move; }

    // Cluster n's proxy candidates, the `order`-th of `count` clusters made.
    void makeProxies(std::size_t n, std::size_t order, std::size_t count, const ProgressSpans& progress)
    {
        const ClusterNode& node = nodes_[n];
        ClusterWork& work = work_[n];
        if (node.children.size() + node.items.size() < 2)
            return;  // its one part or cluster is drawn as itself
        if (options_.fewestCalls) {
            addMergedCandidates(n);
            if (placementsBelow(n) < kSimplifiedClusterPlacements || depthOf(n) % kSimplifiedEveryDepths != 0) {
                select(n);
                return;
            }
        }
        // The error a proxy may show where it can first be drawn, at its nearest point.
        const double nearest = switchAtNearestPoint(0.0, work.radius);
        const double allowance = kProxyInputShare * detail::errorBudgetAt(nearest - work.radius, options_.view);
        MergedParts merged(work.centre);
        double inputError = 0;
        std::vector<const Candidate*> lightest(nodes_.size(), nullptr);
        chooseLightest(n, allowance, lightest);
        gather(n, allowance, lightest, merged, inputError);
        work.mergedTriangles = merged.triangles();
        {
            ProgressSpan span(progress, int(100 * order / count), int(100 * (order + 1) / count),
                              "proxy " + std::to_string(order + 1) + "/" + std::to_string(count));
            // The chain's first level then lands about where the proxy can first be drawn.
            const double first =
                std::max(0.0, nearest - work.radius - projectedErrorDistance(inputError, options_.view));
            simplifyTogether(merged, inputError, {first, farthestDrawn(n, inputError, first)}, work, progress);
        }
        select(n);
    }

    // Past where its parent's proxy has surely taken over, cluster n's proxy is never drawn,
    // nor is a copy's past where the copy's parent takes over. Original n's chain stops at the
    // farthest of those: as a distance at which the proxy's own error is one pixel, like
    // `first`. The root's chain goes on to the far field (0).
    double farthestDrawn(std::size_t n, double inputError, double first) const
    {
        double farthest = kParentTakeOverMargin * first;
        for (std::size_t c : drawnAlike_[n]) {
            if (c == 0)
                return 0.0;
            const Box3& parent = nodes_[parent_[c]].box;
            const double takeOver = kParentTakeOverMargin * switchAtNearestPoint(0.0, parent.halfDiagonal()) +
                                    flt::distance(parent.center(), work_[c].centre);
            farthest =
                std::max(farthest, takeOver - work_[c].radius - projectedErrorDistance(inputError, options_.view));
        }
        return farthest;
    }

    std::size_t depthOf(std::size_t n) const
    {
        std::size_t depth = 0;
        for (; n != 0; n = parent_[n])
            ++depth;
        return depth;
    }

    std::size_t placementsBelow(std::size_t n) const
    {
        std::size_t count = nodes_[n].items.size();
        for (std::size_t child : nodes_[n].children)
            count += placementsBelow(child);
        return count;
    }

    // The first proxy only merges: what the cluster holds, each piece at the level it shows
    // from the nearest distance the eye can have to it while the proxy is drawn, so that every
    // piece keeps its own error bound; one draw call where there were many. Merged from where
    // it may first be drawn, then every kMergedCandidateStep farther until its parent's first
    // proxy may take over: each merge's pieces coarser than the last's.
    void addMergedCandidates(std::size_t n)
    {
        const double first = switchAtNearestPoint(0.0, work_[n].radius);
        const double parentFirst = n == 0 ? first
                                          : switchAtNearestPoint(0.0, work_[parent_[n]].radius) +
                                                flt::distance(work_[parent_[n]].centre, work_[n].centre);
        for (double from = first; from == first || from < parentFirst; from *= kMergedCandidateStep)
            addMergedCandidate(n, from);
    }

    void addMergedCandidate(std::size_t n, double from)
    {
        ClusterWork& work = work_[n];
        LevelMerger merger;
        Candidate candidate;
        collectAt(n, work.centre, from, merger, candidate.error);
        if (merger.empty() || !merger.take("proxy", work.centre, candidate.level))
            return;
        candidate.reach = candidate.level.reachFrom(work.centre);
        candidate.drawnFrom = from;  // where its pieces were chosen for; at least six reaches off
        work.candidates.push_back(std::move(candidate));
    }

    // What cluster m draws when the eye is `from` off `centre`: each piece seen from its
    // nearest possible distance.
    void collectAt(std::size_t m, const Vec3d& centre, double from, LevelMerger& merger, double& error) const
    {
        for (std::size_t p : nodes_[m].items) {
            const flt::PartPlacement& placement = c_.model.placements[p];
            const flt::Level& finest = c_.model.definitions[placement.definition].levels.front();
            const double offset = flt::distance(centre, flt::transformed(placement.matrix, finest.center));
            addPlacedLevel(placement, levelIndexAt(placement, std::max(0.0, from - offset)), merger, error);
        }
        for (std::size_t child : nodes_[m].children) {
            const Candidate* proxy = drawnProxy(child, from - flt::distance(centre, work_[child].centre));
            if (!proxy) {
                collectAt(child, centre, from, merger, error);
                continue;
            }
            merger.add(proxy->level, moveOf(child));
            error = std::max(error, proxy->error);
        }
    }

    // A candidate is drawn from where it holds at the nearest point, if it is lighter there
    // than what the cluster holds; a coarser one that holds as near serves instead.
    void select(std::size_t n)
    {
        ClusterWork& work = work_[n];
        for (std::size_t k = 0; k < work.candidates.size(); ++k) {
            const Candidate& candidate = work.candidates[k];
            const double s =
                candidate.drawnFrom > 0 ? candidate.drawnFrom : switchDistance(candidate.error, candidate.reach);
            if (drawCost(candidate.level) >= drawnBelow(n, s))
                continue;
            while (!work.from.empty() && s <= work.from.back()) {
                work.selected.pop_back();
                work.from.pop_back();
            }
            work.selected.push_back(k);
            work.from.push_back(s);
        }
    }

    // What drawing what cluster n holds costs, seen from distance d (to every node's centre
    // alike: an estimate).
    double drawnBelow(std::size_t n, double d) const
    {
        double triangles = 0;
        for (std::size_t p : nodes_[n].items)
            triangles += drawCost(placedLevelAt(c_.model.placements[p], d));
        for (std::size_t child : nodes_[n].children)
            triangles += drawnAt(child, d);
        return triangles;
    }

    double drawnAt(std::size_t n, double d) const
    {
        const Candidate* proxy = drawnProxy(n, d);
        return proxy ? drawCost(proxy->level) : drawnBelow(n, d);
    }

    // The proxy cluster n is drawn as from distance d to its centre; null: what it holds.
    const Candidate* drawnProxy(std::size_t n, double d) const
    {
        const ClusterWork& work = work_[n];
        for (std::size_t i = work.selected.size(); i-- > 0;)
            if (work.from[i] <= d)
                return &candidatesOf(n)[work.selected[i]];
        return nullptr;
    }

    const flt::Level& placedLevelAt(const flt::PartPlacement& p, double d) const
    {
        return placedLevel(p, levelIndexAt(p, d));
    }

    // The level placement p shows at distance d from its centre.
    std::size_t levelIndexAt(const flt::PartPlacement& p, double d) const
    {
        const std::vector<flt::Level>& levels = c_.model.definitions[p.definition].levels;
        const double local = d / std::max(flt::largestScale(p.matrix), 1e-300);
        for (std::size_t k = 0; k < levels.size(); ++k)
            if (levels[k].switchOut <= local && local < levels[k].switchIn)
                return k;
        return local < levels.front().switchIn ? 0 : levels.size() - 1;
    }

    // What cluster n holds, each piece as light as `allowance` lets it be: a child as
    // chooseLightest chose it, one of its candidates or (null) what it holds.
    void gather(std::size_t n, double allowance, const std::vector<const Candidate*>& lightest,
                MergedParts& merged, double& inputError) const
    {
        for (std::size_t p : nodes_[n].items)
            addPlacedLevel(c_.model.placements[p], coarsestWithin(c_.model.placements[p], allowance), merged,
                           inputError);
        for (std::size_t child : nodes_[n].children) {
            const Candidate* best = lightest[child];
            if (!best) {
                gather(child, allowance, lightest, merged, inputError);
                continue;
            }
            merged.add(best->level, moveOf(child));
            inputError = std::max(inputError, best->error);
        }
    }

    // The lightest way each cluster of n's subtree enters a proxy's input within `allowance`,
    // into `lightest`: the lightest of its candidates within the allowance, or (null) what it
    // holds, each piece so, where that is lighter still (a merged candidate keeps every part
    // whole; its children's simplified proxies may hold the same error in fewer triangles).
    // Returns n's triangles so.
    std::size_t chooseLightest(std::size_t n, double allowance, std::vector<const Candidate*>& lightest) const
    {
        std::size_t triangles = 0;
        for (std::size_t p : nodes_[n].items)
            triangles += placedLevel(c_.model.placements[p], coarsestWithin(c_.model.placements[p], allowance))
                             .triangleCount();
        for (std::size_t child : nodes_[n].children)
            triangles += chooseLightest(child, allowance, lightest);
        for (const Candidate& candidate : candidatesOf(n))
            if (candidate.error <= allowance && candidate.level.triangleCount() < triangles) {
                lightest[n] = &candidate;
                triangles = candidate.level.triangleCount();
            }
        return triangles;
    }

    // Placement p's coarsest level whose measured error, placed, is within `allowance`.
    std::size_t coarsestWithin(const flt::PartPlacement& p, double allowance) const
    {
        const std::vector<flt::Level>& levels = c_.model.definitions[p.definition].levels;
        const std::vector<LodLevel>& measured = c_.parts[p.definition].result.levels;
        const double scale = flt::largestScale(p.matrix);
        std::size_t best = 0;
        for (std::size_t k = 1; k < levels.size() && k < measured.size(); ++k)
            if (scale * measured[k].hausdorffMax <= allowance)
                best = k;
        return best;
    }

    const flt::Level& placedLevel(const flt::PartPlacement& p, std::size_t k) const
    {
        return c_.model.definitions[p.definition].levels[k];
    }

    // Level k of placement p into `sink` (MergedParts or LevelMerger), `error` raised to its.
    template <class Sink>
    void addPlacedLevel(const flt::PartPlacement& p, std::size_t k, Sink& sink, double& error) const
    {
        sink.add(c_.model.definitions[p.definition].levels[k], p.matrix);
        const std::vector<LodLevel>& measured = c_.parts[p.definition].result.levels;
        if (k < measured.size())
            error = std::max(error, flt::largestScale(p.matrix) * measured[k].hausdorffMax);
    }

    void simplifyTogether(MergedParts& merged, double inputError, const ProxyRange& range, ClusterWork& work,
                          const ProgressSpans& progress)
    {
        if (merged.triangles() == 0)
            return;
        CoreMesh mesh;
        {
            ProgressSpan welding(progress, 0, kWeldingShare);
            partToMesh(merged.take(), "cluster", mesh, welding_, progress.step);
        }
        LevelStore store;
        LodSetResult result;
        {
            ProgressSpan chain(progress, kWeldingShare, 100);
            result = buildProxyChain_(mesh, store, range, progress.step);
        }
        if (!result.ok())
            throw std::runtime_error("a cluster proxy: " + result.error);
        std::vector<CoreMesh*> meshes{&mesh};
        for (auto& m : store.meshes)
            meshes.push_back(m.get());
        std::size_t skipped = 0;
        flt::LodModel levels = lodMeshesToModel(meshes, result.levels.front().setId, "proxy", skipped);
        for (std::size_t k = 0; k < levels.levels.size() && k < result.levels.size(); ++k) {
            Candidate candidate;
            candidate.level = asOneDrawable(std::move(levels.levels[k]), "proxy");
            moveBy(candidate.level, work.centre);
            candidate.level.center = work.centre;
            candidate.error = inputError + result.levels[k].hausdorffMax;
            candidate.reach = candidate.level.reachFrom(work.centre);
            work.candidates.push_back(std::move(candidate));
        }
    }

    static void moveBy(flt::Level& level, const Vec3d& offset)
    {
        for (flt::Part& part : level.parts)
            for (Vec3d& p : part.positions)
                for (int a = 0; a < 3; ++a)
                    p[a] += offset[a];
        for (int a = 0; a < 3; ++a)
            level.center[a] += offset[a];
    }

    // Cluster n's proxies that are ever drawn: below `cutoff` (where the parent's proxy
    // takes over, seen from this cluster's centre), each from where it holds.
    void placeCluster(std::size_t n, double cutoff, const std::string& name)
    {
        flt::PlacementCluster& out = c_.model.clusters[n];
        out.name = name;
        out.center = work_[n].centre;
        out.placements = nodes_[n].items;
        out.clusters = nodes_[n].children;
        keepProxies(n, cutoff, name, out);
        if (!out.proxies.empty()) {
            ++stats_.proxied;
            stats_.proxyLevels += out.proxies.size();
        }
        const double below = out.proxies.empty() ? cutoff : out.nearRange();
        for (std::size_t i = 0; i < nodes_[n].children.size(); ++i) {
            const std::size_t child = nodes_[n].children[i];
            placeCluster(child, below + flt::distance(work_[n].centre, work_[child].centre),
                         name + "." + std::to_string(i + 1));
        }
    }

    void keepProxies(std::size_t n, double cutoff, const std::string& name, flt::PlacementCluster& out)
    {
        const ClusterWork& work = work_[n];
        std::size_t kept = 0;
        while (kept < work.from.size() && work.from[kept] < cutoff)
            ++kept;
        for (std::size_t i = 0; i < kept; ++i) {
            flt::Level range;
            range.name = name + " proxy " + std::to_string(i + 1);
            range.switchOut = work.from[i];
            range.switchIn = i + 1 < kept ? work.from[i + 1] : kNeverCulled;
            range.center = work.centre;
            out.shapes.push_back(shapeOf(copies_[n].original, work.selected[i], range.name));
            out.proxies.push_back(std::move(range));
        }
        out.move = moveOf(n);
    }

    // Candidate k of cluster n, an original, as a proxy shape of the model: made the first
    // time a cluster keeps it (named after that cluster's proxy), shared by its copies.
    std::size_t shapeOf(std::size_t n, std::size_t k, const std::string& name)
    {
        const auto [at, added] = shapes_.emplace(std::make_pair(n, k), c_.model.proxyShapes.size());
        if (added) {
            flt::Level shape = std::move(work_[n].candidates[k].level);
            shape.name = name;
            c_.model.proxyShapes.push_back(std::move(shape));
        }
        return at->second;
    }

    AssemblyConversion& c_;
    const HierarchyOptions& options_;
    const PartWelding welding_;
    const BuildProxyChain& buildProxyChain_;
    const ProgressSpans& progress_;
    std::vector<ClusterNode> nodes_;
    std::vector<std::size_t> parent_;  // the root's: 0
    std::vector<ClusterCopy> copies_;  // of each cluster, the cluster it is a copy of (or itself)
    std::vector<std::vector<std::size_t>> drawnAlike_;  // of each original, itself and its copies
    std::vector<ClusterWork> work_;
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> shapes_;  // (cluster, candidate) -> proxy shape
    HierarchyStats stats_;
};

}  // namespace

LodChainOptions proxyChainOptions(LodChainOptions options, int triangles, const ProxyRange& range)
{
    options.nearestDistance = range.nearest;
    options.farthestDistance = range.farthest;
    if (range.nearest > 0 && options.hausdorffSamples == 0)
        options.hausdorffSamples = std::clamp<std::size_t>(std::size_t(triangles), kProxySamples, 100000);
    return options;
}

HierarchyStats buildHierarchy(AssemblyConversion& c, const HierarchyOptions& options, const PartWelding& welding,
                              const BuildProxyChain& buildProxyChain, const ProgressSpans& progress)
{
    return HierarchyBuilder(c, options, welding, buildProxyChain, progress).build();
}

}  // namespace cadlod
