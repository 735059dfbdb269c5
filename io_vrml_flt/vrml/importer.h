// Public entry point of the VRML core: reads a .wrl/.wrz/.vrml file (plain or gzip,
// VRML97 or VRML 1.0, with its Inlines) into a neutral Scene.
#pragma once

#include "vrml/scene.h"
#include "vrml/source_text.h"

#include <cstdint>
#include <functional>
#include <string>

namespace cadlod::vrml {

struct ImportOptions {
    double unitScale = 1.0;            // applied to the world transform (e.g. 0.001: mm -> m)
    bool recomputeNormals = false;     // ignore file normals, use creaseAngle
    int maxInlineDepth = 32;
    int maxNesting = 400;
    size_t maxInflatedBytes = kDefaultMaxInflatedBytes;
    // Triangle limit of the scene, checked before anything is expanded (DEF/USE instancing
    // multiplies geometry): the larger of maxTriangles and maxTrianglesPerInputByte x the
    // bytes read (inflated, inlines included). 50 M triangles take 3-7 GB in the Scene
    // (24-140 bytes each, welded to unwelded) and as much again in MeshLab's layer.
    uint64_t maxTriangles = 50'000'000;
    double maxTrianglesPerInputByte = 1.0;
    std::function<void(double fraction)> progress;  // main file parse progress, 0..1
};

struct ImportResult {
    Scene scene;
    std::string error;  // non-empty: the file could not be read at all
    bool ok() const { return error.empty(); }
};

ImportResult importVrmlFile(const std::string& path, const ImportOptions& options = {});
// From text already in memory (tests); inlines resolve relative to `fileName`.
ImportResult importVrmlText(std::string text, const std::string& fileName, const ImportOptions& options = {});

}  // namespace cadlod::vrml
