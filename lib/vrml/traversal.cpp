#include "vrml/traversal.h"

#include "vrml/transform.h"

#include <algorithm>
#include <set>

namespace cadlod::vrml {
namespace {

const std::string* useSiteAt(const std::vector<UseSite>& sites, size_t index)
{
    const auto it = std::lower_bound(sites.begin(), sites.end(), index,
                                     [](const UseSite& s, size_t i) { return s.index < i; });
    return it != sites.end() && it->index == index ? &it->where : nullptr;
}

void append(const std::vector<NodePtr>& nodes, const std::vector<UseSite>& sites, std::vector<ChildRef>& out)
{
    for (size_t i = 0; i < nodes.size(); ++i) out.push_back({&nodes[i], useSiteAt(sites, i), out.size()});
}

const FieldValue* nodesField(const Node& n, const char* name)
{
    const FieldValue* v = n.field(name);
    return v && v->kind == FieldValue::Kind::Nodes ? v : nullptr;
}

// VRML97: the field's nodes, then the node's VRML 1.0-style children.
std::vector<ChildRef> fieldAndChildren(const Node& n, const char* name)
{
    std::vector<ChildRef> refs;
    if (const FieldValue* v = nodesField(n, name)) append(v->nodes, v->useSites, refs);
    append(n.children, n.childUseSites, refs);
    return refs;
}

std::vector<ChildRef> children10(const Node& n)
{
    std::vector<ChildRef> refs;
    append(n.children, n.childUseSites, refs);
    return refs;
}

TraversedChildren all(std::vector<ChildRef> refs) { return {false, std::move(refs)}; }

TraversedChildren chosen(const std::vector<ChildRef>& refs, int64_t index)
{
    TraversedChildren t{true, {}};
    if (index >= 0 && size_t(index) < refs.size()) t.children.push_back(refs[size_t(index)]);
    return t;
}

}  // namespace

std::vector<ChildRef> writtenList(const std::vector<NodePtr>& nodes, const std::vector<UseSite>& useSites)
{
    std::vector<ChildRef> refs;
    append(nodes, useSites, refs);
    return refs;
}

bool isGroupNode97(const std::string& type)
{
    static const std::set<std::string> types{"Group", "Billboard", "Anchor", "Collision", "StaticGroup",
                                             "CADAssembly", "CADLayer", "CADFace"};
    return types.count(type) > 0;
}

TraversedChildren traversedChildren(const Node& n, bool vrml1)
{
    const std::string& t = n.type;
    if (!vrml1) {
        if (t == "Transform" || t == "CADPart" || isGroupNode97(t)) return all(fieldAndChildren(n, "children"));
        if (t == "Switch")
            return chosen(fieldAndChildren(n, nodesField(n, "choice") ? "choice" : "children"),
                          intField(n, "whichChoice", -1));
        if (t == "LOD") return chosen(fieldAndChildren(n, nodesField(n, "level") ? "level" : "children"), 0);
        return {};
    }
    if (t == "Separator" || t == "TransformSeparator" || t == "Group" || t == "WWWAnchor") return all(children10(n));
    if (t == "Switch") {
        const int32_t which = intField(n, "whichChild", -1);
        return which == -3 ? all(children10(n)) : chosen(children10(n), which);
    }
    if (t == "LOD") return chosen(children10(n), 0);
    return {};
}

}  // namespace cadlod::vrml
