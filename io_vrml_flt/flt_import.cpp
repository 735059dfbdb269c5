// Opening an OpenFlight file: the openflight/ core reads it into the neutral LOD model,
// and one level (the finest by default) becomes the layer through
// mesh_io/lod_model_to_mesh.h (normals, face colors, the part attributes of
// layer_metadata.h); here: parameters, logging, the layer's optional components.
#include "format_adapters.h"

#include "openflight/flt_reader.h"
#include "convert/lod_model_to_mesh.h"
#include "mesh/layer_metadata.h"

#include <QElapsedTimer>

#include <algorithm>

#include <cstdio>

namespace cadlod {
namespace {

const char* const kLevel = "level";

void fillLayer(const flt::Level& level, MeshModel& m, int& mask)
{
    const bool normals = mesh_io::levelHasNormals(level);
    const bool uvs = mesh_io::levelHasUvs(level);
    m.updateDataMask(MeshModel::MM_FACECOLOR);
    if (uvs)
        m.updateDataMask(MeshModel::MM_VERTTEXCOORD);
    mesh_io::levelToMesh(level, m.cm);
    mask |= vcg::tri::io::Mask::IOM_FACECOLOR;
    if (normals)
        mask |= vcg::tri::io::Mask::IOM_VERTNORMAL;
    if (uvs)
        mask |= vcg::tri::io::Mask::IOM_VERTTEXCOORD;
    if (std::any_of(level.parts.begin(), level.parts.end(), [](const flt::Part& p) { return p.hasVertexColors(); })) {
        m.updateDataMask(MeshModel::MM_VERTCOLOR);
        mask |= vcg::tri::io::Mask::IOM_VERTCOLOR;
    }
}

double metresPer(flt::Units units)
{
    switch (units) {
    case flt::Units::Meters: return 1.0;
    case flt::Units::Kilometers: return 1000.0;
    case flt::Units::Feet: return 0.3048;
    case flt::Units::Inches: return 0.0254;
    case flt::Units::NauticalMiles: return 1852.0;
    }
    return 0.0;
}

}  // namespace

void fltOpenParameters(RichParameterList& par)
{
    par.addParam(RichInt(kLevel, -1, "LOD level",
                         "Which LOD level to open, numbered in file order from 0; -1 opens the finest "
                         "(the one shown nearest to the viewer)."));
}

bool openOpenFlight(MeshIOInterface& plugin, const QString& fileName, MeshModel& m, int& mask,
                    const RichParameterList& par, vcg::CallBackPos* cb, QString& error)
{
    QElapsedTimer timer;
    timer.start();
    flt::LodModel model;
    flt::ReadStats stats;
    flt::ReadOptions options;
    ProgressReporter progress(cb);
    if (cb)
        options.progress = [&progress](int percent) { progress(percent, "Reading OpenFlight"); };
    std::string why;
    if (!flt::readOpenFlightFile(fileName.toStdString(), model, why, &stats, options)) {
        error = QString::fromStdString(why);
        report(plugin, GLLogStream::WARNING, error);
        return false;
    }
    if (model.levels.empty() || model.triangleCount() == 0) {
        error = fileName + ": the OpenFlight file holds no triangles";
        report(plugin, GLLogStream::WARNING, error);
        return false;
    }
    const int asked = par.hasParameter(kLevel) ? par.getInt(kLevel) : -1;
    if (asked >= int(model.levels.size())) {
        error = fileName + QString(": LOD level %1 asked for, the file has %2 (0..%3)")
                               .arg(asked).arg(model.levels.size()).arg(model.levels.size() - 1);
        report(plugin, GLLogStream::WARNING, error);
        return false;
    }
    const std::size_t chosen = asked < 0 ? flt::finestLevel(model) : std::size_t(asked);
    fillLayer(model.levels[chosen], m, mask);
    setMetresPerUnit(m.cm, metresPer(model.units));
    report(plugin, GLLogStream::FILTER, QString::asprintf("OpenFlight %s (revision %d, %s): %zu LOD level(s), opened level %zu \"%s\" with %zu part(s), "
               "%d vertices, %d triangles; %zu face(s) skipped, %zu record(s) not interpreted, %lld ms",
               qUtf8Printable(fileName), stats.formatRevision, flt::unitsName(model.units), model.levels.size(),
               chosen, model.levels[chosen].name.c_str(), model.levels[chosen].parts.size(), m.cm.vn, m.cm.fn,
               stats.skippedFaces, stats.unknownRecords, static_cast<long long>(timer.elapsed())));
    progress.finish("OpenFlight opened");  // replaces "Reading OpenFlight" in the status bar
    return true;
}

}  // namespace cadlod
