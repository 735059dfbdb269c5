// Hierarchical LOD over the placements of an instanced assembly (design.md §5, HLOD): the
// placements go into a tree of clusters of nearby parts (lod/cluster_tree.h); each cluster
// gets proxies, its parts merged by colour and simplified together by the same chain, so
// that small parts vanish and gaps close; a cluster is drawn as its proxy from where the
// proxy's error holds at the cluster's nearest point (lod/nearest_point.h), as its parts
// nearer. Shared parts stay instances below the clusters.
//
// A cluster that is another's copy moved (the same parts, turned alike, at the same places
// about it: a repeated rack of boards) gets that cluster's proxies moved, not made again.
//
// A proxy is made bottom-up from what the cluster holds, each piece in its lightest form
// (part level, child proxy, or what the child holds) whose error is at most the error the
// proxy may show where it is first drawn (kProxyInputShare); its error is that input's plus
// its own measured against the input (the triangle inequality of the Hausdorff distance). A
// proxy is kept where it costs less to draw than what it replaces; its ranges are then set
// top-down: a proxy only the parent's proxy would hide is left out.
#pragma once

#include "assembly/assembly_convert.h"

#include "lod/cluster_tree.h"
#include "lod/lod_chain.h"
#include "lod/lod_plan.h"

#include <functional>
#include <string>

namespace cadlod {

// Where a cluster proxy's chain is planned, as distances at which its error is one pixel:
// from `nearest` (it is never drawn nearer) to `farthest` (0: on to the far field; else its
// parent cluster's proxy takes over before the eye is that far).
struct ProxyRange {
    double nearest = 0;
    double farthest = 0;
};

// The chain of a cluster's merged parts, planned over `range`, its steps to `progress` (null:
// none; several chains may run at once, parallel_tasks.h).
using BuildProxyChain = std::function<LodSetResult(CoreMesh& merged, LevelStore& store, const ProxyRange& range,
                                                   vcg::CallBackPos* progress)>;

struct HierarchyOptions {
    ClusterTreeOptions tree;
    ViewParams view;
    // Fewest draw calls near the viewer: every cluster is also drawn, from six radii off, as
    // its parts merged unchanged, each at the level it shows from its nearest possible
    // distance (so that every part keeps its own error), in one draw call, and so again from
    // every kMergedCandidateStep farther, its parts coarser each time; only clusters of
    // kSimplifiedClusterPlacements or more, at every kSimplifiedEveryDepths, also get
    // simplified proxies. Merging gives up instancing: the file holds about the expanded
    // model's geometry again.
    bool fewestCalls = false;
};

// How the placements are clustered (`--hlod`; the LOD-set filter's Hierarchy). Instances: leaves
// of ClusterTreeOptions{} placements, every part its own instance near the viewer. FewestCalls:
// kFewestCallsTree and HierarchyOptions::fewestCalls. Auto: the fewest draw calls for an
// assembly of more placements than kDrawCallBudget, instances for a smaller one.
enum class ClusterMode { Auto, Instances, FewestCalls };

// The draw calls a frame may spend on the model. An assembly of more placements would show a
// viewer inside it more instances than that near the eye, one draw call each; of fewer, it
// never can, and keeps the instance tree's smaller file.
inline constexpr std::size_t kDrawCallBudget = 400;

// What `mode` comes to for a model of `placements`: Instances or FewestCalls.
inline ClusterMode resolvedMode(ClusterMode mode, std::size_t placements)
{
    if (mode != ClusterMode::Auto)
        return mode;
    return placements > kDrawCallBudget ? ClusterMode::FewestCalls : ClusterMode::Instances;
}

// With fewestCalls, the fewest placements a cluster holds to get simplified proxies too.
inline constexpr std::size_t kSimplifiedClusterPlacements = 48;

// With fewestCalls, only clusters at every this many depths below the root get simplified
// proxies: in a tree of two nodes below each cluster, one such cluster per four times the
// placements. Where a cluster has none, its children's proxies stand in, two draw calls
// where there would be one, and the whole model is not simplified once per depth.
inline constexpr std::size_t kSimplifiedEveryDepths = 2;

// With fewestCalls, a cluster's merged proxies are made from six radii off and then every
// this many times farther, until its parent's may take over.
inline constexpr double kMergedCandidateStep = 1.5;

// With fewestCalls, the tree: leaves of two placements, two nodes below a cluster, and a
// placement more than half as large as its group kept above the split, so that clusters are
// small wherever the viewer is.
inline constexpr ClusterTreeOptions kFewestCallsTree{2, 2, 0.5};

// The tree and fewestCalls of `resolved` (resolvedMode), the view left as it is.
inline HierarchyOptions hierarchyOptionsOf(ClusterMode resolved)
{
    HierarchyOptions options;
    options.fewestCalls = resolved == ClusterMode::FewestCalls;
    if (options.fewestCalls)
        options.tree = kFewestCallsTree;
    return options;
}

// Of the error a proxy may show where it is first drawn, the share its input may use. All
// of it: the input is then what the cluster's pieces show there anyway, merged, and the
// proxy's own error only moves its first level out a little. A finer input makes every
// level's collapses and measures dearer, and its levels come out no lighter.
inline constexpr double kProxyInputShare = 1.0;

// A proxy replaces what a cluster holds where drawing it costs less, a draw call counting
// as this many triangles (the per-call work of a renderer).
inline constexpr double kDrawCallTriangles = 256.0;

// The fewest Hausdorff samples per side a cluster proxy is measured with.
inline constexpr std::size_t kProxySamples = 20000;

// A proxy's chain is planned only up to this many times the distance from which its parent's
// proxy may first be drawn: the parent's own chain starts there, its levels twice as far
// apart, so its proxy has taken over by then.
inline constexpr double kParentTakeOverMargin = 4.0;

// A proxy's chain options from the parts' own: planned over `range`; measured with more
// samples where none were asked for (its parts' levels are measured already, its error must
// hold over a whole cluster).
LodChainOptions proxyChainOptions(LodChainOptions options, int triangles, const ProxyRange& range);

struct HierarchyStats {
    std::size_t clusters = 0;
    std::size_t proxied = 0;         // clusters with at least one proxy
    std::size_t proxyLevels = 0;     // LOD records, a copy's as well
    std::size_t proxyShapes = 0;     // meshes they draw, a copy's shared with its original's
    std::size_t proxyTriangles = 0;  // of those shapes, each once
    std::size_t inputTriangles = 0;  // merged into proxies, before simplifying
    std::size_t copied = 0;          // clusters whose proxies were moved from a copy's, not made
    std::size_t turned = 0;          // of those, copies turned as well as moved
    std::size_t mirrored = 0;        // of those, copies seen in a mirror
};

// Puts c.model's placements into clusters with proxies, each proxy made a span of `progress`;
// every level of every part becomes one drawable. A model of one placement gets no clusters.
// The proxies of the clusters of one height are made at once (parallel_tasks.h).
// Throws std::runtime_error when a proxy cannot be built.
HierarchyStats buildHierarchy(AssemblyConversion& c, const HierarchyOptions& options, const PartWelding& welding,
                              const BuildProxyChain& buildProxyChain, const ProgressSpans& progress = {});

}  // namespace cadlod
