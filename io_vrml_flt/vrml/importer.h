// Public entry point of the VRML core: reads a .wrl/.wrz/.vrml file (plain or gzip,
// VRML97 or VRML 1.0, with its Inlines) into a neutral Scene.
#pragma once

#include "vrml/scene.h"
#include "vrml/source_text.h"

#include <functional>
#include <string>

namespace cadlod::vrml {

struct ImportOptions {
    double unitScale = 1.0;            // applied to the world transform (e.g. 0.001: mm -> m)
    bool recomputeNormals = false;     // ignore file normals, use creaseAngle
    int maxInlineDepth = 32;
    int maxNesting = 400;
    size_t maxInflatedBytes = kDefaultMaxInflatedBytes;
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
