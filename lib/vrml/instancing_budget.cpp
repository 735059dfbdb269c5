#include "vrml/instancing_budget.h"

#include "vrml/evaluation.h"
#include "vrml/primitives.h"
#include "vrml/transform.h"
#include "vrml/traversal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace cadlod::vrml {
namespace {

constexpr uint64_t kSaturated = std::numeric_limits<uint64_t>::max();

uint64_t saturatingAdd(uint64_t a, uint64_t b) { return a > kSaturated - b ? kSaturated : a + b; }

// A node reference as the evaluators follow it: the node and, when written as USE, where.
struct Ref {
    const Node* node = nullptr;
    const std::string* useWhere = nullptr;
};

const FieldValue* nodesField(const Node& n, const char* name)
{
    const FieldValue* v = n.field(name);
    return v && v->kind == FieldValue::Kind::Nodes ? v : nullptr;
}

// The non-null entries of `refs` (NULL emits nothing).
std::vector<Ref> nonNull(const std::vector<ChildRef>& refs)
{
    std::vector<Ref> out;
    for (const ChildRef& r : refs)
        if (*r.node) out.push_back({r.node->get(), r.useWhere});
    return out;
}

// The references the evaluators follow below `n` (vrml/traversal.h).
std::vector<Ref> children(const Node& n, bool vrml1) { return nonNull(traversedChildren(n, vrml1).children); }

uint64_t faceSetTriangles(const std::vector<int32_t>* coordIndex)
{
    if (!coordIndex) return 0;
    uint64_t total = 0, corners = 0;
    for (const int32_t i : *coordIndex) {
        if (i >= 0) {
            ++corners;
            continue;
        }
        total += corners > 2 ? corners - 2 : 0;
        corners = 0;
    }
    return total + (corners > 2 ? corners - 2 : 0);
}

uint64_t faceSetTriangles(const OwnedFaceSet& f) { return faceSetTriangles(&f.coordIndex); }

uint64_t sphereTriangles()
{
    static const uint64_t n = faceSetTriangles(makeSphere(1));
    return n;
}
uint64_t cylinderTriangles()
{
    static const uint64_t n = faceSetTriangles(makeCylinder(1, 2, true, true, true));
    return n;
}
uint64_t coneTriangles()
{
    static const uint64_t n = faceSetTriangles(makeCone(1, 2, true, true));
    return n;
}
constexpr uint64_t kBoxTriangles = 12;

uint64_t elevationGridTriangles(const Node& g)
{
    const int64_t x = intField(g, "xDimension", 0), z = intField(g, "zDimension", 0);
    const std::vector<float>* heights = floatsField(g, "height");
    if (x < 2 || z < 2 || double(x) * double(z) > double(heights ? heights->size() : 0)) return 0;
    return 2 * uint64_t(x - 1) * uint64_t(z - 1);
}

uint64_t extrusionTriangles(const Node& g)
{
    const std::vector<float>* cross = floatsField(g, "crossSection");
    const std::vector<float>* spine = floatsField(g, "spine");
    const uint64_t sections = cross ? cross->size() / 2 : 5, spines = spine ? spine->size() / 3 : 2;
    if (sections < 2 || spines < 2) return 0;
    return 2 * (spines - 1) * (sections - 1) + 2 * (sections > 2 ? sections - 2 : 0);
}

uint64_t geometryTriangles97(const Node& g)
{
    const std::string& t = g.type;
    if (t == "IndexedFaceSet") return faceSetTriangles(intsField(g, "coordIndex"));
    if (t == "Box") return kBoxTriangles;
    if (t == "Sphere") return sphereTriangles();
    if (t == "Cylinder") return cylinderTriangles();
    if (t == "Cone") return coneTriangles();
    if (t == "ElevationGrid") return elevationGridTriangles(g);
    if (t == "Extrusion") return extrusionTriangles(g);
    return 0;
}

// Triangles the node emits itself (not through the references it is followed into).
uint64_t ownTriangles(const Node& n, bool vrml1)
{
    const std::string& t = n.type;
    if (!vrml1) {
        if (t != "Shape") return 0;
        const FieldValue* g = nodesField(n, "geometry");
        return g && !g->nodes.empty() && g->nodes.front() ? geometryTriangles97(*g->nodes.front()) : 0;
    }
    if (t == "IndexedFaceSet") return faceSetTriangles(intsField(n, "coordIndex"));
    if (t == "Cube") return kBoxTriangles;
    if (t == "Sphere") return sphereTriangles();
    if (t == "Cylinder") return cylinderTriangles();
    if (t == "Cone") return coneTriangles();
    return 0;
}

std::string exceedsError(const Ref& ref, uint64_t limit)
{
    const Node& n = *ref.node;
    const std::string what = ref.useWhere ? *ref.useWhere + ": USE " + n.defName
                                          : n.where + ": " + n.type + (n.defName.empty() ? "" : " " + n.defName);
    return what + " would make the scene exceed " + std::to_string(limit) + " triangles" +
           (ref.useWhere ? " (instancing limit)" : " (triangle limit)");
}

}  // namespace

uint64_t triangleLimit(uint64_t maxTriangles, double maxTrianglesPerInputByte, uint64_t inputBytes)
{
    const double relative = maxTrianglesPerInputByte * double(inputBytes);
    if (!(relative > double(maxTriangles))) return maxTriangles;
    return relative >= double(kSaturated) ? kSaturated : uint64_t(relative);
}

uint64_t InstancingBudget::triangles(const Node& node, bool vrml1)
{
    const auto it = triangles_.find(&node);
    return it != triangles_.end() ? it->second : computeAll(node, vrml1);
}

// Post-order over the node graph with an explicit stack: USE chains can be far deeper
// than the parser's nesting limit, which only bounds each definition.
uint64_t InstancingBudget::computeAll(const Node& root, bool vrml1)
{
    struct Pending {
        const Node* node;
        bool expanded;
    };
    std::vector<Pending> stack{{&root, false}};
    while (!stack.empty()) {
        Pending& top = stack.back();
        const Node* n = top.node;
        if (triangles_.count(n)) {
            stack.pop_back();
            continue;
        }
        const std::vector<Ref> refs = children(*n, vrml1);
        if (!top.expanded) {
            top.expanded = true;
            for (const Ref& r : refs)
                if (!triangles_.count(r.node)) stack.push_back({r.node, false});
            continue;
        }
        uint64_t total = ownTriangles(*n, vrml1);
        for (const Ref& r : refs) {
            const auto found = triangles_.find(r.node);
            if (found != triangles_.end()) total = saturatingAdd(total, found->second);
        }
        triangles_[n] = total;
        stack.pop_back();
    }
    return triangles_[&root];
}

std::string InstancingBudget::check(const std::vector<NodePtr>& nodes, const std::vector<UseSite>& useSites,
                                    bool vrml1, uint64_t used, uint64_t limit)
{
    std::vector<Ref> refs = nonNull(writtenList(nodes, useSites));
    // Follow the reference that crosses the limit down to a USE (the expansion to blame)
    // or to a node that emits the triangles itself.
    std::optional<Ref> parent;
    for (;;) {
        const Ref* crossing = nullptr;
        for (const Ref& r : refs) {
            const uint64_t n = triangles(*r.node, vrml1);
            if (n <= limit - std::min(used, limit)) {
                used += n;
                continue;
            }
            crossing = &r;
            break;
        }
        if (!crossing) return parent ? exceedsError(*parent, limit) : std::string();
        std::vector<Ref> below = crossing->useWhere ? std::vector<Ref>{} : children(*crossing->node, vrml1);
        if (crossing->useWhere || below.empty() || ownTriangles(*crossing->node, vrml1) > 0)
            return exceedsError(*crossing, limit);
        parent = *crossing;
        refs = std::move(below);
    }
}

}  // namespace cadlod::vrml
