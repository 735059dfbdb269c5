// vcglib mesh -> OpenFlight LOD model: one mesh becomes one neutral flt::Level (indexed
// parts with positions, normals and optionally texture coordinates), and the meshes of one
// LOD set (layer_metadata.h's LodLevel records) become one flt::LodModel through
// lod_assembly.h. Vertex normals are always written: OpenFlight geometry is only lit with
// them. A vertex on a crease (crease_fans.h) is written once per smooth fan with the fan's
// normal, so a box's edges stay sharp in a welded or simplified mesh; elsewhere a vertex
// keeps its normal, and one whose normal is zero or not finite gets the area-weighted face
// normal.
#pragma once

#include "mesh/crease_fans.h"
#include "mesh/layer_metadata.h"
#include "openflight/lod_assembly.h"
#include "openflight/lod_model.h"

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace cadlod::mesh_io {

struct LevelOptions {
    std::string label;        // names the parts of a mesh without a part table
    bool faceColors = false;  // write each face's colour (without a part table: parts by face colour)
    bool vertexColors = false;  // write each vertex's colour (drawn instead of the face colours)
    bool uvs = false;         // write per-vertex texture coordinates
};

struct LevelStats {
    std::size_t skippedFaces = 0;  // degenerate faces (a vertex used twice) left out
};

// Faces grouped into parts: by the VRML importer's part attribute when present, else
// by face color when options.faceColors, else one part.
struct PartGrouping {
    std::vector<int> partOfFace;
    std::vector<flt::Part> parts;  // identities only
};

namespace detail {

inline flt::Rgba toRgba(const vcg::Color4b& c)
{
    return {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, c[3] / 255.0f};
}

inline flt::Part partWith(const PartIdentity& identity)
{
    flt::Part part;
    static_cast<PartIdentity&>(part) = identity;
    return part;
}

inline bool usableNormal(const vcg::Point3f& n)
{
    const float len = n.Norm();
    return std::isfinite(len) && len > 1e-12f;
}

}  // namespace detail

// Area-weighted face normals summed at the vertices: the fallback for vertices whose
// stored normal is zero or not finite.
template <class Mesh>
std::vector<vcg::Point3f> fallbackNormals(const Mesh& m)
{
    std::vector<vcg::Point3f> n(m.vert.size(), vcg::Point3f(0, 0, 0));
    for (const auto& f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k)
                n[vcg::tri::Index(m, f.cV(k))] += vcg::Point3f::Construct(vcg::TriangleNormal(f));
    for (vcg::Point3f& v : n)
        if (v.Norm() > 0)
            v.Normalize();
    return n;
}

template <class Mesh>
PartGrouping groupFaces(Mesh& m, const LevelOptions& options)
{
    PartGrouping g;
    g.partOfFace.assign(m.face.size(), 0);
    const std::string& label = options.label;
    if (hasParts(m)) {
        auto facePart = facePartHandle(m);
        const PartTable table = partTableHandle(m)();
        for (const PartIdentity& info : table)
            g.parts.push_back(detail::partWith(info));
        const int unassigned = int(g.parts.size());
        g.parts.push_back(detail::partWith({label + "_unassigned"}));
        for (std::size_t i = 0; i < m.face.size(); ++i) {
            const int p = facePart[i];
            g.partOfFace[i] = p >= 0 && p < unassigned ? p : unassigned;
        }
        return g;
    }
    if (options.faceColors) {
        std::map<std::uint32_t, int> byColor;
        for (std::size_t i = 0; i < m.face.size(); ++i) {
            const vcg::Color4b c = m.face[i].cC();
            const std::uint32_t key = std::uint32_t(c[0]) << 24 | std::uint32_t(c[1]) << 16 | c[2] << 8 | c[3];
            auto [it, added] = byColor.emplace(key, int(g.parts.size()));
            if (added)
                g.parts.push_back(detail::partWith(
                    {label + (byColor.size() > 1 ? "_" + std::to_string(byColor.size()) : ""), detail::toRgba(c)}));
            g.partOfFace[i] = it->second;
        }
        if (!g.parts.empty())
            return g;
    }
    g.parts.push_back(detail::partWith({label}));
    return g;
}

// The faces of each part, in mesh order; deleted faces left out.
template <class Mesh>
std::vector<std::vector<std::size_t>> facesOfParts(const Mesh& m, const PartGrouping& g)
{
    std::vector<std::vector<std::size_t>> faces(g.parts.size());
    for (std::size_t i = 0; i < m.face.size(); ++i)
        if (!m.face[i].IsD())
            faces[std::size_t(g.partOfFace[i])].push_back(i);
    return faces;
}

// One mesh as one neutral level: indexed parts with positions, normals and (optionally)
// texture coordinates; degenerate faces are skipped and counted. The parts are written one
// after another, so that one index of the mesh's vertices serves them all: a mesh of
// thousands of parts (an expanded assembly) would need thousands of such indices at once.
template <class Mesh>
flt::Level meshToLevel(Mesh& m, const LevelOptions& options, LevelStats& stats)
{
    PartGrouping g = groupFaces(m, options);
    const std::vector<vcg::Point3f> fallback = fallbackNormals(m);
    const CreaseFans fans(m);
    std::vector<std::int64_t> index(m.vert.size(), -1);  // in the part being written
    std::vector<std::size_t> indexed;                      // the vertices set in `index`
    std::unordered_map<std::uint32_t, std::int64_t> fanIndex;
    const std::vector<std::vector<std::size_t>> partFaces = facesOfParts(m, g);
    for (std::size_t p = 0; p < g.parts.size(); ++p) {
        flt::Part& part = g.parts[p];
        for (const std::size_t i : partFaces[p]) {
            const auto& f = m.face[i];
            if (f.cV(0) == f.cV(1) || f.cV(1) == f.cV(2) || f.cV(0) == f.cV(2)) {
                ++stats.skippedFaces;
                continue;
            }
            flt::Triangle tri;
            for (int k = 0; k < 3; ++k) {
                const std::size_t vi = vcg::tri::Index(m, f.cV(k));
                // A vertex on a crease is written once per smooth fan, with the fan's normal;
                // elsewhere once, with its own normal (the file's, or the mesh's).
                const bool onCrease = fans.onCrease(vi);
                const std::uint32_t fan = fans.fanOf(i, k);
                std::int64_t& written = onCrease ? fanIndex.try_emplace(fan, -1).first->second : index[vi];
                if (written < 0) {
                    written = std::int64_t(part.positions.size());
                    if (!onCrease)
                        indexed.push_back(vi);
                    const auto& v = m.vert[vi];
                    part.positions.push_back({double(v.cP()[0]), double(v.cP()[1]), double(v.cP()[2])});
                    const vcg::Point3f stored = vcg::Point3f::Construct(v.cN());
                    vcg::Point3f n = onCrease && detail::usableNormal(fans.normal(fan)) ? fans.normal(fan)
                                     : detail::usableNormal(stored)                    ? stored
                                                                                       : fallback[vi];
                    if (n.Norm() > 0)
                        n.Normalize();
                    part.normals.push_back({n[0], n[1], n[2]});
                    if (options.uvs)
                        part.uvs.push_back({float(v.cT().U()), float(v.cT().V())});
                    if (options.vertexColors)
                        part.vertexColors.push_back(detail::toRgba(v.cC()));
                }
                tri[k] = std::uint32_t(written);
            }
            part.triangles.push_back(tri);
            if (options.faceColors)
                part.triangleColors.push_back(detail::toRgba(f.cC()));
        }
        for (const std::size_t vi : indexed)
            index[vi] = -1;
        indexed.clear();
        fanIndex.clear();
    }
    flt::Level level;
    for (flt::Part& p : g.parts) {
        if (p.triangles.empty())
            continue;
        // Faces of one colour: that colour is the part's, no list needed.
        const bool uniform = std::all_of(p.triangleColors.begin(), p.triangleColors.end(),
                                         [&](const flt::Rgba& c) { return c == p.triangleColors.front(); });
        if (!p.triangleColors.empty() && uniform) {
            p.color = p.triangleColors.front();
            p.triangleColors.clear();
        }
        level.parts.push_back(std::move(p));
    }
    return level;
}

// A mesh that may belong to an LOD set, with the options its level is written with.
template <class Mesh>
struct LodLayer {
    Mesh* mesh = nullptr;
    LevelOptions options;
};

// Every mesh in `layers` whose LodLevel record belongs to set `setId`, as one LOD model
// (finest level first, each with its switch range and center). False, with `error`, when
// the set is not usable (flt::assembleLodSet says why).
template <class Mesh>
bool lodSetToModel(const std::vector<LodLayer<Mesh>>& layers, int setId, flt::LodModel& model, LevelStats& stats,
                   std::string& error)
{
    std::vector<flt::LodSetMember> members;
    for (const LodLayer<Mesh>& layer : layers) {
        if (!layer.mesh || !hasLodLevel(*layer.mesh))
            continue;
        const LodLevel info = lodLevelHandle(*layer.mesh)();
        if (info.setId != setId)
            continue;
        flt::LodSetMember member;
        member.setId = info.setId;
        member.level = info.level;
        member.geometry = meshToLevel(*layer.mesh, layer.options, stats);
        member.geometry.switchIn = info.switchIn;
        member.geometry.switchOut = info.switchOut;
        member.geometry.center = info.center;
        members.push_back(std::move(member));
    }
    return flt::assembleLodSet(std::move(members), setId, model, error);
}

}  // namespace cadlod::mesh_io
