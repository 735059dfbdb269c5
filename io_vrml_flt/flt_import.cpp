// Opening an OpenFlight file: the openflight/ core reads it into the neutral LOD model,
// and one level (the finest by default) becomes the layer, with per-vertex normals,
// face colors from the part colors and the part attributes of layer_metadata.h.
#include "format_adapters.h"

#include "layer_metadata.h"
#include "flt_reader.h"

#include <QElapsedTimer>

#include <cstdio>

namespace cadlod {
namespace {

// meshlabserver never prints an IO plugin's log, so every report also goes to stderr.
void report(MeshIOInterface& plugin, GLLogStream::Levels level, const QString& text)
{
    plugin.Log(level, text.toStdString());
    std::fprintf(stderr, "io_vrml_flt: %s\n", qUtf8Printable(text));
}

const char* const kLevel = "level";

vcg::Color4b toColor(const flt::Rgba& c)
{
    auto byte = [](float v) { return static_cast<unsigned char>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
    return vcg::Color4b(byte(c[0]), byte(c[1]), byte(c[2]), byte(c[3]));
}

bool allPartsHave(const flt::Level& level, bool (flt::Part::*has)() const)
{
    for (const flt::Part& p : level.parts)
        if (!(p.*has)())
            return false;
    return !level.parts.empty();
}

void fillLayer(const flt::Level& level, MeshModel& m, int& mask)
{
    CMeshO& cm = m.cm;
    const bool normals = allPartsHave(level, &flt::Part::hasNormals);
    const bool uvs = allPartsHave(level, &flt::Part::hasUvs);
    m.updateDataMask(MeshModel::MM_FACECOLOR);
    if (uvs)
        m.updateDataMask(MeshModel::MM_VERTTEXCOORD);
    auto facePart = facePartHandle(cm);
    PartTable table;
    for (std::size_t p = 0; p < level.parts.size(); ++p) {
        const flt::Part& part = level.parts[p];
        table.push_back(part);
        auto v = vcg::tri::Allocator<CMeshO>::AddVertices(cm, part.positions.size());
        const std::size_t firstVertex = std::size_t(vcg::tri::Index(cm, &*v));
        for (std::size_t i = 0; i < part.positions.size(); ++i, ++v) {
            v->P() = vcg::Point3f(float(part.positions[i][0]), float(part.positions[i][1]), float(part.positions[i][2]));
            if (normals)
                v->N() = vcg::Point3f(part.normals[i][0], part.normals[i][1], part.normals[i][2]);
            if (uvs)
                v->T() = vcg::TexCoord2f(part.uvs[i][0], part.uvs[i][1]);
        }
        auto f = vcg::tri::Allocator<CMeshO>::AddFaces(cm, part.triangles.size());
        for (const flt::Triangle& t : part.triangles) {
            for (int k = 0; k < 3; ++k)
                f->V(k) = &cm.vert[firstVertex + t[k]];
            f->C() = toColor(part.color);
            facePart[f] = int(p);
            ++f;
        }
    }
    partTableHandle(cm)() = table;
    mask |= vcg::tri::io::Mask::IOM_FACECOLOR;
    if (normals)
        mask |= vcg::tri::io::Mask::IOM_VERTNORMAL;
    if (uvs)
        mask |= vcg::tri::io::Mask::IOM_VERTTEXCOORD;
    vcg::tri::UpdateBounding<CMeshO>::Box(cm);
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
    if (cb)
        options.progress = [cb](int percent) { cb(percent, "Reading OpenFlight"); };
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
    report(plugin, GLLogStream::FILTER, QString::asprintf("OpenFlight %s (revision %d, %s): %zu LOD level(s), opened level %zu \"%s\" with %zu part(s), "
               "%d vertices, %d triangles; %zu face(s) skipped, %zu record(s) not interpreted, %lld ms",
               qUtf8Printable(fileName), stats.formatRevision, flt::unitsName(model.units), model.levels.size(),
               chosen, model.levels[chosen].name.c_str(), model.levels[chosen].parts.size(), m.cm.vn, m.cm.fn,
               stats.skippedFaces, stats.unknownRecords, static_cast<long long>(timer.elapsed())));
    return true;
}

}  // namespace cadlod
