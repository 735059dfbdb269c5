// Reading any input the command line accepts into a cadlod::CoreMesh (VRML 97/1.0, plain
// or gzip; OpenFlight, finest level; OBJ with our obj_reader.h; PLY/STL through vcglib)
// and writing a mesh as PLY/OBJ/STL (vcglib) or a one-level OpenFlight file.
#pragma once
#include "assembly/part_mesh.h"
#include "mesh/core_mesh.h"
#include "openflight/flt_writer.h"
#include "openflight/lod_model.h"
#include "unit_choice.h"
#include "vrml/diagnostics.h"
#include "vrml/importer.h"
#include "vrml/scene.h"

#include <string>
#include <vector>

namespace cadlod::cli {

enum class InputFormat { Vrml, OpenFlight, Ply, Obj, Stl, Unknown };

InputFormat formatOf(const std::string& path);
const char* formatName(InputFormat format);

struct ImportSettings {
    double unitScale = 1.0;          // of `unit`, else of `defaultUnit`
    std::string unit;                // --unit (empty: not given): wins over a KiCad header
    std::string defaultUnit = "m";
    bool defaultUnitGiven = false;
    bool yUpToZUp = false;
    bool allowPartial = false;       // accept a VRML input that lost geometry
    bool recomputeNormals = false;
    bool mergeVertices = true;
    float mergeTolerance = 0.0f;
    bool keepInstances = false;  // VRML: an assembly that shares geometry is kept as placements
    // VRML, with keepInstances: a file that shares nothing but has several parts is kept as
    // its parts, each placed once (vrml::partsPlacedOnce).
    bool placeParts = false;
    // VRML, with placeParts: a file of one part (or none named) is kept as that part placed
    // once, so that it is chunked and its levels held at its nearest point too.
    bool placeWholeModel = false;
    // VRML: PowerOfTwo reads at the power of two nearest to the unit, so that the simplifier
    // decides alike in every unit; LoadedMesh::lengthScale is the rest.
    vrml::UnitScaling unitScaling = vrml::UnitScaling::Exact;
};

struct LoadedMesh {
    InputFormat format = InputFormat::Unknown;
    std::size_t parts = 0;
    int mergedVertices = 0;
    std::size_t invalidFaces = 0;    // VRML: faces left out for bad indices or fewer than 3
    int degenerateFaces = 0;         // VRML: faces that welding gave a vertex twice, removed
    std::size_t fltLevels = 0;       // OpenFlight: levels in the file
    flt::Units fltUnits = flt::Units::Meters;
    std::size_t placements = 0;      // kept instances: placements of the distinct parts
    // VRML: the unit applied and why, KiCad's header, the importer's findings, and the
    // command's own warnings about the model (an implausible size for its unit).
    UnitChoice unit{"file units", 1.0, "--unit applies to VRML inputs only"};
    bool kicadHeader = false, kicadUnitApplied = false;
    vrml::Diagnostics findings;
    std::vector<std::string> notes;
    // What every length of the loaded mesh is multiplied by to be in the unit chosen: not 1
    // where the unit is applied in part (ImportSettings::unitScaling).
    double lengthScale = 1.0;
};

// `settings` for lengths of the loaded mesh: the merge tolerance, given in the unit chosen,
// in the mesh's own.
ImportSettings inMeshUnits(ImportSettings settings, const LoadedMesh& loaded);

// Loads `path` into `m` (empty) ready for the simplifier (compact, VF adjacency, face
// normals, bbox); throws InputError with the reader's message (file:line:col or offset),
// also for a VRML input that lost geometry unless settings.allowPartial.
// With settings.keepInstances and `assembly`, a VRML file that shares geometry goes to
// `assembly` (its parts not welded yet) and `m` stays empty.
LoadedMesh loadMesh(const std::string& path, CoreMesh& m, const ImportSettings& settings,
                    vrml::Scene* assembly = nullptr);

// How loadMesh welds, for the parts of an assembly (assembly/part_mesh.h).
PartWelding weldingOf(const ImportSettings& settings);

// Reads an OpenFlight file whole; throws InputError.
flt::LodModel readFlt(const std::string& path);

struct SaveSettings {
    flt::WriteOptions flt;
    flt::Units units = flt::Units::Meters;
};

// Writes `m` to `path` by its extension (flt, ply, obj, stl), atomically.
void saveMesh(const std::string& path, CoreMesh& m, const SaveSettings& settings);

}  // namespace cadlod::cli
