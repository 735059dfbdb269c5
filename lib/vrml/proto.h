// PROTO and EXTERNPROTO declarations and their instantiation: an instance becomes a
// deep copy of the proto body's first node with every `IS` field replaced by the
// instance's value (or the declared default). Nodes passed in from the instance are
// shared, not copied; DEF/USE sharing inside the body is preserved in the copy.
#pragma once

#include "vrml/node.h"

#include <cstddef>
#include <string>
#include <vector>

namespace cadlod::vrml {

struct ProtoDecl {
    std::string name;
    std::vector<Field> interface;  // declared fields with their defaults
    std::vector<NodePtr> body;
    bool external = false;
    std::vector<std::string> urls;           // EXTERNPROTO only
    std::shared_ptr<ProtoDecl> resolved;      // EXTERNPROTO: the fetched PROTO
    bool resolveAttempted = false;
    size_t instanceNodes = 0;  // cached instanceNodeCount(); 0 until computed
};

// How many nodes one instance copies: the distinct nodes of the body's first node, not
// counting the instance's own node values, which are shared. Nested PROTO instances in a
// body are already copies, so this grows with every level of nesting.
size_t instanceNodeCount(ProtoDecl& proto);

// `instance` holds the fields given at the use site. Returns null when the body is empty.
NodePtr instantiateProto(const ProtoDecl& proto, const Node& instance);

}  // namespace cadlod::vrml
