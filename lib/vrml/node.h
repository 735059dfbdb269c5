// Parsed VRML nodes, version-neutral: a type name, an optional DEF name, fields with
// generically parsed values and (VRML 1.0) child nodes. USE yields the same shared
// node, so a USE'd Coordinate is shared, never copied.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace cadlod::vrml {

struct Node;
using NodePtr = std::shared_ptr<Node>;

// A node reference written as `USE name`: its index in the node list and where the USE
// is (file:line:col), so that an error about instancing can point at the USE itself.
struct UseSite {
    size_t index = 0;
    std::string where;
};

struct FieldValue {
    enum class Kind { Empty, Floats, Ints, Strings, Words, Nodes, IsRef };
    Kind kind = Kind::Empty;
    std::shared_ptr<std::vector<float>> floats;
    // Where a placement is written (the parser's keepsExactNumbers): the same numbers in
    // double precision. A float holds a site coordinate only coarsely; a placement must hold
    // it as written.
    std::shared_ptr<std::vector<double>> exact;
    std::shared_ptr<std::vector<int32_t>> ints;
    std::vector<std::string> strings;  // Strings, Words (enums, TRUE/FALSE, bit mask parts), IsRef name
    std::vector<NodePtr> nodes;        // null entries for NULL
    std::vector<UseSite> useSites;     // the entries of `nodes` written as USE
};

struct Field {
    std::string name;
    FieldValue value;
};

struct Node {
    std::string type;
    std::string defName;
    int useCount = 0;               // USEs of this DEF: each use is another instance
    std::vector<Field> fields;
    std::vector<NodePtr> children;  // VRML 1.0 children
    std::vector<UseSite> childUseSites;  // the entries of `children` written as USE
    std::string where;              // file:line:col of the type name

    const FieldValue* field(const char* name) const
    {
        for (const Field& f : fields)
            if (f.name == name) return &f.value;
        return nullptr;
    }
};

}  // namespace cadlod::vrml
