// Saving a layer as OpenFlight: translates the layer (or, when it belongs to an LOD set,
// every layer of that set in the document) into the neutral LOD model and lets the
// openflight/ core write it. Vertex normals are always written: OpenFlight geometry is
// only lit with them (light mode 2).
#include "format_adapters.h"

#include "layer_metadata.h"
#include "flt_writer.h"
#include "lod_assembly.h"

#include <QElapsedTimer>

#include <cstdio>
#include <QFileInfo>

#include <map>

namespace cadlod {
namespace {

// meshlabserver never prints an IO plugin's log, so every report also goes to stderr.
void report(MeshIOInterface& plugin, GLLogStream::Levels level, const QString& text)
{
    plugin.Log(level, text.toStdString());
    std::fprintf(stderr, "io_vrml_flt: %s\n", qUtf8Printable(text));
}

const char* const kUnits = "units";
const char* const kDrawType = "drawType";
const char* const kObjects = "objects";
const char* const kRecords = "records";
const char* const kWholeSet = "wholeLodSet";

const flt::Units kUnitChoices[] = {flt::Units::Meters, flt::Units::Kilometers, flt::Units::Feet,
                                   flt::Units::Inches, flt::Units::NauticalMiles};

flt::Rgba toRgba(const vcg::Color4b& c)
{
    return {c[0] / 255.0f, c[1] / 255.0f, c[2] / 255.0f, c[3] / 255.0f};
}

// Area-weighted face normals summed at the vertices: the fallback for vertices whose
// stored normal is zero or not finite.
std::vector<vcg::Point3f> fallbackNormals(const CMeshO& m)
{
    std::vector<vcg::Point3f> n(m.vert.size(), vcg::Point3f(0, 0, 0));
    for (const CFaceO& f : m.face)
        if (!f.IsD())
            for (int k = 0; k < 3; ++k)
                n[vcg::tri::Index(m, f.cV(k))] += vcg::TriangleNormal(f);
    for (vcg::Point3f& v : n)
        if (v.Norm() > 0)
            v.Normalize();
    return n;
}

flt::Part partWith(const PartIdentity& identity)
{
    flt::Part part;
    static_cast<PartIdentity&>(part) = identity;
    return part;
}

bool usableNormal(const vcg::Point3f& n)
{
    const float len = n.Norm();
    return std::isfinite(len) && len > 1e-12f;
}

// Faces grouped into parts: by the VRML importer's part attribute when present, else
// by face color when the layer has face colors, else one part.
struct PartGrouping {
    std::vector<int> partOfFace;
    std::vector<flt::Part> parts;  // names and colors only
};

PartGrouping groupFaces(MeshModel& mm)
{
    CMeshO& m = mm.cm;
    PartGrouping g;
    g.partOfFace.assign(m.face.size(), 0);
    const std::string label = mm.label().toStdString();
    if (hasParts(m)) {
        auto facePart = facePartHandle(m);
        const PartTable table = partTableHandle(m)();
        for (const PartIdentity& info : table)
            g.parts.push_back(partWith(info));
        const int unassigned = int(g.parts.size());
        g.parts.push_back(partWith({label + "_unassigned"}));
        for (std::size_t i = 0; i < m.face.size(); ++i) {
            const int p = facePart[i];
            g.partOfFace[i] = p >= 0 && p < unassigned ? p : unassigned;
        }
        return g;
    }
    if (mm.hasDataMask(MeshModel::MM_FACECOLOR)) {
        std::map<std::uint32_t, int> byColor;
        for (std::size_t i = 0; i < m.face.size(); ++i) {
            const vcg::Color4b c = m.face[i].cC();
            const std::uint32_t key = std::uint32_t(c[0]) << 24 | std::uint32_t(c[1]) << 16 | c[2] << 8 | c[3];
            auto [it, added] = byColor.emplace(key, int(g.parts.size()));
            if (added)
                g.parts.push_back(partWith({label + (byColor.size() > 1 ? "_" + std::to_string(byColor.size()) : ""),
                                            toRgba(c)}));
            g.partOfFace[i] = it->second;
        }
        if (!g.parts.empty())
            return g;
    }
    g.parts.push_back(partWith({label}));
    return g;
}

struct LayerStats {
    std::size_t skippedFaces = 0;
};

// One layer as one neutral level: indexed parts with positions, normals and (optionally)
// texture coordinates; degenerate faces are skipped and counted.
flt::Level layerLevel(MeshModel& mm, bool withUvs, LayerStats& stats)
{
    CMeshO& m = mm.cm;
    PartGrouping g = groupFaces(mm);
    const std::vector<vcg::Point3f> fallback = fallbackNormals(m);
    const bool uvs = withUvs && mm.hasDataMask(MeshModel::MM_VERTTEXCOORD);
    std::vector<std::vector<std::int64_t>> localIndex(g.parts.size());
    for (std::size_t i = 0; i < m.face.size(); ++i) {
        const CFaceO& f = m.face[i];
        if (f.IsD())
            continue;
        if (f.cV(0) == f.cV(1) || f.cV(1) == f.cV(2) || f.cV(0) == f.cV(2)) {
            ++stats.skippedFaces;
            continue;
        }
        const int p = g.partOfFace[i];
        flt::Part& part = g.parts[std::size_t(p)];
        std::vector<std::int64_t>& index = localIndex[std::size_t(p)];
        if (index.empty())
            index.assign(m.vert.size(), -1);
        flt::Triangle tri;
        for (int k = 0; k < 3; ++k) {
            const std::size_t vi = vcg::tri::Index(m, f.cV(k));
            if (index[vi] < 0) {
                index[vi] = std::int64_t(part.positions.size());
                const CVertexO& v = m.vert[vi];
                part.positions.push_back({double(v.cP()[0]), double(v.cP()[1]), double(v.cP()[2])});
                vcg::Point3f n = usableNormal(v.cN()) ? v.cN() : fallback[vi];
                if (n.Norm() > 0)
                    n.Normalize();
                part.normals.push_back({n[0], n[1], n[2]});
                if (uvs)
                    part.uvs.push_back({v.cT().U(), v.cT().V()});
            }
            tri[k] = std::uint32_t(index[vi]);
        }
        part.triangles.push_back(tri);
    }
    flt::Level level;
    for (flt::Part& p : g.parts)
        if (!p.triangles.empty())
            level.parts.push_back(std::move(p));
    return level;
}

// Every layer of the document that belongs to the same LOD set as `mm`.
bool gatherLodSet(MeshModel& mm, bool withUvs, flt::LodModel& model, LayerStats& stats, QString& error)
{
    const int setId = lodLevelHandle(mm.cm)().setId;
    std::vector<flt::LodSetMember> members;
    const QList<MeshModel*> layers = mm.parent ? mm.parent->meshList : QList<MeshModel*>{&mm};
    for (MeshModel* layer : layers) {
        if (!layer || !hasLodLevel(layer->cm))
            continue;
        const LodLevel info = lodLevelHandle(layer->cm)();
        if (info.setId != setId)
            continue;
        flt::LodSetMember member;
        member.setId = info.setId;
        member.level = info.level;
        member.geometry = layerLevel(*layer, withUvs, stats);
        member.geometry.switchIn = info.switchIn;
        member.geometry.switchOut = info.switchOut;
        member.geometry.center = info.center;
        members.push_back(std::move(member));
    }
    std::string why;
    if (!flt::assembleLodSet(std::move(members), setId, model, why)) {
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
                          "Units", "Unit of the vertex coordinates, stored in the OpenFlight header. "
                          "Coordinates are written as they are (no scaling)."));
    par.addParam(RichEnum(kDrawType, 0, {"Single-sided (back faces culled)", "Two-sided"}, "Draw type",
                          "Two-sided for open CAD surfaces seen from both sides."));
    par.addParam(RichEnum(kObjects, 0, {"One Object per part", "One Object per level"}, "Objects",
                          "One OpenFlight Object per CAD part (names kept in Long ID records), or one per LOD level."));
    par.addParam(RichEnum(kRecords, 0,
                          {"Mesh records (compact, fast to load)", "Face records (one per triangle)"},
                          "Geometry records",
                          "Mesh records: a local vertex pool and one triangle strip per part. "
                          "Face records: a shared vertex palette and one Face per triangle, for old tools."));
    par.addParam(RichBool(kWholeSet, true, "Write the whole LOD set",
                          "When the layer belongs to an LOD set, write every level of the set with its "
                          "switch distances; otherwise only this layer."));
}

int fltExportCapability()
{
    return vcg::tri::io::Mask::IOM_VERTNORMAL | vcg::tri::io::Mask::IOM_FACECOLOR |
           vcg::tri::io::Mask::IOM_VERTTEXCOORD;
}

bool saveOpenFlight(MeshIOInterface& plugin, const QString& fileName, MeshModel& m, int mask,
                    const RichParameterList& par, vcg::CallBackPos* cb, QString& error)
{
    QElapsedTimer timer;
    timer.start();
    const bool withUvs = (mask & vcg::tri::io::Mask::IOM_VERTTEXCOORD) != 0;
    const bool wholeSet = !par.hasParameter(kWholeSet) || par.getBool(kWholeSet);
    flt::LodModel model;
    model.name = QFileInfo(fileName).completeBaseName().toStdString();
    model.units = unitsParameter(par);
    LayerStats stats;
    if (wholeSet && hasLodLevel(m.cm)) {
        QString why;
        if (!gatherLodSet(m, withUvs, model, stats, why)) {
            error = fileName + ": cannot write the LOD set of layer " + m.label() + ": " + why;
            report(plugin, GLLogStream::WARNING, error);
            return false;
        }
    } else {
        flt::Level level = layerLevel(m, withUvs, stats);
        level.name = m.label().toStdString();
        model.levels.push_back(std::move(level));
    }
    if (model.triangleCount() == 0) {
        error = fileName + ": layer " + m.label() + " has no triangles to write";
        report(plugin, GLLogStream::WARNING, error);
        return false;
    }
    flt::WriteOptions options = writeOptions(par);
    if (cb)
        options.progress = [cb](int percent) { cb(percent, "Writing OpenFlight"); };
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
    return true;
}

}  // namespace cadlod
