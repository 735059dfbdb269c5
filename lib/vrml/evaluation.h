// Shared state of the scene evaluators (VRML97: evaluator97.cpp, VRML 1.0:
// evaluator10.cpp): the scene being built, parts keyed by owner and color, and the
// Inline loader (importer.cpp) that can switch between versions per file.
#pragma once

#include "vrml/face_set_emitter.h"
#include "vrml/importer.h"
#include "vrml/instancing_budget.h"
#include "vrml/node.h"
#include "vrml/primitives.h"
#include "vrml/traversal.h"

#include <functional>
#include <map>
#include <set>
#include <string>
#include <tuple>

namespace cadlod::vrml {

// Faces belong to the part of their owner: the nearest DEF'd node on the traversal path
// (one owner per traversal instance, so two USEs of a DEF'd part are two parts), or the
// Shape itself, named by its path, when nothing above it has a DEF.
struct Owner {
    int id = -1;
    std::string name;
    bool named = false;  // a DEF'd node: a part the CAD system named
};

// The part name of a DEF'd node. A node that is also USE'd is several instances of one
// definition: each is named after the nearest DEF above it too ("HOUSING_B/HOUSING"), so the
// parts of an assembly stay told apart.
inline std::string instanceName(const Node& node, const Owner& outer)
{
    if (node.useCount > 0 && !outer.name.empty())
        return outer.name + "/" + node.defName;
    return node.defName;
}

// With instances kept: the geometry whose shapes are being read, and the DEF names of its
// unshared nodes on the way down, which name the placements met there.
struct GeometryScope {
    std::size_t geometry = 0;
    std::vector<std::string> names;
    std::map<std::tuple<int, float, float, float, float, std::string>, size_t> partIndex;
    Owner shapes;  // the owner of its shapes that have no DEF'd node of their own above them
};

struct EvalContext {
    EvalContext(Scene& scene, const ImportOptions& options) : scene(scene), options(options) {}

    Scene& scene;
    const ImportOptions& options;
    EmitOptions emit;
    std::string baseDir;  // of the file being evaluated, for Inline urls
    // Loads and evaluates an Inline url under `world`; `where` is the Inline's location.
    std::function<void(const std::vector<std::string>& urls, const std::string& where, const Mat4& world,
                       const Owner& owner)> loadInline;

    Owner newOwner(const std::string& name, bool named = false) { return {nextOwnerId++, name, named}; }
    Part& part(const Owner& owner, const std::array<float, 4>& color, const std::string& texture = {});
    // Whose part a shape's faces go to: `owner` (the nearest DEF'd node above it), else the shape
    // itself, named by `path`. In a shared geometry, such shapes are the faces of one part, named
    // after the geometry: its placements are what a user picks.
    Owner shapeOwner(const Owner& owner, const std::string& path);

    bool keepsInstances() const { return keepInstances; }
    // With instances kept: `key` (a shared node, an Inline file) placed at `world`. The first
    // time a key is met, `evaluate` reads its geometry, with its shapes going to a geometry of
    // its own, evaluated in `frame`. A key met again inside itself is refused.
    void placeInstance(const std::string& key, const std::string& name, const Mat4& world, const std::string& where,
                       const std::function<void()>& evaluate);
    // Expanding: counts a use of the shared node `key` after its first (SceneStats::expandedCopies).
    void noteExpandedUse(const std::string& key);
    // Around an unshared DEF'd node, with instances kept: its name goes into the placements'.
    void enterNamed(const Node& node);
    void leaveNamed(const Node& node);
    // The first texture url that exists relative to baseDir; "" (and a warning) if none.
    std::string resolveTexture(const std::vector<std::string>& urls, const std::string& where);

    // Before `nodes` are evaluated: false, with `error` set, if they would take the scene
    // beyond the triangle limit. Every traversal stops once `error` is set.
    bool admit(const std::vector<NodePtr>& nodes, const std::vector<UseSite>& useSites, bool vrml1);
    bool admit(const NodePtr& node, bool vrml1) { return admit(std::vector<NodePtr>{node}, {}, vrml1); }
    bool stopped() const { return !error.empty(); }

    int nextOwnerId = 0;
    std::map<std::tuple<int, float, float, float, float, std::string>, size_t> partIndex;
    bool keepInstances = false;
    Mat4 frame, frameInverse;            // output units <-> file units, uniform
    std::vector<GeometryScope> scopes;   // with instances kept: back() is being read
    std::map<std::string, std::size_t> geometryOfKey;
    std::vector<bool> reading;           // per geometry: being read now
    std::set<std::string> expandedKeys;  // expanding: the shared nodes met so far
    InstancingBudget budget;
    std::string error;  // fatal: the scene would exceed the triangle limit
};

// What tells a shared node from every other: the node itself (one parse per file).
std::string sharedNodeKey(const Node& node);

void evaluateVrml97(const std::vector<NodePtr>& roots, const Mat4& world, const Owner& owner, const std::string& path,
                    EvalContext& ctx);
void evaluateVrml10(const std::vector<NodePtr>& roots, const Mat4& world, const Owner& owner, const std::string& path,
                    EvalContext& ctx);

// Adds the triangles a shape node added to `part` to the scene's per-source counts.
void countShapeTriangles(const std::string& geometryType, size_t before, const Part& part, SceneStats& stats);

// Emits the face set a primitive node was turned into.
void emitOwnedFaceSet(const OwnedFaceSet& f, const std::string& where, const Mat4& world, Part& part,
                      EvalContext& ctx);

}  // namespace cadlod::vrml
