#include "mesh_files.h"

#include "assembly_size.h"
#include "cli_errors.h"
#include "openflight/flt_reader.h"
#include "convert/lod_model_to_mesh.h"
#include "convert/mesh_to_lod_model.h"
#include "input_losses.h"
#include "measure/hausdorff.h"
#include "note_lines.h"
#include "obj_reader.h"
#include "output_file.h"
#include "progress_bar.h"
#include "convert/scene_to_mesh.h"
#include "vrml/assembly.h"
#include "vrml/importer.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <wrap/io_trimesh/export_obj.h>
#include <wrap/io_trimesh/export_ply.h>
#include <wrap/io_trimesh/export_stl.h>
#include <wrap/io_trimesh/import_ply.h>
#include <wrap/io_trimesh/import_stl.h>

#include <filesystem>
#include <fstream>

namespace cadlod::cli {
namespace {

bool endsWith(const std::string& s, const std::string& tail)
{
    return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// vcglib's OBJ exporter names the file it writes in a header comment ("# Object NAME"):
// here the temporary file, renamed into place afterwards. The temporary name is longer than
// the output's (".NAME.tmp-XXXXXX", atomic_file.h), so the output's name, padded with
// spaces, takes its place in the file without moving a byte.
bool nameObjOutput(const std::string& temporary, const std::string& path)
{
    std::fstream file(temporary, std::ios::in | std::ios::out | std::ios::binary);
    std::string head(512, '\0');
    file.read(head.data(), std::streamsize(head.size()));
    head.resize(std::size_t(file.gcount()));
    file.clear();
    const std::string written = std::filesystem::path(temporary).filename().string();
    std::string name = std::filesystem::path(path).filename().string();
    const std::string comment = "# Object " + written + "\n";
    const std::size_t at = head.find(comment);
    if (at == std::string::npos || name.size() > written.size())
        return bool(file);
    name.resize(written.size(), ' ');
    file.seekp(std::streamoff(at + comment.size() - 1 - written.size()));
    file.write(name.data(), std::streamsize(name.size()));
    return bool(file.flush());
}

std::string lower(std::string s)
{
    for (char& c : s)
        c = char(std::tolower((unsigned char)c));
    return s;
}

void sceneToCoreMesh(vrml::Scene& scene, CoreMesh& m, const ImportSettings& settings, LoadedMesh& info)
{
    const WeldingStats stats = weldScene(scene, m, weldingOf(settings), progress::callback);
    info.mergedVertices = stats.mergedVertices;
    info.degenerateFaces = stats.degenerateFaces;
}

vrml::ImportOptions vrmlOptions(const ImportSettings& settings, bool keepInstances)
{
    vrml::ImportOptions options;
    options.unitScale = settings.unitScale;
    options.detectKicadUnits = settings.unit.empty();  // --unit says what the file is in
    options.kicadUnitScale = 0.001;                    // KiCad's millimetres to metres
    options.upAxis = settings.yUpToZUp ? vrml::UpAxis::YUpToZUp : vrml::UpAxis::Keep;
    options.recomputeNormals = settings.recomputeNormals;
    options.unitScaling = settings.unitScaling;
    if (keepInstances)
        options.instances = vrml::Instances::Keep;
    options.progress = [](double f) { progress::report(int(60 * f), "Reading VRML"); };
    return options;
}

LoadedMesh loadVrml(const std::string& path, CoreMesh& m, const ImportSettings& settings, vrml::Scene* assembly)
{
    vrml::ImportResult imported =
        vrml::importVrmlFile(path, vrmlOptions(settings, settings.keepInstances && assembly));
    if (!imported.ok())
        throw InputError(imported.error);
    refuseLosses(imported.scene.diagnostics, settings.allowPartial);
    printFolded("warning", findingLines(imported.scene.diagnostics), 12);
    LoadedMesh info;
    info.format = InputFormat::Vrml;
    info.findings = imported.scene.diagnostics;
    info.kicadHeader = imported.assumed.kicadHeader;
    info.kicadUnitApplied = imported.assumed.kicadUnits;
    info.unit = chooseUnit(settings.unit, info.kicadUnitApplied, settings.defaultUnit, settings.defaultUnitGiven);
    info.lengthScale = imported.assumed.remainingScale;
    info.invalidFaces = imported.scene.stats.skippedFaces;
    if (settings.placeParts && assembly && imported.scene.assembly.empty() &&
        (vrml::namedParts(imported.scene.parts) > 1 || settings.placeWholeModel))
        imported.scene.assembly = vrml::partsPlacedOnce(std::move(imported.scene.parts));
    if (!imported.scene.assembly.empty()) {
        info.parts = imported.scene.assembly.geometries.size();
        info.placements = imported.scene.assembly.placementCount();
        *assembly = std::move(imported.scene);
        return info;
    }
    info.parts = imported.scene.parts.size();
    sceneToCoreMesh(imported.scene, m, inMeshUnits(settings, info), info);
    if (m.fn == 0)
        throw InputError(path + ": no triangles in the scene");
    return info;
}

// A VRML model whose size is implausible for its unit is reported when loaded.
void checkModelSize(double diagonalInMeshUnits, LoadedMesh& info)
{
    const std::string warning = implausibleSizeWarning(diagonalInMeshUnits * info.lengthScale, info.unit);
    if (warning.empty())
        return;
    printFolded("warning", {warning});
    info.notes.push_back(warning);
}

// An OpenFlight file writes a vertex once per smooth fan where faces fold (cadlod's own
// exporter, metadata/crease_fans.h) or once per face (Face records): welded here, as the VRML
// importer welds, so that the simplifier sees the surface whole and not cut along its creases.
LoadedMesh loadFlt(const std::string& path, CoreMesh& m, const ImportSettings& settings)
{
    const flt::LodModel model = readFlt(path);
    if (model.levels.empty())
        throw InputError(path + ": no geometry");
    LoadedMesh info;
    info.format = InputFormat::OpenFlight;
    info.fltLevels = model.levels.size();
    info.fltUnits = model.units;
    const flt::Level& finest = model.levels[flt::finestLevel(model)];
    info.parts = finest.parts.size();
    mesh_io::levelToMesh(finest, m);
    if (settings.mergeVertices) {
        info.mergedVertices = vcg::tri::Clean<CoreMesh>::RemoveDuplicateVertex(m);
        vcg::tri::Clean<CoreMesh>::RemoveUnreferencedVertex(m);
        if (settings.mergeTolerance > 0)  // as for VRML (scene_to_mesh.h)
            info.mergedVertices += mesh_io::mergeCloseVertices(m, settings.mergeTolerance);
    }
    return info;
}

template <class Importer>
LoadedMesh loadWithVcg(const std::string& path, CoreMesh& m, InputFormat format, bool critical(int))
{
    int mask = 0;
    const int rc = Importer::Open(m, path.c_str(), mask);
    if (rc != 0 && critical(rc))
        throw InputError(path + ": " + Importer::ErrorMsg(rc));
    LoadedMesh info;
    info.format = format;
    info.parts = 1;
    return info;
}

LoadedMesh loadObj(const std::string& path, CoreMesh& m)
{
    LoadedMesh info;
    info.format = InputFormat::Obj;
    info.parts = readObjFile(path, m);
    return info;
}

void saveFlt(const std::string& path, CoreMesh& m, const SaveSettings& settings)
{
    flt::LodModel model;
    model.units = settings.units;
    mesh_io::LevelOptions options;
    options.label = "mesh";
    options.faceColors = true;
    mesh_io::LevelStats stats;
    model.levels.push_back(mesh_io::meshToLevel(m, options, stats));
    std::string error;
    if (!flt::writeOpenFlightFile(path, model, settings.flt, error))
        throw InputError(error);
}

}  // namespace

ImportSettings inMeshUnits(ImportSettings settings, const LoadedMesh& loaded)
{
    settings.mergeTolerance = float(settings.mergeTolerance / loaded.lengthScale);
    return settings;
}

InputFormat formatOf(const std::string& path)
{
    const std::string p = lower(path);
    for (const char* ext : {".wrl", ".wrz", ".vrml", ".wrl.gz", ".vrml.gz"})
        if (endsWith(p, ext))
            return InputFormat::Vrml;
    if (endsWith(p, ".flt"))
        return InputFormat::OpenFlight;
    if (endsWith(p, ".ply"))
        return InputFormat::Ply;
    if (endsWith(p, ".obj"))
        return InputFormat::Obj;
    if (endsWith(p, ".stl"))
        return InputFormat::Stl;
    return InputFormat::Unknown;
}

const char* formatName(InputFormat format)
{
    switch (format) {
    case InputFormat::Vrml: return "VRML";
    case InputFormat::OpenFlight: return "OpenFlight";
    case InputFormat::Ply: return "PLY";
    case InputFormat::Obj: return "OBJ";
    case InputFormat::Stl: return "STL";
    default: return "unknown";
    }
}

flt::LodModel readFlt(const std::string& path)
{
    flt::LodModel model;
    std::string error;
    if (!flt::readOpenFlightFile(path, model, error))
        throw InputError(error.rfind(path, 0) == 0 ? error : path + ": " + error);
    return model;
}

LoadedMesh loadMesh(const std::string& path, CoreMesh& m, const ImportSettings& settings, vrml::Scene* assembly)
{
    LoadedMesh info;
    switch (formatOf(path)) {
    case InputFormat::Vrml:
        info = loadVrml(path, m, settings, assembly);
        if (info.placements > 0) {
            checkModelSize(placedDiagonal(assembly->assembly), info);
            return info;
        }
        break;
    case InputFormat::OpenFlight: info = loadFlt(path, m, settings); break;
    case InputFormat::Ply: info = loadWithVcg<vcg::tri::io::ImporterPLY<CoreMesh>>(
        path, m, InputFormat::Ply, [](int rc) { return vcg::tri::io::ImporterPLY<CoreMesh>::ErrorCritical(rc); }); break;
    case InputFormat::Obj: info = loadObj(path, m); break;
    case InputFormat::Stl: info = loadWithVcg<vcg::tri::io::ImporterSTL<CoreMesh>>(
        path, m, InputFormat::Stl, [](int rc) { return rc != 0; }); break;
    default:
        throw InputError(path + ": unknown input format (VRML .wrl/.wrz/.vrml[.gz], .flt, .ply, .obj, .stl)");
    }
    if (m.fn == 0)
        throw InputError(path + ": no triangles");
    prepareForSimplifier(m);
    if (info.format == InputFormat::Vrml)
        checkModelSize(liveDiagonal(m), info);
    return info;
}

PartWelding weldingOf(const ImportSettings& settings)
{
    return {settings.mergeVertices, settings.mergeTolerance};
}

void saveMesh(const std::string& path, CoreMesh& m, const SaveSettings& settings)
{
    using namespace vcg::tri::io;
    const std::string ext = extensionOf(path);
    if (ext == "flt") {
        saveFlt(path, m, settings);
        return;
    }
    vcg::tri::Allocator<CoreMesh>::CompactEveryVector(m);
    const int mask = Mask::IOM_VERTNORMAL | Mask::IOM_VERTCOLOR | Mask::IOM_FACECOLOR;
    std::function<bool(const std::string&)> write;
    if (ext == "ply")
        write = [&](const std::string& t) { return ExporterPLY<CoreMesh>::Save(m, t.c_str(), mask, true) == 0; };
    else if (ext == "obj")
        write = [&](const std::string& t) {
            return ExporterOBJ<CoreMesh>::Save(m, t.c_str(), Mask::IOM_VERTNORMAL) == 0 && nameObjOutput(t, path);
        };
    else if (ext == "stl")
        write = [&](const std::string& t) { return ExporterSTL<CoreMesh>::Save(m, t.c_str(), true) == 0; };
    else
        throw UsageError(path + ": unknown output format (.flt, .ply, .obj, .stl)");
    writeAtomically(path, write);
}

}  // namespace cadlod::cli
