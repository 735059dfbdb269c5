// Turns one indexed face set (VRML97 IndexedFaceSet, VRML 1.0 IndexedFaceSet, or a
// primitive expressed as one) into triangles of a Part in world coordinates: validates
// and skips bad faces, resolves color/normal/texCoord bindings, triangulates (fan, or
// ear clipping for convex FALSE), computes creaseAngle normals when the file gives none
// (or when asked to), applies ccw and mirrored transforms to the winding.
#pragma once

#include "vrml/diagnostics.h"
#include "vrml/math.h"
#include "vrml/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cadlod::vrml {

struct AttributeSource {
    enum class Binding { None, Overall, PerFace, PerCorner };
    Binding binding = Binding::None;
    const std::vector<float>* values = nullptr;
    int components = 3;
    // PerFace: value index per face (null: the face number).
    // PerCorner: value index per coordIndex position, -1 separators included (null: the
    // running corner number, VRML 1.0 PER_VERTEX).
    const std::vector<int32_t>* index = nullptr;

    size_t valueCount() const { return values ? values->size() / size_t(components) : 0; }
    bool present() const { return binding != Binding::None && valueCount() > 0; }
};

struct FaceSetInput {
    const std::vector<float>* coords = nullptr;      // xyz triples
    const std::vector<int32_t>* coordIndex = nullptr;
    AttributeSource normals, colors, texCoords;      // colors: rgb (3) or rgba (4), 0..1
    bool ccw = true;
    bool convex = true;
    float creaseAngle = 0;
    std::string where;  // file:line:col of the geometry node
};

struct EmitOptions {
    bool recomputeNormals = false;  // ignore file normals, use creaseAngle
};

// Returns the number of triangles appended.
size_t emitFaceSet(const FaceSetInput& in, const Mat4& world, const EmitOptions& options, Part& part,
                   Diagnostics& diag, SceneStats& stats);

}  // namespace cadlod::vrml
