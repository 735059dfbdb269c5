// Saving a layer as OpenFlight: parameters, logging and the document's layers around
// mesh_io/mesh_to_lod_model.h, which turns the layer (or, when it belongs to an LOD set,
// every layer of that set in the document) into the neutral LOD model the openflight/
// core writes. Vertex normals are always written: OpenFlight geometry is only lit with
// them (light mode 2).
#include "format_adapters.h"

#include "openflight/flt_writer.h"
#include "mesh/layer_metadata.h"
#include "convert/mesh_to_lod_model.h"

#include <QElapsedTimer>

#include <algorithm>
#include <cstdio>
#include <QFileInfo>

namespace cadlod {
namespace {

const char* const kUnits = "units";
const char* const kDrawType = "drawType";
const char* const kObjects = "objects";
const char* const kRecords = "records";
const char* const kWholeSet = "wholeLodSet";
const char* const kColors = "colors";

const flt::Units kUnitChoices[] = {flt::Units::Meters, flt::Units::Kilometers, flt::Units::Feet,
                                   flt::Units::Inches, flt::Units::NauticalMiles};

// A layer's name in the file. An LOD level's label ends in a suffix for the layer panel to
// drop (lod/level_names.h), and its '≥' is written ">=", so that record names stay ASCII.
std::string recordName(MeshModel& mm)
{
    if (!hasLodLevel(mm.cm))
        return mm.label().toStdString();
    return QFileInfo(mm.label()).completeBaseName().replace(QString::fromUtf8("\u2265"), ">=").toStdString();
}

mesh_io::LevelOptions levelOptions(MeshModel& mm, bool withUvs, bool faceColors)
{
    mesh_io::LevelOptions o;
    o.label = recordName(mm);
    o.faceColors = faceColors && mm.hasDataMask(MeshModel::MM_FACECOLOR);
    // Vertex colours only where the layer has them (a VRML file's per-vertex Color, a PLY's).
    o.vertexColors = faceColors && mm.hasDataMask(MeshModel::MM_VERTCOLOR);
    o.uvs = withUvs && mm.hasDataMask(MeshModel::MM_VERTTEXCOORD);
    return o;
}

// Every layer of the document that belongs to the same LOD set as `mm`.
bool gatherLodSet(MeshModel& mm, bool withUvs, bool faceColors, flt::LodModel& model, mesh_io::LevelStats& stats, QString& error)
{
    const int setId = lodLevelHandle(mm.cm)().setId;
    std::vector<mesh_io::LodLayer<CMeshO>> layers;
    const QList<MeshModel*> list = mm.parent ? mm.parent->meshList : QList<MeshModel*>{&mm};
    for (MeshModel* layer : list)
        if (layer)
            layers.push_back({&layer->cm, levelOptions(*layer, withUvs, faceColors)});
    std::string why;
    if (!mesh_io::lodSetToModel(layers, setId, model, stats, why)) {
        error = QString::fromStdString(why);
        return false;
    }
    return true;
}

flt::WriteOptions writeOptions(const RichParameterList& par)
{
    flt::WriteOptions o;
    if (par.hasParameter(kDrawType))
        o.drawType = par.getEnum(kDrawType) == 1 ? flt::DrawType::TwoSided : flt::DrawType::SingleSided;
    if (par.hasParameter(kObjects))
        o.objects = par.getEnum(kObjects) == 1 ? flt::ObjectGrouping::PerLevel : flt::ObjectGrouping::PerPart;
    if (par.hasParameter(kRecords))
        o.geometry = par.getEnum(kRecords) == 1 ? flt::GeometryRecords::Faces : flt::GeometryRecords::Meshes;
    return o;
}

flt::Units unitsParameter(const RichParameterList& par)
{
    if (!par.hasParameter(kUnits))
        return flt::Units::Meters;
    const int i = par.getEnum(kUnits);
    return i >= 0 && i < int(std::size(kUnitChoices)) ? kUnitChoices[i] : flt::Units::Meters;
}

}  // namespace

void fltSaveParameters(MeshModel&, RichParameterList& par)
{
    par.addParam(RichEnum(kUnits, 0, {"meters", "kilometers", "feet", "inches", "nautical miles"},
                          "Units", "Stored in the header; coordinates are not scaled."));
    par.addParam(RichEnum(kDrawType, 0, {"Single-sided (back faces culled)", "Two-sided"}, "Draw type",
                          "Two-sided for open surfaces seen from both sides."));
    par.addParam(RichEnum(kObjects, 0, {"One Object per part", "One Object per level"}, "Objects",
                          "One Object per CAD part (names kept), or one per level."));
    par.addParam(RichEnum(kRecords, 0,
                          {"Mesh records (compact, fast to load)", "Face records (one per triangle)"},
                          "Geometry records",
                          "Mesh records are compact; Face records suit old tools."));
    par.addParam(RichEnum(kColors, 0, {"As the layer has them", "One colour per part"}, "Colours",
                          "Face (and vertex) colours as the layer has them, or one per CAD part."));
    par.addParam(RichBool(kWholeSet, true, "Write the whole LOD set",
                          "All levels of the layer's LOD set; off: this layer."));
}

int fltExportCapability()
{
    // No face-colour checkbox: meshlabserver passes an empty mask unless told otherwise,
    // so colours are a save parameter ("Colours"), the same in the GUI and headless.
    return vcg::tri::io::Mask::IOM_VERTNORMAL | vcg::tri::io::Mask::IOM_VERTTEXCOORD;
}

bool saveOpenFlight(MeshIOInterface& plugin, const QString& fileName, MeshModel& m, int mask,
                    const RichParameterList& par, vcg::CallBackPos* cb, QString& error)
{
    QElapsedTimer timer;
    timer.start();
    const bool withUvs = (mask & vcg::tri::io::Mask::IOM_VERTTEXCOORD) != 0;
    const bool wholeSet = !par.hasParameter(kWholeSet) || par.getBool(kWholeSet);
    const bool faceColors = !par.hasParameter(kColors) || par.getEnum(kColors) == 0;
    flt::LodModel model;
    model.name = QFileInfo(fileName).completeBaseName().toStdString();
    model.units = unitsParameter(par);
    mesh_io::LevelStats stats;
    if (wholeSet && hasLodLevel(m.cm)) {
        QString why;
        if (!gatherLodSet(m, withUvs, faceColors, model, stats, why)) {
            error = fileName + ": cannot write the LOD set of layer " + m.label() + ": " + why;
            report(plugin, GLLogStream::WARNING, error);
            return false;
        }
    } else {
        flt::Level level = mesh_io::meshToLevel(m.cm, levelOptions(m, withUvs, faceColors), stats);
        level.name = recordName(m);
        model.levels.push_back(std::move(level));
    }
    if (model.triangleCount() == 0) {
        error = fileName + ": layer " + m.label() + " has no triangles to write";
        report(plugin, GLLogStream::WARNING, error);
        return false;
    }
    flt::WriteOptions options = writeOptions(par);
    ProgressReporter progress(cb);
    if (cb)
        options.progress = [&progress](int percent) { progress(percent, "Writing OpenFlight"); };
    std::string why;
    flt::WriteStats written;
    if (!flt::writeOpenFlightFile(fileName.toStdString(), model, options, why, &written)) {
        error = QString::fromStdString(why);
        report(plugin, GLLogStream::WARNING, error);
        return false;
    }
    report(plugin, GLLogStream::FILTER, QString::asprintf("OpenFlight %s: %zu LOD level(s), %zu object(s), %zu triangles, %zu vertices, %zu bytes "
               "(%.1f bytes/triangle), %s records, units %s, %zu degenerate face(s) skipped, %lld ms",
               qUtf8Printable(fileName), model.levels.size(), written.objects, written.triangles,
               written.vertices, written.bytes,
               written.triangles ? double(written.bytes) / double(written.triangles) : 0.0,
               options.geometry == flt::GeometryRecords::Meshes ? "Mesh" : "Face", flt::unitsName(model.units),
               stats.skippedFaces, static_cast<long long>(timer.elapsed())));
    progress.finish("OpenFlight saved");  // replaces "Writing OpenFlight" in the status bar
    return true;
}

}  // namespace cadlod
