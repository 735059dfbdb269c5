// Parses VRML97 or VRML 1.0 text into node trees. Field values are parsed without a
// node schema (numbers, strings, words, nodes), index fields straight into int arrays.
// PROTO instances are expanded at parse time (the instance becomes a copy of the
// proto body's first node with IS fields substituted); EXTERNPROTO bodies are fetched
// through a callback. ROUTEs are skipped. A syntax error stops parsing with a warning
// and keeps everything read so far (truncated files still give their geometry).
#pragma once

#include "vrml/diagnostics.h"
#include "vrml/node.h"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>

namespace cadlod::vrml {

enum class VrmlVersion { Unknown, V1, V2 };

struct ProtoDecl;
using ProtoTable = std::map<std::string, std::shared_ptr<ProtoDecl>>;

struct ParsedFile {
    VrmlVersion version = VrmlVersion::Unknown;
    std::vector<NodePtr> roots;
    std::vector<UseSite> rootUseSites;  // the roots written as USE
    ProtoTable protos;  // top-level PROTO declarations (used to resolve EXTERNPROTO)
    std::string error;  // fatal: not a VRML file, or PROTO copies beyond their limit
};

// Given an EXTERNPROTO url (relative to the current file) and a proto name, returns its
// declaration, or null.
using ExternProtoResolver = std::function<std::shared_ptr<ProtoDecl>(const std::string& url,
                                                                      const std::string& name)>;

struct ParseOptions {
    int maxDepth = 400;
    // PROTO instances are copies, and a PROTO whose body instantiates another multiplies
    // them: nodes copied in all may not exceed the larger of these (a node with its fields
    // takes ~300 bytes). Exceeding it is a fatal error naming the instance.
    size_t maxProtoCopies = 1'000'000;
    double maxProtoCopiesPerInputByte = 8;
    ExternProtoResolver externProto;
    std::function<void(size_t done, size_t total)> progress;
};

VrmlVersion detectVersion(std::string_view text);

ParsedFile parseVrml(std::string_view text, const std::string& fileName, Diagnostics& diag,
                     const ParseOptions& options = {});

}  // namespace cadlod::vrml
