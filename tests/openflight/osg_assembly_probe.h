// What OpenSceneGraph makes of an assembly .flt: what it draws from up close (the LOD
// children whose range starts at 0: every part's finest level), in world
// coordinates (through every MatrixTransform), gathered under each named node on its path;
// the nodes it shares between several parents; the distinct subgraphs below its LOD nodes.
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace cadlod::test {

struct OsgNamedNode {
    std::array<double, 3> min{1e300, 1e300, 1e300}, max{-1e300, -1e300, -1e300};
    std::size_t triangles = 0;  // finest level, in world coordinates
    std::size_t visits = 0;     // times the traversal met a node of this name
};

struct OsgAssemblyProbe {
    bool loaded = false;
    double loadSeconds = 0;
    std::map<std::string, OsgNamedNode> named;
    // The outermost named nodes below the model's root (named after the model) and its
    // clusters: the placements.
    std::map<std::string, OsgNamedNode> placements;
    std::vector<std::array<std::array<double, 3>, 3>> finestTriangles;  // world coordinates
    std::size_t sharedNodes = 0;     // distinct nodes with more than one parent
    std::size_t lodNodes = 0;        // distinct LOD nodes
    std::size_t lodSubgraphs = 0;    // distinct children of LOD nodes
    std::size_t drawables = 0;       // drawables of the finest levels, as drawn
};

// `modelName`: the name of the model's root group (the header's and the root Group's ID).
OsgAssemblyProbe probeAssemblyWithOsg(const std::string& path, const std::string& modelName = "");

}  // namespace cadlod::test
