// OpenFlight LOD model -> vcglib mesh: one level of a model the OpenFlight reader returned
// becomes a mesh with per-vertex normals and texture coordinates (when every part has them),
// face colours from the part colours, and the part table and per-face part ids of
// layer_metadata.h. The mesh needs per-face colour, and per-vertex normal and texture
// coordinate when the level has them (enable them first on a mesh where they are optional).
#pragma once

#include "mesh/layer_metadata.h"
#include "openflight/lod_model.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>

namespace cadlod::mesh_io {

// True when every part of a non-empty level has them.
inline bool levelHasNormals(const flt::Level& level)
{
    return !level.parts.empty() &&
           std::all_of(level.parts.begin(), level.parts.end(), [](const flt::Part& p) { return p.hasNormals(); });
}

inline bool levelHasUvs(const flt::Level& level)
{
    return !level.parts.empty() &&
           std::all_of(level.parts.begin(), level.parts.end(), [](const flt::Part& p) { return p.hasUvs(); });
}

namespace detail {

inline vcg::Color4b toColor4b(const flt::Rgba& c)
{
    auto byte = [](float v) { return static_cast<unsigned char>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    return vcg::Color4b(byte(c[0]), byte(c[1]), byte(c[2]), byte(c[3]));
}

}  // namespace detail

// Appends `level` to `m` and sets its part table (one entry per part, in order).
template <class Mesh>
void levelToMesh(const flt::Level& level, Mesh& m)
{
    using Point = vcg::Point3<typename Mesh::ScalarType>;
    const bool normals = levelHasNormals(level);
    const bool uvs = levelHasUvs(level);
    auto facePart = facePartHandle(m);
    PartTable table;
    for (std::size_t p = 0; p < level.parts.size(); ++p) {
        const flt::Part& part = level.parts[p];
        table.push_back(part);  // its identity
        auto v = vcg::tri::Allocator<Mesh>::AddVertices(m, part.positions.size());
        const std::size_t firstVertex = std::size_t(vcg::tri::Index(m, &*v));
        for (std::size_t i = 0; i < part.positions.size(); ++i, ++v) {
            v->P() = Point(float(part.positions[i][0]), float(part.positions[i][1]), float(part.positions[i][2]));
            if (normals)
                v->N() = Point(part.normals[i][0], part.normals[i][1], part.normals[i][2]);
            if (uvs)
                v->T() = vcg::TexCoord2f(part.uvs[i][0], part.uvs[i][1]);
            v->C() = detail::toColor4b(part.hasVertexColors() ? part.vertexColors[i] : part.color);
        }
        auto f = vcg::tri::Allocator<Mesh>::AddFaces(m, part.triangles.size());
        for (std::size_t i = 0; i < part.triangles.size(); ++i) {
            const flt::Triangle& t = part.triangles[i];
            for (int k = 0; k < 3; ++k)
                f->V(k) = &m.vert[firstVertex + t[k]];
            f->C() = detail::toColor4b(part.colorOf(i));
            facePart[f] = int(p);
            ++f;
        }
    }
    partTableHandle(m)() = table;
    vcg::tri::UpdateBounding<Mesh>::Box(m);
}

}  // namespace cadlod::mesh_io
