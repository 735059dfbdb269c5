#include "vrml/face_set_emitter.h"

#include "vrml/triangulate.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cadlod::vrml {
namespace {

using Binding = AttributeSource::Binding;

struct Corner {
    int32_t coord;
    int32_t position;  // in coordIndex
    int32_t sequence;  // running corner number
};

struct Face {
    uint32_t firstCorner;
    uint32_t cornerCount;
    int32_t number;  // face number in coordIndex order, skipped faces included
};

// A per-coordinate slot table that needs no clearing between face sets.
class CoordTable {
public:
    void reset(size_t size)
    {
        if (stamp_.size() < size) {
            stamp_.resize(size, 0);
            value_.resize(size, -1);
        }
        if (++generation_ == 0) {
            std::fill(stamp_.begin(), stamp_.end(), 0);
            generation_ = 1;
        }
    }
    int32_t get(size_t i) const { return stamp_[i] == generation_ ? value_[i] : -1; }
    void set(size_t i, int32_t v)
    {
        stamp_[i] = generation_;
        value_[i] = v;
    }

private:
    std::vector<uint32_t> stamp_;
    std::vector<int32_t> value_;
    uint32_t generation_ = 0;
};

// Resolves the value index of an attribute for one corner of one face; -1 when invalid.
long valueIndex(const AttributeSource& a, const Corner& c, const Face& f)
{
    long i = -1;
    switch (a.binding) {
    case Binding::None: return -1;
    case Binding::Overall: i = 0; break;
    case Binding::PerFace:
        if (!a.index) i = f.number;
        else if (size_t(f.number) < a.index->size()) i = (*a.index)[size_t(f.number)];
        break;
    case Binding::PerCorner:
        if (!a.index) i = c.sequence;
        else if (size_t(c.position) < a.index->size()) i = (*a.index)[size_t(c.position)];
        break;
    }
    return i >= 0 && size_t(i) < a.valueCount() ? i : -1;
}

Vec3 coordAt(const std::vector<float>& coords, int32_t i)
{
    const float* p = coords.data() + size_t(i) * 3;
    return {p[0], p[1], p[2]};
}

Rgba8 toRgba8(const AttributeSource& a, long i)
{
    const float* v = a.values->data() + size_t(i) * size_t(a.components);
    auto b = [](float x) { return uint8_t(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); };
    return {b(v[0]), b(v[1]), b(v[2]), a.components > 3 ? b(v[3]) : uint8_t(255)};
}

Rgba8 partRgba8(const Part& part)
{
    auto b = [](float x) { return uint8_t(std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f)); };
    return {b(part.color[0]), b(part.color[1]), b(part.color[2]), b(part.color[3])};
}

class FaceSetEmitter {
public:
    FaceSetEmitter(const FaceSetInput& in, const Mat4& world, const EmitOptions& options, Part& part,
                   Diagnostics& diag, SceneStats& stats, CoordTable& vertexAtCoord, CoordTable& adjacency)
        : in_(in), world_(world), normalMatrix_(world.normalMatrix()), options_(options), part_(part),
          diag_(diag), stats_(stats), vertexAtCoord_(vertexAtCoord), adjacency_(adjacency)
    {
    }

    size_t run()
    {
        if (!in_.coords || !in_.coordIndex) return 0;
        markPlaceablePoints();
        collectFaces();
        if (faces_.empty()) return 0;
        computeCornerNormals();
        return emitTriangles();
    }

private:
    bool cornerAttributesValid(const Corner& c, const Face& f) const
    {
        for (const AttributeSource* a : {&in_.normals, &in_.colors, &in_.texCoords})
            if (a->present() && valueIndex(*a, c, f) < 0) return false;
        return true;
    }

    // A color/normal/texCoord index out of range keeps the face (its geometry is fine)
    // with a fallback attribute: face normal, part color, texture origin.
    void warnBadAttributeIndex(const Face& f)
    {
        if (badAttributeWarned_) return;
        badAttributeWarned_ = true;
        diag_.warn("bad attribute index", in_.where,
                   "face " + std::to_string(f.number) +
                       ": color/normal/texCoord index out of range (fallback used; first of this face set)");
    }

    void skipFace(const Face& f, const char* kind, const std::string& why)
    {
        ++stats_.skippedFaces;
        diag_.warn(kind, in_.where, "face " + std::to_string(f.number) + " skipped: " + why);
    }

    // A point that is NaN or infinite in the file, or beyond float range once transformed,
    // cannot be placed: faces using it are skipped like faces with a bad index.
    void markPlaceablePoints()
    {
        const size_t coordCount = in_.coords->size() / 3;
        placeable_.assign(coordCount, 1);
        const double limit = double(std::numeric_limits<float>::max());
        for (size_t i = 0; i < coordCount; ++i) {
            const Vec3 p = world_.transformPoint(coordAt(*in_.coords, int32_t(i)));
            placeable_[i] = std::fabs(p.x) <= limit && std::fabs(p.y) <= limit && std::fabs(p.z) <= limit;
        }
    }

    void collectFaces()
    {
        const std::vector<int32_t>& idx = *in_.coordIndex;
        const size_t coordCount = in_.coords->size() / 3;
        faces_.reserve(idx.size() / 3);
        corners_.reserve(idx.size());
        int32_t faceNumber = 0, sequence = 0;
        size_t start = 0;
        while (start < idx.size()) {
            size_t end = start;
            while (end < idx.size() && idx[end] != -1) ++end;  // other negatives: bad index
            Face f{uint32_t(corners_.size()), 0, faceNumber};
            bool bad = false;
            for (size_t k = start; k < end; ++k) {
                const Corner c{idx[k], int32_t(k), sequence++};
                if (size_t(c.coord) >= coordCount) {
                    if (!bad)
                        skipFace(f, "bad index",
                                 "coordIndex[" + std::to_string(k) + "] = " + std::to_string(c.coord) + " out of range");
                    bad = true;
                    continue;
                }
                if (!placeable_[size_t(c.coord)]) {
                    if (!bad)
                        skipFace(f, "bad coordinate",
                                 "point " + std::to_string(c.coord) + " is NaN, infinite or beyond float range");
                    bad = true;
                    continue;
                }
                if (!bad && !cornerAttributesValid(c, f)) warnBadAttributeIndex(f);
                if (f.cornerCount > 0 && corners_.back().coord == c.coord) continue;  // repeated vertex
                corners_.push_back(c);
                ++f.cornerCount;
            }
            if (f.cornerCount > 1 && corners_[f.firstCorner].coord == corners_.back().coord) {
                corners_.pop_back();
                --f.cornerCount;
            }
            if (!bad && f.cornerCount < 3 && end > start) {
                ++stats_.skippedFaces;
                diag_.warn("degenerate face", in_.where,
                           "face " + std::to_string(faceNumber) + " skipped: fewer than 3 distinct vertices");
                bad = true;
            }
            if (bad || f.cornerCount < 3) corners_.resize(f.firstCorner);
            else faces_.push_back(f);
            if (end > start) ++faceNumber;
            start = end + 1;
        }
    }

    Vec3 faceNormal(const Face& f)
    {
        polygon_.clear();
        for (uint32_t k = 0; k < f.cornerCount; ++k)
            polygon_.push_back(coordAt(*in_.coords, corners_[f.firstCorner + k].coord));
        return newellNormal(polygon_);
    }

    bool useFileNormals() const { return in_.normals.present() && !options_.recomputeNormals; }

    Vec3f toWorldNormal(const Vec3& local) const
    {
        const Vec3 n = normalized(normalMatrix_.transformVector(local));
        return {float(n.x), float(n.y), float(n.z)};
    }

    // World-space unit normal per corner. File normals are transformed once per value,
    // not once per corner.
    void computeCornerNormals()
    {
        cornerNormals_.assign(corners_.size(), Vec3f{0, 0, 0});
        if (useFileNormals()) {
            std::vector<Vec3f> world(in_.normals.valueCount());
            for (size_t i = 0; i < world.size(); ++i) world[i] = toWorldNormal(coordAt(*in_.normals.values, int32_t(i)));
            for (const Face& f : faces_)
                for (uint32_t k = 0; k < f.cornerCount; ++k) {
                    const long i = valueIndex(in_.normals, corners_[f.firstCorner + k], f);
                    cornerNormals_[f.firstCorner + k] = i >= 0 ? world[size_t(i)] : toWorldNormal(faceNormal(f));
                }
            return;
        }
        const double sign = in_.ccw ? 1.0 : -1.0;
        std::vector<Vec3> areaNormals(faces_.size()), unitNormals(faces_.size());
        for (size_t i = 0; i < faces_.size(); ++i) {
            areaNormals[i] = faceNormal(faces_[i]) * sign;
            unitNormals[i] = normalized(areaNormals[i]);
        }
        if (in_.creaseAngle <= 1e-6f) {
            for (size_t i = 0; i < faces_.size(); ++i) {
                const Vec3f n = toWorldNormal(unitNormals[i]);
                for (uint32_t k = 0; k < faces_[i].cornerCount; ++k) cornerNormals_[faces_[i].firstCorner + k] = n;
            }
            return;
        }
        smoothAcrossCreases(areaNormals, unitNormals);
    }

    void smoothAcrossCreases(const std::vector<Vec3>& areaNormals, const std::vector<Vec3>& unitNormals)
    {
        const double cosCrease = std::cos(std::min<double>(in_.creaseAngle, M_PI));
        std::vector<int32_t> cornerFace(corners_.size()), nextAtCoord(corners_.size(), -1);
        adjacency_.reset(in_.coords->size() / 3);
        for (size_t i = 0; i < faces_.size(); ++i)
            for (uint32_t k = 0; k < faces_[i].cornerCount; ++k) {
                const uint32_t c = faces_[i].firstCorner + k;
                cornerFace[c] = int32_t(i);
                nextAtCoord[c] = adjacency_.get(size_t(corners_[c].coord));
                adjacency_.set(size_t(corners_[c].coord), int32_t(c));
            }
        constexpr int kMaxNeighbours = 512;  // hubs of huge fans: keep the face normal
        for (size_t c = 0; c < corners_.size(); ++c) {
            const Vec3& own = unitNormals[size_t(cornerFace[c])];
            Vec3 sum;
            int visited = 0;
            for (int32_t d = adjacency_.get(size_t(corners_[c].coord)); d >= 0 && visited < kMaxNeighbours;
                 d = nextAtCoord[size_t(d)], ++visited) {
                const size_t g = size_t(cornerFace[size_t(d)]);
                if (dot(own, unitNormals[g]) >= cosCrease) sum += areaNormals[g];
            }
            const Vec3 n = visited >= kMaxNeighbours ? own : normalized(sum);
            cornerNormals_[c] = toWorldNormal(length(n) > 0 ? n : own);
        }
    }

    bool flipWinding() const { return (!in_.ccw) != (world_.determinant3() < 0); }

    size_t emitTriangles()
    {
        const bool perVertexColors = in_.colors.present() && in_.colors.binding == Binding::PerCorner;
        const bool perFaceColors = in_.colors.present() && in_.colors.binding == Binding::PerFace;
        const bool texCoords = in_.texCoords.present();
        const Rgba8 overall = partRgba8(part_);
        padAttributes(perVertexColors, texCoords, perFaceColors, overall);

        vertexAtCoord_.reset(in_.coords->size() / 3);
        nextVertex_.clear();
        const uint32_t firstVertex = uint32_t(part_.positions.size());
        std::vector<uint32_t> cornerVertex(corners_.size());
        for (const Face& f : faces_)
            for (uint32_t k = 0; k < f.cornerCount; ++k) {
                const uint32_t c = f.firstCorner + k;
                cornerVertex[c] = vertexFor(c, f, firstVertex, perVertexColors, texCoords, overall);
            }

        const bool flip = flipWinding();
        size_t triangles = 0;
        for (const Face& f : faces_) {
            triangulateFace(f);
            for (const auto& t : faceTriangles_) {
                const uint32_t a = cornerVertex[f.firstCorner + t[0]];
                const uint32_t b = cornerVertex[f.firstCorner + t[1]];
                const uint32_t c = cornerVertex[f.firstCorner + t[2]];
                if (flip) part_.triangles.insert(part_.triangles.end(), {a, c, b});
                else part_.triangles.insert(part_.triangles.end(), {a, b, c});
                if (perFaceColors) {
                    const long i = valueIndex(in_.colors, corners_[f.firstCorner], f);
                    part_.faceColors.push_back(i >= 0 ? toRgba8(in_.colors, i) : overall);
                } else if (!part_.faceColors.empty()) {
                    part_.faceColors.push_back(overall);
                }
                ++triangles;
            }
        }
        return triangles;
    }

    void padAttributes(bool perVertexColors, bool texCoords, bool perFaceColors, const Rgba8& overall)
    {
        if (perVertexColors && part_.colors.size() < part_.positions.size())
            part_.colors.resize(part_.positions.size(), overall);
        if (texCoords && part_.texCoords.size() < part_.positions.size())
            part_.texCoords.resize(part_.positions.size(), Vec2f{0, 0});
        if (perFaceColors && part_.faceColors.size() < part_.triangleCount())
            part_.faceColors.resize(part_.triangleCount(), overall);
    }

    void triangulateFace(const Face& f)
    {
        faceTriangles_.clear();
        // Ear clipping is quadratic: a huge concave face is fanned (with a warning) rather
        // than stalling the import.
        constexpr uint32_t kMaxEarClippedCorners = 5000;
        const bool hugeConcave = !in_.convex && f.cornerCount > kMaxEarClippedCorners;
        if (hugeConcave)
            diag_.warn("huge face", in_.where,
                       "face " + std::to_string(f.number) + " has " + std::to_string(f.cornerCount) +
                           " vertices; fan-triangulated instead of ear clipping");
        if (in_.convex || f.cornerCount == 3 || hugeConcave) {
            for (uint32_t k = 1; k + 1 < f.cornerCount; ++k) faceTriangles_.push_back({0, k, k + 1});
            return;
        }
        polygon_.clear();
        for (uint32_t k = 0; k < f.cornerCount; ++k)
            polygon_.push_back(coordAt(*in_.coords, corners_[f.firstCorner + k].coord));
        triangulatePolygon(polygon_, faceTriangles_);
    }

    uint32_t vertexFor(uint32_t c, const Face& f, uint32_t firstVertex, bool perVertexColors, bool texCoords,
                       const Rgba8& overall)
    {
        const Corner& corner = corners_[c];
        const Vec3f& normal = cornerNormals_[c];
        const long colorIndex = perVertexColors ? valueIndex(in_.colors, corner, f) : -1;
        const Rgba8 color = colorIndex >= 0 ? toRgba8(in_.colors, colorIndex) : overall;
        Vec2f tex{0, 0};
        const long texIndex = texCoords ? valueIndex(in_.texCoords, corner, f) : -1;
        if (texIndex >= 0)
            tex = {(*in_.texCoords.values)[size_t(texIndex) * 2], (*in_.texCoords.values)[size_t(texIndex) * 2 + 1]};
        for (int32_t v = vertexAtCoord_.get(size_t(corner.coord)); v >= 0; v = nextVertex_[size_t(v) - firstVertex]) {
            if (part_.normals[size_t(v)] == normal && (!perVertexColors || part_.colors[size_t(v)] == color) &&
                (!texCoords || part_.texCoords[size_t(v)] == tex))
                return uint32_t(v);
        }
        const uint32_t v = uint32_t(part_.positions.size());
        const Vec3 p = world_.transformPoint(coordAt(*in_.coords, corner.coord));
        part_.positions.push_back({float(p.x), float(p.y), float(p.z)});
        part_.normals.push_back(normal);
        if (perVertexColors || !part_.colors.empty()) part_.colors.push_back(color);
        if (texCoords || !part_.texCoords.empty()) part_.texCoords.push_back(tex);
        nextVertex_.push_back(vertexAtCoord_.get(size_t(corner.coord)));
        vertexAtCoord_.set(size_t(corner.coord), int32_t(v));
        return v;
    }

    const FaceSetInput& in_;
    const Mat4& world_;
    const Mat4 normalMatrix_;
    const EmitOptions& options_;
    Part& part_;
    Diagnostics& diag_;
    SceneStats& stats_;

    bool badAttributeWarned_ = false;
    std::vector<char> placeable_;  // per point of in_.coords
    std::vector<Corner> corners_;
    std::vector<Face> faces_;
    std::vector<Vec3f> cornerNormals_;
    std::vector<Vec3> polygon_;
    std::vector<std::array<uint32_t, 3>> faceTriangles_;
    std::vector<int32_t> nextVertex_;
    CoordTable& vertexAtCoord_;  // reused between face sets: no per-set clearing
    CoordTable& adjacency_;
};

}  // namespace

size_t emitFaceSet(const FaceSetInput& in, const Mat4& world, const EmitOptions& options, Part& part,
                   Diagnostics& diag, SceneStats& stats)
{
    thread_local CoordTable vertexAtCoord, adjacency;
    return FaceSetEmitter(in, world, options, part, diag, stats, vertexAtCoord, adjacency).run();
}

}  // namespace cadlod::vrml
