// Placed levels merged, for a cluster's proxies (design.md §5, HLOD): a level made one
// drawable, levels merged per colour as the input of a proxy's simplification, and levels
// appended unchanged into one drawable. Model coordinates throughout; a mirroring placement
// has its triangles turned back so that they still face out.
#pragma once

#include "openflight/lod_model.h"
#include "vrml/math.h"
#include "vrml/part.h"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace cadlod {

// A level as one part named `name` whose vertices carry the colours: one Mesh record, so
// one draw call, however many colours it has (a Mesh record has one colour of its own). A
// vertex where colours meet is written once per colour. A user picks a placement, never
// one colour of a part.
flt::Level asOneDrawable(flt::Level level, const std::string& name);

// A level's draw calls: one per colour of each part (a Mesh record per colour).
std::size_t drawables(const flt::Level& level);

// The parts of some levels, placed, merged into one part per colour about `centre`.
class MergedParts {
public:
    explicit MergedParts(const flt::Vec3d& centre) : centre_(centre) {}

    void add(const flt::Level& level, const flt::Mat4d& m);

    std::size_t triangles() const { return triangles_; }
    std::vector<vrml::Part> take() { return std::move(parts_); }

private:
    void addPart(const flt::Part& part, const flt::Mat4d& m);
    std::size_t partFor(const Rgba& colour);

    static constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();
    flt::Vec3d centre_;
    std::vector<vrml::Part> parts_;
    std::map<Rgba, std::size_t> byColour_;
    std::size_t triangles_ = 0;
};

// Levels placed in the model and appended into one part whose vertices carry the colours:
// one drawable, its pieces unchanged.
class LevelMerger {
public:
    void add(const flt::Level& level, const flt::Mat4d& m);

    bool empty() const { return out_.triangles.empty(); }

    // Null when a piece had colours per face only, which one Mesh record cannot draw.
    bool take(const std::string& name, const flt::Vec3d& centre, flt::Level& level);

private:
    static flt::Vec3f turned(const vrml::Mat4& normalMatrix, const flt::Vec3f& v);

    flt::Part out_;
    bool normals_ = true;
    bool faceColours_ = false;
};

}  // namespace cadlod
