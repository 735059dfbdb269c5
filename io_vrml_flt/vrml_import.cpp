// VRML import adapter: runs the MeshLab-independent reader (vrml/) and copies its
// neutral scene into a CMeshO, with the part table and per-face part ids that the
// simplifier and the OpenFlight exporter read (filter_cadlod/metadata/layer_metadata.h).
#include "format_adapters.h"

#include "layer_metadata.h"
#include "vrml/importer.h"
#include "vrml/vertex_welding.h"

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
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

vcg::Color4b toColor(const vrml::Rgba8& c) { return vcg::Color4b(c[0], c[1], c[2], c[3]); }

vcg::Color4b toColor(const std::array<float, 4>& c)
{
    auto b = [](float x) { return (unsigned char)std::lround(std::clamp(x, 0.0f, 1.0f) * 255.0f); };
    return vcg::Color4b(b(c[0]), b(c[1]), b(c[2]), b(c[3]));
}

// Index of `texture` in the mesh's texture list (added if new); -1 for none.
short textureIndexOf(CMeshO& m, const std::string& texture)
{
    if (texture.empty()) return -1;
    auto it = std::find(m.textures.begin(), m.textures.end(), texture);
    if (it != m.textures.end()) return short(it - m.textures.begin());
    m.textures.push_back(texture);
    return short(m.textures.size() - 1);
}

void setWedgeTexCoord(CFaceO& f, int k, const vrml::Part& part, uint32_t vertex, short textureIndex)
{
    if (part.texCoords.empty()) {
        f.WT(k) = vcg::TexCoord2f(0, 0);
        f.WT(k).N() = -1;
        return;
    }
    f.WT(k) = vcg::TexCoord2f(part.texCoords[vertex][0], part.texCoords[vertex][1]);
    f.WT(k).N() = textureIndex;
}

bool hasTexCoords(const vrml::Scene& scene)
{
    return std::any_of(scene.parts.begin(), scene.parts.end(), [](const vrml::Part& p) { return !p.texCoords.empty(); });
}

// Moves the scene into `m` (each part's arrays are freed once copied, to keep the peak
// memory low); with `welding`, coincident vertices become one vertex whose normal is the
// normalized sum of theirs (the first one's color wins).
void moveScene(vrml::Scene& scene, const vrml::Welding* welding, CMeshO& m, vcg::CallBackPos* cb)
{
    const size_t vertexCount = welding ? welding->weldedCount : scene.vertexCount();
    const size_t base = m.vert.size();
    vcg::tri::Allocator<CMeshO>::AddVertices(m, vertexCount);
    auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, scene.triangleCount());
    std::vector<bool> written(welding ? vertexCount : 0, false);
    auto partOf = facePartHandle(m);
    PartTable& table = partTableHandle(m)();
    table.clear();
    size_t sceneVertex = 0, done = 0;
    const size_t triangleCount = scene.triangleCount();
    const bool wedgeTexCoords = vcg::tri::HasPerWedgeTexCoord(m);
    std::vector<CVertexO*> partVertex;
    for (size_t p = 0; p < scene.parts.size(); ++p) {
        vrml::Part& part = scene.parts[p];
        table.push_back(part);
        const vcg::Color4b partColor = toColor(part.color);
        partVertex.resize(part.positions.size());
        for (size_t i = 0; i < part.positions.size(); ++i, ++sceneVertex) {
            const size_t target = welding ? welding->weldedIndex[sceneVertex] : sceneVertex;
            CVertexO& v = m.vert[base + target];
            partVertex[i] = &v;
            const vcg::Point3f normal = part.normals.empty()
                                            ? vcg::Point3f(0, 0, 0)
                                            : vcg::Point3f(part.normals[i][0], part.normals[i][1], part.normals[i][2]);
            if (welding && written[target]) {
                v.N() += normal;
                continue;
            }
            if (welding) written[target] = true;
            v.P() = vcg::Point3f(part.positions[i][0], part.positions[i][1], part.positions[i][2]);
            v.N() = normal;
            v.C() = part.colors.empty() ? partColor : toColor(part.colors[i]);
        }
        const short textureIndex = textureIndexOf(m, part.texture);
        for (size_t t = 0; t < part.triangleCount(); ++t, ++fi) {
            for (int k = 0; k < 3; ++k) {
                const uint32_t local = part.triangles[3 * t + size_t(k)];
                fi->V(k) = partVertex[local];
                if (wedgeTexCoords) setWedgeTexCoord(*fi, k, part, local, textureIndex);
            }
            fi->C() = part.faceColors.empty() ? partColor : toColor(part.faceColors[t]);
            partOf[fi] = int(p);
        }
        done += part.triangleCount();
        part = vrml::Part{};
        if (cb) cb(60 + int(30.0 * double(done) / double(std::max<size_t>(1, triangleCount))), "Building mesh");
    }
    if (welding)
        for (size_t i = base; i < m.vert.size(); ++i) m.vert[i].N().Normalize();
}

int mergeCloseVertices(CMeshO& m, float tolerance)
{
    const int merged = vcg::tri::Clean<CMeshO>::MergeCloseVertex(m, tolerance);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(m);
    return merged;
}

// meshlabserver's -i path never gives an IO plugin a log (MeshLabInterface::Log is then
// a no-op), so every report also goes to stderr.
void report(MeshIOInterface& plugin, GLLogStream::Levels level, const std::string& text)
{
    plugin.Log(level, text);
    std::fprintf(stderr, "io_vrml_flt: %s\n", text.c_str());
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
    if (cb) options.progress = [cb](double f) { cb(int(60 * f), "Reading VRML"); };

    vrml::ImportResult result = vrml::importVrmlFile(fileName.toStdString(), options);
    if (!result.ok()) {
        error = QString::fromStdString(result.error);
        report(plugin, GLLogStream::WARNING, result.error);
        return false;
    }
    vrml::Scene& scene = result.scene;
    const size_t sceneVertices = scene.vertexCount();
    const qint64 parsedMs = timer.elapsed();
    mask = vcg::tri::io::Mask::IOM_VERTNORMAL | vcg::tri::io::Mask::IOM_VERTCOLOR | vcg::tri::io::Mask::IOM_FACECOLOR;
    if (hasTexCoords(scene)) mask |= vcg::tri::io::Mask::IOM_WEDGTEXCOORD;
    m.Enable(mask);
    const bool merge = !par.hasParameter(kMergeVertices) || par.getBool(kMergeVertices);
    const float tolerance = par.hasParameter(kMergeTolerance) ? par.getFloat(kMergeTolerance) : 0.0f;
    vrml::Welding welding;
    if (merge) welding = vrml::weldCoincidentVertices(scene);
    int merged = merge ? int(sceneVertices - welding.weldedCount) : 0;
    moveScene(scene, merge ? &welding : nullptr, m.cm, cb);
    welding = {};
    if (merge && tolerance > 0) merged += mergeCloseVertices(m.cm, tolerance);
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(m.cm);
    vcg::tri::UpdateBounding<CMeshO>::Box(m.cm);

    const double seconds = std::max(1e-6, timer.elapsed() / 1000.0);
    char line[1024];
    std::snprintf(line, sizeof line,
                  "VRML %d import of %s: %zu parts, %d triangles, %d vertices (%d merged), %zu shapes, "
                  "%zu faces skipped, %zu line/point sets ignored, %zu inlines; %.1f MB in %.2f s (read %.2f s), "
                  "%.1f MB/s",
                  scene.version == 1 ? 1 : 2, qUtf8Printable(fileName), partTableHandle(m.cm)().size(), m.cm.fn,
                  m.cm.vn, merged, scene.stats.shapes, scene.stats.skippedFaces,
                  scene.stats.lineSets + scene.stats.pointSets, scene.stats.inlinesLoaded, scene.stats.bytesRead / 1e6,
                  seconds, parsedMs / 1000.0, scene.stats.bytesRead / 1e6 / seconds);
    report(plugin, GLLogStream::FILTER, line);
    logDiagnostics(plugin, scene.diagnostics);
    if (cb) cb(100, "VRML import done");
    return true;
}

}  // namespace cadlod
