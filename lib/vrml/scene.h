// The neutral scene a VRML file evaluates to: parts in world coordinates, each an
// indexed triangle mesh with optional per-vertex normals, colors and texture
// coordinates and optional per-triangle colors. No MeshLab dependency.
#pragma once

#include "mesh/part_identity.h"
#include "vrml/diagnostics.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cadlod::vrml {

using Vec3f = std::array<float, 3>;
using Vec2f = std::array<float, 2>;
using Rgba8 = std::array<uint8_t, 4>;

// A part as read: its identity (nearest DEF name, or the node path; material diffuse
// + (1 - transparency)) and its triangles.
struct Part : PartIdentity {
    std::vector<Vec3f> positions;
    std::vector<Vec3f> normals;       // empty or one per position
    std::vector<Rgba8> colors;        // empty or one per position
    std::vector<Vec2f> texCoords;     // empty or one per position
    std::string texture;              // image file (resolved path) or empty
    std::vector<uint32_t> triangles;  // 3 indices per triangle, counter-clockwise front
    std::vector<Rgba8> faceColors;    // empty or one per triangle

    size_t triangleCount() const { return triangles.size() / 3; }
};

struct SceneStats {
    size_t shapes = 0;
    size_t skippedFaces = 0;       // bad indices, fewer than 3 vertices
    size_t lineSets = 0;           // IndexedLineSet / PointSet: counted, not imported
    size_t pointSets = 0;
    size_t inlinesLoaded = 0;
    // Triangles by source, for comparing with other readers: IndexedFaceSet, ElevationGrid,
    // Extrusion and Box/Cube tessellate the same everywhere; Sphere/Cylinder/Cone do not.
    size_t meshTriangles = 0;
    size_t roundPrimitiveTriangles = 0;
    size_t bytesRead = 0;          // source bytes (inflated), main file and inlines
};

struct Scene {
    std::vector<Part> parts;
    Diagnostics diagnostics;
    SceneStats stats;
    int version = 0;               // 1 or 2 (VRML97) for the main file

    size_t triangleCount() const
    {
        size_t n = 0;
        for (const Part& p : parts) n += p.triangleCount();
        return n;
    }
    size_t vertexCount() const
    {
        size_t n = 0;
        for (const Part& p : parts) n += p.positions.size();
        return n;
    }
};

}  // namespace cadlod::vrml
