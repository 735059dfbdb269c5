#include "assembly/merged_levels.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace cadlod {
namespace {

// The colour triangle t is drawn with: its vertices' where they carry one (all three alike,
// asOneDrawable), else its face's.
const Rgba& triangleColour(const flt::Part& part, std::size_t t)
{
    return part.hasVertexColors() ? part.vertexColors[part.triangles[t][0]] : part.colorOf(t);
}

}  // namespace

flt::Level asOneDrawable(flt::Level level, const std::string& name)
{
    if (level.parts.size() < 2 && (level.parts.empty() || !level.parts.front().hasTriangleColors()))
        return level;
    flt::Part one;
    one.name = name;
    one.color = level.parts.front().color;
    const bool normals = std::all_of(level.parts.begin(), level.parts.end(),
                                     [](const flt::Part& p) { return p.hasNormals(); });
    for (const flt::Part& part : level.parts) {
        std::map<std::pair<std::uint32_t, Rgba>, std::uint32_t> index;
        for (std::size_t t = 0; t < part.triangles.size(); ++t) {
            const Rgba& colour = triangleColour(part, t);
            flt::Triangle out;
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t v = part.triangles[t][c];
                const auto [at, added] = index.emplace(std::make_pair(v, colour), std::uint32_t(one.positions.size()));
                if (added) {
                    one.positions.push_back(part.positions[v]);
                    one.vertexColors.push_back(colour);
                    if (normals)
                        one.normals.push_back(part.normals[v]);
                }
                out[c] = at->second;
            }
            one.triangles.push_back(out);
        }
    }
    level.parts.assign(1, std::move(one));
    return level;
}

std::size_t drawables(const flt::Level& level)
{
    std::size_t n = 0;
    for (const flt::Part& part : level.parts) {
        if (!part.hasTriangleColors()) {
            ++n;
            continue;
        }
        std::vector<Rgba> colours(part.triangleColors);
        std::sort(colours.begin(), colours.end());
        n += std::size_t(std::unique(colours.begin(), colours.end()) - colours.begin());
    }
    return n;
}

void MergedParts::add(const flt::Level& level, const flt::Mat4d& m)
{
    for (const flt::Part& part : level.parts)
        addPart(part, m);
}

void MergedParts::addPart(const flt::Part& part, const flt::Mat4d& m)
{
    const bool mirrored = flt::mirrors(m);
    std::map<std::size_t, std::vector<std::uint32_t>> remaps;  // per merged part
    for (std::size_t t = 0; t < part.triangles.size(); ++t) {
        const std::size_t target = partFor(triangleColour(part, t));
        std::vector<std::uint32_t>& remap = remaps[target];
        remap.resize(part.positions.size(), kUnset);
        vrml::Part& out = parts_[target];
        flt::Triangle tri = part.triangles[t];
        if (mirrored)
            std::swap(tri[1], tri[2]);
        for (std::uint32_t v : tri) {
            if (remap[v] == kUnset) {
                remap[v] = std::uint32_t(out.positions.size());
                const flt::Vec3d p = flt::transformed(m, part.positions[v]);
                out.positions.push_back({float(p[0] - centre_[0]), float(p[1] - centre_[1]),
                                         float(p[2] - centre_[2])});
            }
            out.triangles.push_back(remap[v]);
        }
        ++triangles_;
    }
}

std::size_t MergedParts::partFor(const Rgba& colour)
{
    const auto found = byColour_.find(colour);
    if (found != byColour_.end())
        return found->second;
    vrml::Part part;
    part.color = colour;
    part.name = "colour " + std::to_string(parts_.size() + 1);
    parts_.push_back(std::move(part));
    return byColour_[colour] = parts_.size() - 1;
}

void LevelMerger::add(const flt::Level& level, const flt::Mat4d& m)
{
    const bool mirrored = flt::mirrors(m);
    vrml::Mat4 placement;
    placement.m = m;
    const vrml::Mat4 normalMatrix = placement.normalMatrix();
    for (const flt::Part& part : level.parts) {
        const auto first = std::uint32_t(out_.positions.size());
        normals_ = normals_ && part.hasNormals();
        for (std::size_t v = 0; v < part.positions.size(); ++v) {
            out_.positions.push_back(flt::transformed(m, part.positions[v]));
            out_.vertexColors.push_back(part.hasVertexColors() ? part.vertexColors[v] : part.color);
            if (normals_)
                out_.normals.push_back(turned(normalMatrix, part.normals[v]));
        }
        for (std::size_t t = 0; t < part.triangles.size(); ++t) {
            flt::Triangle tri = part.triangles[t];
            for (std::uint32_t& v : tri)
                v += first;
            if (mirrored)
                std::swap(tri[1], tri[2]);
            out_.triangles.push_back(tri);
        }
        faceColours_ = faceColours_ || (part.hasTriangleColors() && !part.hasVertexColors());
    }
}

bool LevelMerger::take(const std::string& name, const flt::Vec3d& centre, flt::Level& level)
{
    if (faceColours_)
        return false;
    if (!normals_)
        out_.normals.clear();
    out_.name = name;
    if (!out_.vertexColors.empty())
        out_.color = out_.vertexColors.front();
    level.parts.assign(1, std::move(out_));
    level.center = centre;
    return true;
}

flt::Vec3f LevelMerger::turned(const vrml::Mat4& normalMatrix, const flt::Vec3f& v)
{
    const vrml::Vec3 n = normalMatrix.transformVector({v[0], v[1], v[2]});
    const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
    const double k = length > 0 ? 1.0 / length : 1.0;
    return {float(n.x * k), float(n.y * k), float(n.z * k)};
}

}  // namespace cadlod
