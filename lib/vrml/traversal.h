// The traversal rules of VRML97 and VRML 1.0, stated once: which children of a grouping
// node (groups, Transform, Separator, Switch, LOD, ...) the scene evaluation follows. The
// evaluators (evaluator97.cpp, evaluator10.cpp) walk these children, and the instancing
// budget (instancing_budget.cpp) counts triangles over exactly the same children, so it
// bounds what evaluation will emit.
#pragma once

#include "vrml/node.h"

#include <string>
#include <vector>

namespace cadlod::vrml {

// A child as written: `node` points into the parent's node list and may hold null (a NULL
// entry, which emits nothing); `useWhere` is where it was written as USE, or null;
// `index` is its position in that list (the evaluators' paths name it).
struct ChildRef {
    const NodePtr* node = nullptr;
    const std::string* useWhere = nullptr;
    size_t index = 0;
};

struct TraversedChildren {
    // Every child in order (groups, Separator, Switch whichChild -3), or the one chosen
    // child of a Switch or LOD (none when the choice is out of range).
    bool chosen = false;
    std::vector<ChildRef> children;
};

// A node list as written (e.g. a file's roots), every entry with its USE site.
std::vector<ChildRef> writtenList(const std::vector<NodePtr>& nodes, const std::vector<UseSite>& useSites);

// The children evaluation follows below `n`; none for nodes that are not grouping nodes.
// VRML97: Transform, CADPart and the groups of isGroupNode97 follow `children` (then any
// VRML 1.0-style children); Switch follows choice[whichChoice] (or children[...]); LOD
// follows level[0] (or children[0]). VRML 1.0: Separator, TransformSeparator, Group and
// WWWAnchor follow their children; Switch follows child whichChild, or all for -3; LOD
// follows its first child.
TraversedChildren traversedChildren(const Node& n, bool vrml1);

// VRML97 grouping nodes whose `children` are followed as they are (Transform aside).
bool isGroupNode97(const std::string& type);

}  // namespace cadlod::vrml
