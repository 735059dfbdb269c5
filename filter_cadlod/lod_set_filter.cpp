#include "lod_set_filter.h"

#include "hierarchical_lod_file.h"

#include "lod/copy_with_parts.h"
#include "lod/lod_builder.h"  // buildLodSet<CMeshO>: compiled in cores_for_cmesho.cpp
#include "lod/lod_chain.h"    // buildLodChain<CMeshO>: likewise
#include "mesh/layer_metadata.h"
#include "simplify_parameters.h"
#include "lod/level_names.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <QElapsedTimer>

#include <memory>

namespace cadlod {
namespace {

int nextSetId(MeshDocument& md)
{
    int id = 0;
    for (MeshModel* mm : md.meshList)
        if (hasLodLevel(mm->cm))
            id = std::max(id, lodLevelHandle(mm->cm)().setId);
    return id + 1;
}

bool chainMode(const RichParameterList& par) { return par.getEnum("levelMode") == 0; }

// Per part and cluster (the hierarchy written to a file) rather than one LOD node as layers.
bool perPartAndCluster(const RichParameterList& par)
{
    return par.hasParameter("hierarchy") && par.getEnum("hierarchy") >= 1;
}

// Hierarchy 1 is `--hlod auto`, 2 `calls`, 3 `instances`.
ClusterMode clusterMode(const RichParameterList& par)
{
    switch (par.getEnum("hierarchy")) {
    case 2:
        return ClusterMode::FewestCalls;
    case 3:
        return ClusterMode::Instances;
    default:
        return ClusterMode::Auto;
    }
}

ViewParams readView(const RichParameterList& par)
{
    ViewParams v;
    v.fovYDegrees = par.getFloat("fovY");
    v.viewportHeightPx = par.getInt("viewportHeight");
    v.pixelThreshold = par.getFloat("pixelError");
    return v;
}

LodSetOptions readListOptions(const RichParameterList& par)
{
    LodSetOptions o;
    o.levels = par.getString("levels").toStdString();
    o.spec = par.getEnum("levelUnit") == 0 ? LevelSpec::ReductionPercent : LevelSpec::FaceCount;
    o.fromOriginal = par.getBool("fromOriginal");
    o.view = readView(par);
    o.hausdorffSamples = std::size_t(std::max(0, par.getInt("samples")));
    readPlacementParameters(par, o.simplify);
    return o;
}

LodChainOptions readChainOptions(const RichParameterList& par)
{
    LodChainOptions o;
    o.view = readView(par);
    o.distanceRatio = par.getFloat("distanceRatio");
    o.proxyPixels = par.getFloat("proxyPixels");
    o.cullPixels = par.getFloat("cullPixels");
    o.hausdorffSamples = std::size_t(std::max(0, par.getInt("samples")));
    readPlacementParameters(par, o.simplify);
    return o;
}

QString validateView(const ViewParams& v)
{
    if (!(v.fovYDegrees > 0 && v.fovYDegrees < 180))
        return "the vertical field of view must be between 0 and 180 degrees";
    if (v.viewportHeightPx < 1)
        return "the viewport height must be at least one pixel";
    if (!(v.pixelThreshold > 0))
        return "the pixel error must be positive";
    return {};
}

// A level's error in pixels where it is switched in (0 for level 0).
double pixelsAtSwitchIn(const LodLevel& l, const ViewParams& view)
{
    if (!(l.switchOut > 0))
        return 0.0;
    return l.hausdorffMax * view.viewportHeightPx /
           (2.0 * l.switchOut * std::tan(0.5 * view.fovYDegrees * M_PI / 180.0));
}

QString distanceText(double d, int digits = 4)
{
    return d >= kNeverCulled ? QString("inf") : QString::number(d, 'g', digits);
}

// One line per level, words and numbers only: MeshLab's log is HTML, where aligned columns
// collapse and a '<' starts a tag.
void logLevels(MeshFilterInterface& plugin, const LodSetResult& r, const ViewParams& view, double seconds)
{
    plugin.Log("CAD LOD set: %d levels in %.2f s (%.2f s of it measuring the levels against level 0); model size "
               "%.6g (errors and distances in model units)",
               int(r.levels.size()), seconds, r.measureSeconds, r.modelSize);
    for (std::size_t k = 0; k < r.levels.size(); ++k) {
        const LodLevel& l = r.levels[k];
        const CompactnessStats& c = r.compactness[k];
        plugin.Log("LOD%d: %d faces (%.2f %% of level 0), error %.4g = %.4f %% of the size = %.2f px at switch-in, "
                   "drawn from %s to %s, compactness mean %.3f, slivers %.1f %%",
                   l.level, l.faces, r.levels[0].faces ? 100.0 * l.faces / r.levels[0].faces : 0.0, l.hausdorffMax,
                   r.modelSize > 0 ? 100.0 * l.hausdorffMax / r.modelSize : 0.0, pixelsAtSwitchIn(l, view),
                   qUtf8Printable(distanceText(l.switchOut)), qUtf8Printable(distanceText(l.switchIn)), c.mean,
                   100.0 * c.shareBelow01);
        if (k > 0 && !r.steps[k - 1].weightTrials.empty())
            plugin.Log("LOD%d: %s", l.level, r.steps[k - 1].weightTrials.c_str());
        if (k > 0)
            for (const std::string& step : r.steps[k - 1].relaxed)
                plugin.Log("LOD%d: %s", l.level, step.c_str());
    }
}

// Names every level by its distance, shows level 0 alone (the levels lie on top of each
// other) and lets Export Mesh As propose the input's folder and name for any level.
void presentLevels(MeshDocument& md, MeshModel& original, MeshModel& level0, const std::vector<MeshModel*>& kept,
                   const LodSetResult& result)
{
    const double metres = metresPerUnit(original.cm);
    const QFileInfo input(original.fullName().isEmpty() ? original.label() : original.fullName());
    const std::string base = input.completeBaseName().toStdString();
    // Never the input's own name: exporting a level must not overwrite what the user opened.
    const QString exportName = original.fullName().isEmpty() ? QString() : input.absolutePath() + "/" +
                                                                              input.completeBaseName() + "_lod.flt";
    auto present = [&](MeshModel& layer, const LodLevel& l, const std::string& suffix) {
        const std::string range = levelRangeName(l.level, l.switchOut, l.switchIn, metres);
        layer.setLabel(QString::fromStdString(levelLabel(base, range, suffix)));
        if (&layer != &original && !exportName.isEmpty())
            layer.setFileName(exportName);
    };
    const QString suffix = QFileInfo(level0.label()).suffix();
    present(level0, result.levels[0], suffix.isEmpty() ? ".flt" : "." + suffix.toStdString());
    for (std::size_t k = 0; k < kept.size(); ++k) {
        present(*kept[k], result.levels[k + 1], ".flt");
        kept[k]->visible = false;
    }
    level0.visible = true;
    if (&level0 != &original)
        original.visible = false;  // the same geometry as its copy, level 0
    // The views copy every layer's visibility when the layer list changes, not after a
    // filter: tell them.
    emit md.meshSetChanged();
}

}  // namespace

void lodSetParameters(MeshModel& m, RichParameterList& par)
{
    const LodChainOptions chain;
    par.addParam(RichEnum("levelMode", 0, {"By screen-space error (VR)", "Level list (the paper)"}, "Levels by",
                          "Screen-space error: levels down to a few px high. Level list: the values below."));
    par.addParam(RichString("levels", "50 60 70 80 90", "Level list",
                            "With Level list: one value per level, coarser each time (the paper: 50 60 70 80 90)."));
    par.addParam(RichEnum("levelUnit", 0, {"Reduction %", "Face count"}, "Level list unit",
                          "How the values of the level list are read."));
    par.addParam(RichBool("fromOriginal", false, "List levels from the original",
                          "Level list: each level from the original."));
    par.addParam(RichFloat("fovY", 45.0f, "Vertical field of view (deg)",
                           "Camera of the simulator, for the switch distances."));
    par.addParam(RichInt("viewportHeight", 1080, "Viewport height (px)",
                         "Screen height of the simulator, for the switch distances."));
    par.addParam(RichFloat("pixelError", 1.0f, "Pixel error",
                           "A level is drawn only where its measured error is smaller than this on screen."));
    par.addParam(RichFloat("distanceRatio", float(chain.distanceRatio), "Distance ratio",
                           "Screen-space error: each level serves this many times farther than the one before."));
    par.addParam(RichFloat("proxyPixels", float(chain.proxyPixels), "Proxy size (px)",
                           "Screen-space error: below this height on screen, one box per part stands in."));
    par.addParam(RichFloat("cullPixels", float(chain.cullPixels), "Cull below (px)",
                           "Not drawn when smaller than this on screen; 0: always drawn."));
    par.addParam(RichInt("samples", 0, "Hausdorff samples",
                         "Surface samples per side to measure each level; 0: automatic."));
    addFeatureParameters(par);
    par.addParam(RichEnum("hierarchy", 0,
                          {"One LOD node: the levels as layers", "Per part and cluster: to a file",
                           "Per part and cluster, fewest draw calls: to a file",
                           "Per part and cluster, instances near the viewer: to a file"},
                          "Hierarchy",
                          "Per part and cluster (VRML assemblies, seen from inside): writes the HLOD file."));
    par.addParam(RichSaveFile("hierarchyFile", defaultHierarchyFile(m), ".flt", "HLOD file",
                              "Per part and cluster writes here (empty: beside the input, _hlod.flt)."));
}

bool generateLodSet(MeshFilterInterface& plugin, MeshDocument& md, const RichParameterList& par,
                    vcg::CallBackPos* cb, QString& error)
{
    MeshModel& original = *md.mm();
    const ViewParams view = readView(par);
    error = validateView(view);
    if (!error.isEmpty())
        return false;
    if (perPartAndCluster(par)) {
        if (!chainMode(par)) {
            error = "per part and cluster needs levels by screen-space error: a level list has no error to switch "
                    "a proxy by";
            return false;
        }
        return writeHierarchicalLod(plugin, original, readChainOptions(par), clusterMode(par),
                                    par.getSaveFileName("hierarchyFile"), cb, error);
    }
    const int setId = nextSetId(md);
    if (original.cm.fn == 0) {
        error = "the current layer has no faces";
        return false;
    }
    const QString baseName = QFileInfo(original.label()).completeBaseName();
    std::vector<MeshModel*> layers;
    // A layer that already belongs to a set (level 0 of an earlier run, or one of its
    // levels) keeps its record: the new set starts from a copy of it, its own level 0.
    MeshModel* level0 = &original;
    if (hasLodLevel(original.cm)) {
        level0 = md.addNewMesh("", QString("%1 LOD0").arg(baseName), false);
        level0->updateDataMask(&original);
        detail::copyWithParts(level0->cm, original.cm);
        vcg::tri::UpdateBounding<CMeshO>::Box(level0->cm);
        layers.push_back(level0);
        plugin.Log("CAD LOD set: %s already belongs to LOD set %d; LOD set %d starts from a copy of it (%s)",
                   qUtf8Printable(original.label()), lodLevelHandle(original.cm)().setId, setId,
                   qUtf8Printable(level0->label()));
    }
    level0->updateDataMask(MeshModel::MM_VERTFACETOPO | MeshModel::MM_VERTMARK);
    vcg::tri::Allocator<CMeshO>::CompactEveryVector(level0->cm);
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(level0->cm);

    auto newLevel = [&](int k) -> CMeshO& {
        MeshModel* layer = md.addNewMesh("", QString("%1 LOD%2").arg(baseName).arg(k), false);
        layer->updateDataMask(level0);
        layer->updateDataMask(MeshModel::MM_VERTFACETOPO | MeshModel::MM_VERTMARK);
        layers.push_back(layer);
        return layer->cm;
    };

    QElapsedTimer timer;
    timer.start();
    LodSetResult result;
    if (chainMode(par)) {
        LodChainOptions options = readChainOptions(par);
        options.setId = setId;
        options.runTogether = runOnTwoThreads;
        // The chain simplifies scratch copies of the model's pieces level after level. A
        // MeshModel gives them CMeshO's optional components, enabled like level 0's; it is
        // never added to the document, so the layer panel and the views never see it.
        std::vector<std::unique_ptr<MeshModel>> scratch;
        auto newScratch = [&]() -> CMeshO& {
            scratch.push_back(std::make_unique<MeshModel>(&md, "", QString("%1 scratch").arg(baseName)));
            scratch.back()->updateDataMask(level0);
            scratch.back()->updateDataMask(MeshModel::MM_VERTFACETOPO | MeshModel::MM_VERTMARK);
            return scratch.back()->cm;
        };
        CMeshO& working = newScratch();
        result = buildLodChain<CMeshO>(level0->cm, working, options, newLevel, cb, newScratch);
    } else {
        LodSetOptions options = readListOptions(par);
        options.setId = setId;
        options.runTogether = runOnTwoThreads;
        result = buildLodSet<CMeshO>(level0->cm, options, newLevel, cb);
    }
    if (!result.ok()) {
        for (MeshModel* layer : layers)
            md.delMesh(layer);
        error = QString::fromStdString(result.error);
        return false;
    }
    const std::size_t firstLevel = level0 == &original ? 0 : 1;  // layers[0] is the copy
    std::vector<MeshModel*> kept;
    for (std::size_t i = firstLevel; i < layers.size(); ++i) {
        const int level = int(i - firstLevel) + 1;
        const auto& dropped = result.droppedLevels;
        if (std::find(dropped.begin(), dropped.end(), level) != dropped.end())
            md.delMesh(layers[i]);
        else
            kept.push_back(layers[i]);
    }
    for (const std::string& warning : result.warnings)
        plugin.Log(GLLogStream::WARNING, "CAD LOD set: %s", warning.c_str());
    for (MeshModel* layer : kept)
        layer->UpdateBoxAndNormals();
    presentLevels(md, original, *level0, kept, result);
    logLevels(plugin, result, view, timer.elapsed() / 1000.0);
    return true;
}

}  // namespace cadlod
