// VRML scene -> vcglib mesh: copies the neutral scene of the VRML reader (vrml/) into any
// vcglib mesh with per-vertex normal and colour and per-face colour (wedge texture
// coordinates when the mesh has them enabled), with the part table and per-face part ids
// of layer_metadata.h that the simplifier and the OpenFlight exporter read. Coincident
// vertices are welded first (the simplifier needs one connected mesh).
#pragma once

#include "mesh/layer_metadata.h"
#include "vrml/scene.h"
#include "vrml/vertex_welding.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace cadlod::mesh_io {

struct SceneToMeshOptions {
    bool mergeVertices = true;    // weld identical points into one vertex
    float mergeTolerance = 0.0f;  // with mergeVertices: also merge points closer than this (model units)
};

namespace detail {

inline vcg::Color4b toColor(const vrml::Rgba8& c) { return vcg::Color4b(c[0], c[1], c[2], c[3]); }

inline vcg::Color4b toColor(const Rgba& c)
{
    auto b = [](float x) { return (unsigned char)std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f); };
    return vcg::Color4b(b(c[0]), b(c[1]), b(c[2]), b(c[3]));
}

// Index of `texture` in the mesh's texture list (added if new); -1 for none.
template <class Mesh>
short textureIndexOf(Mesh& m, const std::string& texture)
{
    if (texture.empty()) return -1;
    auto it = std::find(m.textures.begin(), m.textures.end(), texture);
    if (it != m.textures.end()) return short(it - m.textures.begin());
    m.textures.push_back(texture);
    return short(m.textures.size() - 1);
}

template <class Face>
void setWedgeTexCoord(Face& f, int k, const vrml::Part& part, uint32_t vertex, short textureIndex)
{
    if (part.texCoords.empty()) {
        f.WT(k) = vcg::TexCoord2f(0, 0);
        f.WT(k).N() = -1;
        return;
    }
    f.WT(k) = vcg::TexCoord2f(part.texCoords[vertex][0], part.texCoords[vertex][1]);
    f.WT(k).N() = textureIndex;
}

}  // namespace detail

inline bool hasTexCoords(const vrml::Scene& scene)
{
    return std::any_of(scene.parts.begin(), scene.parts.end(), [](const vrml::Part& p) { return !p.texCoords.empty(); });
}

// Moves the scene into `m` (each part's arrays are freed once copied, to keep the peak
// memory low); with `welding`, coincident vertices become one vertex whose normal is the
// normalized sum of theirs (the first one's color wins).
template <class Mesh>
void moveScene(vrml::Scene& scene, const vrml::Welding* welding, Mesh& m, vcg::CallBackPos* cb)
{
    using VertexPointer = typename Mesh::VertexPointer;
    using Point = vcg::Point3<typename Mesh::ScalarType>;
    const size_t vertexCount = welding ? welding->weldedCount : scene.vertexCount();
    const size_t base = m.vert.size();
    vcg::tri::Allocator<Mesh>::AddVertices(m, vertexCount);
    auto fi = vcg::tri::Allocator<Mesh>::AddFaces(m, scene.triangleCount());
    std::vector<bool> written(welding ? vertexCount : 0, false);
    auto partOf = facePartHandle(m);
    PartTable& table = partTableHandle(m)();
    table.clear();
    size_t sceneVertex = 0, done = 0;
    const size_t triangleCount = scene.triangleCount();
    const bool wedgeTexCoords = vcg::tri::HasPerWedgeTexCoord(m);
    std::vector<VertexPointer> partVertex;
    for (size_t p = 0; p < scene.parts.size(); ++p) {
        vrml::Part& part = scene.parts[p];
        table.push_back(part);  // its identity
        const vcg::Color4b partColor = detail::toColor(part.color);
        partVertex.resize(part.positions.size());
        for (size_t i = 0; i < part.positions.size(); ++i, ++sceneVertex) {
            const size_t target = welding ? welding->weldedIndex[sceneVertex] : sceneVertex;
            auto& v = m.vert[base + target];
            partVertex[i] = &v;
            const Point normal = part.normals.empty() ? Point(0, 0, 0)
                                                      : Point(part.normals[i][0], part.normals[i][1], part.normals[i][2]);
            if (welding && written[target]) {
                v.N() += normal;
                continue;
            }
            if (welding) written[target] = true;
            v.P() = Point(part.positions[i][0], part.positions[i][1], part.positions[i][2]);
            v.N() = normal;
            v.C() = part.colors.empty() ? partColor : detail::toColor(part.colors[i]);
        }
        const short textureIndex = detail::textureIndexOf(m, part.texture);
        for (size_t t = 0; t < part.triangleCount(); ++t, ++fi) {
            for (int k = 0; k < 3; ++k) {
                const uint32_t local = part.triangles[3 * t + size_t(k)];
                fi->V(k) = partVertex[local];
                if (wedgeTexCoords) detail::setWedgeTexCoord(*fi, k, part, local, textureIndex);
            }
            fi->C() = part.faceColors.empty() ? partColor : detail::toColor(part.faceColors[t]);
            partOf[fi] = int(p);
        }
        done += part.triangleCount();
        part = vrml::Part{};
        if (cb) cb(60 + int(30.0 * double(done) / double(std::max<size_t>(1, triangleCount))), "Building mesh");
    }
    if (welding)
        for (size_t i = base; i < m.vert.size(); ++i) m.vert[i].N().Normalize();
}

// Merges vertices closer than `tolerance`; returns how many were merged away.
template <class Mesh>
int mergeCloseVertices(Mesh& m, float tolerance)
{
    const int merged = vcg::tri::Clean<Mesh>::MergeCloseVertex(m, tolerance);
    vcg::tri::Allocator<Mesh>::CompactEveryVector(m);
    return merged;
}

struct SceneToMeshStats {
    int mergedVertices = 0;        // vertices welded or merged away
    int facesRepeatingVertex = 0;  // faces removed because welding gave them a vertex twice
};

// Deletes the faces that use one vertex twice (welding rounded coordinates can make them:
// two corners of a sliver land on one point). They have no area and are not part of the
// surface: a closed mesh stays closed without them. MeshLab's load path would remove them
// anyway, with a modal "degenerated faces. Corrected." dialog. Returns how many.
template <class Mesh>
int removeFacesRepeatingAVertex(Mesh& m)
{
    int removed = 0;
    for (auto& f : m.face)
        if (!f.IsD() && (f.V(0) == f.V(1) || f.V(1) == f.V(2) || f.V(2) == f.V(0))) {
            vcg::tri::Allocator<Mesh>::DeleteFace(m, f);
            ++removed;
        }
    if (removed > 0) vcg::tri::Allocator<Mesh>::CompactFaceVector(m);
    return removed;
}

// The whole conversion: welding (and merging within the tolerance), the scene moved into
// `m` (the scene's parts are emptied), faces repeating a vertex removed, face normals and
// the bounding box. Returns the number of vertices merged away; `stats` (optional) also
// gets the faces removed. Progress runs from 60 to 90 %.
template <class Mesh>
int sceneToMesh(vrml::Scene& scene, Mesh& m, const SceneToMeshOptions& options, vcg::CallBackPos* cb = nullptr,
                SceneToMeshStats* stats = nullptr)
{
    const size_t sceneVertices = scene.vertexCount();
    vrml::Welding welding;
    if (options.mergeVertices) welding = vrml::weldCoincidentVertices(scene);
    int merged = options.mergeVertices ? int(sceneVertices - welding.weldedCount) : 0;
    moveScene(scene, options.mergeVertices ? &welding : nullptr, m, cb);
    welding = {};
    if (options.mergeVertices && options.mergeTolerance > 0) merged += mergeCloseVertices(m, options.mergeTolerance);
    const int repeating = removeFacesRepeatingAVertex(m);
    if (stats) *stats = {merged, repeating};
    vcg::tri::UpdateNormal<Mesh>::PerFaceNormalized(m);
    vcg::tri::UpdateBounding<Mesh>::Box(m);
    return merged;
}

}  // namespace cadlod::mesh_io
