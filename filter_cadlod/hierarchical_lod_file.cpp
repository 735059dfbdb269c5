#include "hierarchical_lod_file.h"

#include "assembly/assembly_convert.h"
#include "assembly/hierarchical_lod.h"
#include "assembly/progress_spans.h"
#include "mesh/layer_metadata.h"
#include "openflight/local_origin.h"
#include "vrml/assembly.h"
#include "vrml/importer.h"

#include <QElapsedTimer>
#include <QFileInfo>

#include <exception>

namespace cadlod {
namespace {

// Reading the file takes this share of the progress; writing it the last few percent.
constexpr int kReadingEnd = 10, kWritingStart = 95;
// The parts' chains take this share of the rest when proxies follow them.
constexpr int kPartsShare = 70;

// As the layer was read, so that the file holds the layer's coordinates, but with the shared
// parts kept.
vrml::ImportOptions importOptions(const VrmlSource& source)
{
    vrml::ImportOptions o;
    o.unitScale = source.unitScale;
    o.detectKicadUnits = source.detectKicadUnits;
    o.upAxis = source.yUpToZUp ? vrml::UpAxis::YUpToZUp : vrml::UpAxis::Keep;
    o.recomputeNormals = source.recomputeNormals;
    o.instances = vrml::Instances::Keep;
    // The simplifier decides alike in every unit at a power of two (vrml/importer.h).
    o.unitScaling = vrml::UnitScaling::PowerOfTwo;
    return o;
}

// The model name cadlod convert gives: the output's name up to its first dot.
std::string modelName(const QString& output)
{
    const std::string name = QFileInfo(output).fileName().toStdString();
    return name.substr(0, name.find('.'));
}

// Only a .flt name: the VRML input (.wrl, .wrz, .gz) can never be written over.
QString checkOutput(const QString& output)
{
    if (QFileInfo(output).suffix().toLower() != "flt")
        return output + ": the HLOD file is OpenFlight; give it the .flt extension";
    return {};
}

struct Converted {
    AssemblyConversion conversion;
    HierarchyStats hierarchy;
    double lengthScale = 1.0;
    std::size_t centredParts = 0;  // parts whose geometry was moved about its own origin (local_origin.h)
    ClusterMode mode = ClusterMode::Instances;  // what the mode asked came to (resolvedMode)
};

// The assembly of `source`, its placements in clusters with proxies; throws with the reason.
Converted convert(const VrmlSource& source, const LodChainOptions& chain, ClusterMode mode,
                  const std::string& name, CallbackSpans& progress)
{
    vrml::ImportResult imported = vrml::importVrmlFile(source.path, importOptions(source));
    if (!imported.ok())
        throw std::runtime_error(imported.error);
    vrml::Scene& scene = imported.scene;
    if (scene.assembly.empty())  // each named part placed once; a file of one part is that part placed once
        scene.assembly = vrml::partsPlacedOnce(std::move(scene.parts));
    if (scene.assembly.placementCount() == 0)
        throw std::runtime_error(source.path + ": no shape to place");
    Converted out;
    out.lengthScale = imported.assumed.remainingScale;
    LodChainOptions options = chain;
    options.distanceUnit = "m";
    options.distanceScale = out.lengthScale;
    const ProgressSpans spans = progress.spans();
    const auto build = [&](CoreMesh& mesh, LevelStore& store, const ProxyRange& range, vcg::CallBackPos* step) {
        CoreMesh scratch;
        const auto newLevel = [&](int) -> CoreMesh& { return store.add(); };
        return buildLodChain<CoreMesh>(mesh, scratch, proxyChainOptions(options, mesh.fn, range), newLevel, step);
    };
    const PartWelding welding{source.mergeVertices, float(source.mergeTolerance / out.lengthScale)};
    const int partsEnd = kReadingEnd + (kWritingStart - kReadingEnd) * kPartsShare / 100;
    {
        ProgressSpan parts(spans, kReadingEnd, partsEnd);
        out.conversion = convertAssembly(
            scene, name, welding,
            [&](CoreMesh& m, LevelStore& store, vcg::CallBackPos* step) { return build(m, store, {}, step); }, true,
            spans);
    }
    out.mode = resolvedMode(mode, out.conversion.model.placements.size());
    HierarchyOptions hierarchy = hierarchyOptionsOf(out.mode);
    hierarchy.view = chain.view;
    {
        ProgressSpan proxies(spans, partsEnd, kWritingStart);
        out.hierarchy = buildHierarchy(out.conversion, hierarchy, welding, build, spans);
    }
    scaleLengths(out.conversion, out.lengthScale);  // to the layer's unit
    out.centredParts = flt::moveToLocalOrigin(out.conversion.model);
    return out;
}

void logConversion(MeshFilterInterface& plugin, const Converted& c, const QString& output,
                   const flt::InstancedWriteStats& written, double seconds)
{
    const std::size_t placements = c.conversion.model.placements.size();
    const ClusterTreeOptions tree = hierarchyOptionsOf(c.mode).tree;
    plugin.Log("CAD LOD set, per part and cluster: %zu distinct parts in %zu placements, each part's chain once; "
               "%s; "
               "%zu clusters of up to %zu placements (%zu per node%s), %zu with proxies: %zu proxy levels drawing %zu "
               "meshes of %zu triangles, merged from %zu; %zu clusters copies of others (%zu turned, %zu mirrored), "
               "drawing their "
               "meshes moved",
               c.conversion.parts.size(), placements,
               c.mode == ClusterMode::FewestCalls ? "the fewest draw calls near the viewer"
                                                  : "every part its own instance near the viewer",
               c.hierarchy.clusters, tree.leafItems, tree.fanout,
               tree.largeShare > 0 ? ", the largest above" : "", c.hierarchy.proxied, c.hierarchy.proxyLevels,
               c.hierarchy.proxyShapes, c.hierarchy.proxyTriangles, c.hierarchy.inputTriangles, c.hierarchy.copied, c.hierarchy.turned,
               c.hierarchy.mirrored);
    if (c.conversion.stretchedPlacements > 0)
        plugin.Log("CAD LOD set, per part and cluster: %zu placements scale their part unevenly; each such part is "
                   "simplified as stretched as it is seen",
                   c.conversion.stretchedPlacements);
    const std::string originNote = flt::localOriginNote(c.conversion.model, c.centredParts, "model units");
    if (!originNote.empty())
        plugin.Log("CAD LOD set, per part and cluster: %s", originNote.c_str());
    plugin.Log("CAD LOD set, per part and cluster: wrote %s: %zu bytes, %zu triangles in %.2f s (the document is "
               "unchanged: a layer cannot hold instances)",
               qUtf8Printable(output), written.bytes, written.triangles, seconds);
}

}  // namespace

QString defaultHierarchyFile(const MeshModel& layer)
{
    if (layer.fullName().isEmpty())
        return {};
    const QFileInfo input(layer.fullName());
    QString name = input.fileName();
    if (name.endsWith(".gz", Qt::CaseInsensitive))
        name.chop(3);
    return input.absolutePath() + "/" + QFileInfo(name).completeBaseName() + "_hlod.flt";
}

bool writeHierarchicalLod(MeshFilterInterface& plugin, MeshModel& layer, const LodChainOptions& chain,
                          ClusterMode mode, const QString& chosen, vcg::CallBackPos* cb, QString& error)
{
    const QString output = chosen.isEmpty() ? defaultHierarchyFile(layer) : chosen;
    VrmlSource source;
    if (!vrmlSource(layer.cm, source)) {
        error = layer.label() + ": a hierarchical LOD reads the assembly's VRML file again, its shared parts kept; "
                                "open the assembly from its .wrl file";
        return false;
    }
    error = checkOutput(output);
    if (!error.isEmpty())
        return false;
    QElapsedTimer timer;
    timer.start();
    CallbackSpans progress(cb);
    try {
        const Converted c = convert(source, chain, mode, modelName(output), progress);
        flt::InstancedWriteStats written;
        std::string why;
        const ProgressSpans spans = progress.spans();
        ProgressSpan writing(spans, kWritingStart, 100, "Writing OpenFlight");
        if (!flt::writeInstancedOpenFlightFile(output.toStdString(), c.conversion.model, flt::WriteOptions{}, why,
                                               &written)) {
            error = QString::fromStdString(why);
            return false;
        }
        logConversion(plugin, c, output, written, timer.elapsed() / 1000.0);
    } catch (const std::exception& e) {
        error = QString::fromStdString(e.what());
        return false;
    }
    return true;
}

}  // namespace cadlod
