#include "vrml/proto.h"

#include <unordered_map>
#include <unordered_set>

namespace cadlod::vrml {
namespace {

class ProtoCopier {
public:
    ProtoCopier(const ProtoDecl& proto, const Node& instance) : proto_(proto), instance_(instance) {}

    NodePtr copy(const NodePtr& source)
    {
        if (!source) return nullptr;
        auto done = copies_.find(source.get());
        if (done != copies_.end()) return done->second;
        auto n = std::make_shared<Node>();
        copies_[source.get()] = n;
        n->type = source->type;
        n->defName = source->defName;
        n->where = source->where;
        n->fields.reserve(source->fields.size());
        for (const Field& f : source->fields) n->fields.push_back({f.name, copyValue(f.value)});
        for (const NodePtr& c : source->children) n->children.push_back(copy(c));
        n->childUseSites = source->childUseSites;
        return n;
    }

private:
    FieldValue copyValue(const FieldValue& v)
    {
        if (v.kind == FieldValue::Kind::IsRef) return lookup(v.strings.empty() ? std::string() : v.strings[0]);
        if (v.kind != FieldValue::Kind::Nodes) return v;  // arrays are shared, never copied
        FieldValue out = v;
        for (NodePtr& n : out.nodes) n = copy(n);
        return out;
    }

    FieldValue lookup(const std::string& name) const
    {
        if (const FieldValue* given = instance_.field(name.c_str())) return *given;
        for (const Field& f : proto_.interface)
            if (f.name == name) return f.value;
        return {};
    }

    const ProtoDecl& proto_;
    const Node& instance_;
    std::unordered_map<const Node*, NodePtr> copies_;
};

size_t countDistinctNodes(const Node& root)
{
    std::unordered_set<const Node*> seen{&root};
    std::vector<const Node*> pending{&root};
    const auto visit = [&](const NodePtr& n) {
        if (n && seen.insert(n.get()).second) pending.push_back(n.get());
    };
    while (!pending.empty()) {
        const Node* n = pending.back();
        pending.pop_back();
        for (const Field& f : n->fields)
            if (f.value.kind == FieldValue::Kind::Nodes)
                for (const NodePtr& c : f.value.nodes) visit(c);
        for (const NodePtr& c : n->children) visit(c);
    }
    return seen.size();
}

}  // namespace

size_t instanceNodeCount(ProtoDecl& proto)
{
    if (proto.instanceNodes == 0)
        for (const NodePtr& n : proto.body)
            if (n) {
                proto.instanceNodes = countDistinctNodes(*n);
                break;
            }
    return proto.instanceNodes;
}

NodePtr instantiateProto(const ProtoDecl& proto, const Node& instance)
{
    for (const NodePtr& n : proto.body)
        if (n) return ProtoCopier(proto, instance).copy(n);
    return nullptr;
}

}  // namespace cadlod::vrml
