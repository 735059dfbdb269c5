// VRML import adapter: parameters, logging and the layer's optional components around
// the MeshLab-independent reader (vrml/) and its conversion into a mesh
// (mesh_io/scene_to_mesh.h, instantiated for CMeshO).
#include "format_adapters.h"

#include "mesh/layer_metadata.h"
#include "convert/scene_to_mesh.h"
#include "vrml/importer.h"

#include <wrap/io_trimesh/io_mask.h>

#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>

namespace cadlod {
namespace {

constexpr const char* kUnitScale = "vrmlUnitScale";
constexpr const char* kMergeVertices = "vrmlMergeVertices";
constexpr const char* kMergeTolerance = "vrmlMergeTolerance";
constexpr const char* kNormals = "vrmlNormals";
constexpr const char* kUpAxis = "vrmlUpAxis";
constexpr const char* kKicadUnits = "vrmlKicadUnits";

// A speed only where the time says something: a small file reads in less than a clock tick.
std::string importSpeed(std::size_t bytes, double seconds)
{
    if (seconds < 0.05)
        return "";
    char text[32];
    std::snprintf(text, sizeof text, ", %.1f MB/s", bytes / 1e6 / seconds);
    return text;
}

void logDiagnostics(MeshIOInterface& plugin, const vrml::Diagnostics& diag)
{
    if (diag.total() == 0) return;
    std::string summary = "VRML import warnings:";
    for (const auto& [kind, count] : diag.counts()) summary += " " + kind + " " + std::to_string(count) + ";";
    report(plugin, GLLogStream::WARNING, summary);
    constexpr size_t kShown = 12;  // the first few in full; counts above say how many more
    for (size_t i = 0; i < diag.kept().size() && i < kShown; ++i) {
        const vrml::Diagnostic& d = diag.kept()[i];
        report(plugin, GLLogStream::WARNING, d.where + ": " + d.kind + ": " + d.message);
    }
}

}  // namespace

void vrmlOpenParameters(RichParameterList& par)
{
    par.addParam(RichFloat(kUnitScale, 1.0f, "Unit scale",
                           "Multiplies every coordinate, e.g. 0.001 to read a file in mm as meters."));
    par.addParam(RichBool(kMergeVertices, true, "Merge coincident vertices",
                          "CAD exporters split a body into one face set per face or material; merging "
                          "identical points rejoins them into one connected mesh, which the simplifier needs."));
    par.addParam(RichFloat(kMergeTolerance, 0.0f, "Merge tolerance",
                           "Largest distance (model units, after scaling) between merged vertices; 0 merges "
                           "only identical points, never closing real small gaps."));
    par.addParam(RichEnum(kUpAxis, 0, QStringList{"Keep (Z up, as CAD exporters write)", "Y up -> Z up"}, "Up axis",
                          "OpenFlight is Z up. FreeCAD, KiCad and OCCT write Z up: keep. "
                          "Y up -> Z up rotates files that follow VRML's Y-up convention."));
    par.addParam(RichBool(kKicadUnits, true, "KiCad 0.1-inch units",
                          "Files with KiCad StepUp's header are in 0.1 inch: scale them by 2.54 to mm "
                          "(before Unit scale)."));
    par.addParam(RichEnum(kNormals, 0, QStringList{"Keep file normals", "Recompute from creaseAngle"}, "Normals",
                          "Keep the normals the file gives (creaseAngle where it gives none), or ignore them "
                          "and recompute everything from creaseAngle."));
}

bool openVrml(MeshIOInterface& plugin, const QString& fileName, MeshModel& m, int& mask,
              const RichParameterList& par, vcg::CallBackPos* cb, QString& error)
{
    QElapsedTimer timer;
    timer.start();
    vrml::ImportOptions options;
    options.unitScale = par.hasParameter(kUnitScale) ? par.getFloat(kUnitScale) : 1.0f;
    options.recomputeNormals = par.hasParameter(kNormals) && par.getEnum(kNormals) == 1;
    options.upAxis = par.hasParameter(kUpAxis) && par.getEnum(kUpAxis) == 1 ? vrml::UpAxis::YUpToZUp : vrml::UpAxis::Keep;
    options.detectKicadUnits = !par.hasParameter(kKicadUnits) || par.getBool(kKicadUnits);
    ProgressReporter progress(cb);
    if (cb) options.progress = [&progress](double f) { progress(int(60 * f), "Reading VRML"); };

    vrml::ImportResult result = vrml::importVrmlFile(fileName.toStdString(), options);
    if (!result.ok()) {
        error = QString::fromStdString(result.error);
        report(plugin, GLLogStream::WARNING, result.error);
        return false;
    }
    vrml::Scene& scene = result.scene;
    const qint64 parsedMs = timer.elapsed();
    mask = vcg::tri::io::Mask::IOM_VERTNORMAL | vcg::tri::io::Mask::IOM_FACECOLOR;
    // Vertex colours only when the file gives them (colorPerVertex): the layer then shows
    // them and the OpenFlight export writes them; otherwise the face colours are the truth.
    if (std::any_of(scene.parts.begin(), scene.parts.end(), [](const vrml::Part& p) { return !p.colors.empty(); }))
        mask |= vcg::tri::io::Mask::IOM_VERTCOLOR;
    if (mesh_io::hasTexCoords(scene)) mask |= vcg::tri::io::Mask::IOM_WEDGTEXCOORD;
    m.Enable(mask);
    mesh_io::SceneToMeshOptions toMesh;
    toMesh.mergeVertices = !par.hasParameter(kMergeVertices) || par.getBool(kMergeVertices);
    toMesh.mergeTolerance = par.hasParameter(kMergeTolerance) ? par.getFloat(kMergeTolerance) : 0.0f;
    mesh_io::SceneToMeshStats built;
    const int merged = mesh_io::sceneToMesh(scene, m.cm, toMesh, cb, &built);
    progress(90, "Building mesh");  // the last step the reporter times finish() from
    setMetresPerUnit(m.cm, 1.0);  // VRML's unit; Unit scale is how a file in mm becomes one
    setVrmlSource(m.cm, VrmlSource{fileName.toStdString(), options.unitScale, options.detectKicadUnits,
                                   options.upAxis == vrml::UpAxis::YUpToZUp, options.recomputeNormals,
                                   toMesh.mergeVertices, toMesh.mergeTolerance});

    const double seconds = std::max(1e-6, timer.elapsed() / 1000.0);
    char line[1024];
    std::snprintf(line, sizeof line,
                  "VRML %d import of %s: %zu parts, %d triangles, %d vertices (%d merged), %zu shapes, "
                  "%zu faces skipped, %d faces repeating a vertex after welding removed, %zu line/point sets ignored, %zu inlines; %.1f MB in %.2f s (read %.2f s)"
                  "%s",
                  scene.version == 1 ? 1 : 2, qUtf8Printable(fileName), partTableHandle(m.cm)().size(), m.cm.fn,
                  m.cm.vn, merged, scene.stats.shapes, scene.stats.skippedFaces, built.facesRepeatingVertex,
                  scene.stats.lineSets + scene.stats.pointSets, scene.stats.inlinesLoaded, scene.stats.bytesRead / 1e6,
                  seconds, parsedMs / 1000.0, importSpeed(scene.stats.bytesRead, seconds).c_str());
    report(plugin, GLLogStream::FILTER, std::string(line));
    report(plugin, GLLogStream::FILTER, "VRML import of " + fileName.toStdString() + ": " +
                                            result.assumed.describe(options.unitScale));
    if (scene.stats.expandedCopies > 0)
        report(plugin, GLLogStream::WARNING,
               "VRML import of " + fileName.toStdString() + ": the file places shared parts (USE, Inline) " +
                   std::to_string(scene.stats.expandedCopies) +
                   " more times; a MeshLab layer is one mesh, so each is a copy here. `cadlod convert` keeps them "
                   "as OpenFlight instances, each part simplified once.");
    logDiagnostics(plugin, scene.diagnostics);
    progress.finish("VRML opened");  // replaces "Reading VRML" in the status bar
    return true;
}

}  // namespace cadlod
