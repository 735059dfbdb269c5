// The neutral scene a VRML file evaluates to: parts in world coordinates, or an assembly
// of shared geometry and its placements (assembly.h). No MeshLab dependency.
#pragma once

#include "vrml/assembly.h"
#include "vrml/diagnostics.h"
#include "vrml/part.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cadlod::vrml {

struct SceneStats {
    size_t shapes = 0;
    size_t skippedFaces = 0;       // bad indices, fewer than 3 vertices
    size_t lineSets = 0;           // IndexedLineSet / PointSet: counted, not imported
    size_t pointSets = 0;
    size_t inlinesLoaded = 0;
    // Expanding: uses of a shared node (a USE'd DEF that holds shapes, an Inline file) after
    // its first, each a copy. Keeping instances makes them placements instead.
    size_t expandedCopies = 0;
    // Triangles by source, for comparing with other readers: IndexedFaceSet, ElevationGrid,
    // Extrusion and Box/Cube tessellate the same everywhere; Sphere/Cylinder/Cone do not.
    size_t meshTriangles = 0;
    size_t roundPrimitiveTriangles = 0;
    size_t bytesRead = 0;          // source bytes (inflated), main file and inlines
};

// Expanded (the importer's default), the parts are in world coordinates and the assembly is
// empty. With instances kept, `parts` is empty and the assembly holds the geometry.
struct Scene {
    std::vector<Part> parts;
    Assembly assembly;
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
