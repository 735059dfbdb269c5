// Public entry point of the VRML core: reads a .wrl/.wrz/.vrml file (plain or gzip,
// VRML97 or VRML 1.0, with its Inlines) into a neutral Scene.
#pragma once

#include "vrml/scene.h"
#include "vrml/source_text.h"

#include <cstdint>
#include <functional>
#include <string>

namespace cadlod::vrml {

// Which way is up in the file. VRML's convention is +Y, OpenFlight's +Z; CAD exporters
// (FreeCAD, KiCad StepUp, OCCT, robot libraries) write their native Z-up coordinates into
// VRML, so Keep is the default and YUpToZUp is for files that follow VRML's convention.
enum class UpAxis { Keep, YUpToZUp };

// What shared nodes (a DEF'd node that is USE'd, an Inline file) become. Expand: a copy per
// use, in world coordinates (Scene::parts). Keep: one geometry per shared node, read once,
// and its placements (Scene::assembly); a file that shares no geometry is read expanded.
enum class Instances { Expand, Keep };

// How the unit scale reaches the coordinates. Exact: all of it is multiplied in. PowerOfTwo:
// only the power of two nearest to it, the rest left to the caller
// (ImportAssumptions::remainingScale). A power of two changes a float's exponent and none of
// its bits, so one file gives the same coordinates up to that power in any unit, and a
// simplifier that measures only relative lengths decides the same in every unit.
enum class UnitScaling { Exact, PowerOfTwo };

struct ImportOptions {
    double unitScale = 1.0;            // applied to the world transform (e.g. 0.001: mm -> m)
    UpAxis upAxis = UpAxis::Keep;      // YUpToZUp: rotate +90 degrees about X, (x, y, z) -> (x, -z, y)
    // KiCad's 3D models (header comment "#kicad StepUp wrl exported") are in 0.1 inch:
    // scale them by 2.54 to millimetres (before unitScale) when the header says so. Off:
    // the header is still looked for (ImportAssumptions::kicadHeader), never applied.
    bool detectKicadUnits = true;
    // The scale applied to a KiCad file's millimetres instead of unitScale (e.g. 0.001 to
    // metres), so a caller need not know beforehand which files are KiCad's; 0: unitScale.
    double kicadUnitScale = 0.0;
    UnitScaling unitScaling = UnitScaling::Exact;
    bool recomputeNormals = false;     // ignore file normals, use creaseAngle
    Instances instances = Instances::Expand;
    // Keep: the most placements the assembly may expand to (a file that USEs groups of USEs
    // describes far more placements than it has bytes).
    uint64_t maxPlacements = 1'000'000;
    int maxInlineDepth = 32;
    int maxNesting = 400;
    size_t maxInflatedBytes = kDefaultMaxInflatedBytes;
    // Triangle limit of the scene, checked before anything is expanded (DEF/USE instancing
    // multiplies geometry; with instances kept, the distinct geometry is counted): the larger of maxTriangles and maxTrianglesPerInputByte x the
    // bytes read (inflated, inlines included). 50 M triangles take 3-7 GB in the Scene
    // (24-140 bytes each, welded to unwelded) and as much again in MeshLab's layer.
    uint64_t maxTriangles = 50'000'000;
    double maxTrianglesPerInputByte = 1.0;
    std::function<void(double fraction)> progress;  // main file parse progress, 0..1
};

// What the importer assumed about the file's axes and units, for the log.
struct ImportAssumptions {
    bool kicadHeader = false;  // the KiCad StepUp header was found
    bool kicadUnits = false;   // ... and 2.54 applied (detectKicadUnits)
    double fileScale = 1.0;    // 2.54 for KiCad, else 1 (before unitScale)
    UpAxis upAxis = UpAxis::Keep;
    // The part of the unit scale not in the coordinates (UnitScaling::PowerOfTwo), for the
    // caller to multiply every length it writes by; 1 with UnitScaling::Exact.
    double remainingScale = 1.0;
    std::string describe(double unitScale) const;  // one sentence
};

struct ImportResult {
    Scene scene;
    ImportAssumptions assumed;
    std::string error;  // non-empty: the file could not be read at all
    bool ok() const { return error.empty(); }
};

ImportResult importVrmlFile(const std::string& path, const ImportOptions& options = {});
// From text already in memory (tests); inlines resolve relative to `fileName`.
ImportResult importVrmlText(std::string text, const std::string& fileName, const ImportOptions& options = {});

}  // namespace cadlod::vrml
