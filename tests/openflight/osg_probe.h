// What OpenSceneGraph (osgdb_openflight, an independent OpenFlight reader) makes of a
// .flt file: its LOD nodes (ranges, centers), the triangles under each (positions,
// normals, colors), and the names of its group nodes.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace cadlod::test {

struct OsgTriangle {
    std::array<std::array<float, 3>, 3> position{};
    std::array<std::array<float, 3>, 3> normal{};
    bool hasNormals = false;
    std::array<float, 4> color{1, 1, 1, 1};  // the first corner's
    std::array<std::array<float, 4>, 3> cornerColor{};
    bool hasCornerColors = false;  // a colour per vertex (else one for the whole geometry)
};

struct OsgLodChild {
    float minRange = 0, maxRange = 0;
    std::array<float, 3> center{};
    std::vector<OsgTriangle> triangles;
    std::vector<std::string> names;  // group/node names under this child
};

struct OsgProbe {
    bool loaded = false;
    std::vector<OsgLodChild> lods;            // one entry per LOD child, in traversal order
    std::vector<OsgTriangle> outsideLods;     // triangles not under any LOD
    std::vector<std::string> names;           // every named node
    bool cullsBackFaces = false;              // some state set enables back-face culling
    bool disablesCulling = false;             // some state set disables GL_CULL_FACE
};

// `options` as osgDB takes them, e.g. "noUnitsConversion" or "preserveFace".
OsgProbe probeWithOsg(const std::string& path, const std::string& options = "");

}  // namespace cadlod::test
