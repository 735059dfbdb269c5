#include "lod_set_filter.h"

#include "core/lod_builder.h"
#include "simplify_parameters.h"

#include <QElapsedTimer>

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

LodSetOptions readOptions(const RichParameterList& par)
{
    LodSetOptions o;
    o.levels = par.getString("levels").toStdString();
    o.spec = par.getEnum("levelUnit") == 0 ? LevelSpec::ReductionPercent : LevelSpec::FaceCount;
    o.fromOriginal = par.getBool("fromOriginal");
    o.view.fovYDegrees = par.getFloat("fovY");
    o.view.viewportHeightPx = par.getInt("viewportHeight");
    o.view.pixelThreshold = par.getFloat("pixelError");
    o.hausdorffSamples = std::size_t(std::max(0, par.getInt("samples")));
    readPlacementParameters(par, o.simplify);
    return o;
}

QString validateView(const LodSetOptions& o)
{
    if (!(o.view.fovYDegrees > 0 && o.view.fovYDegrees < 180))
        return "the vertical field of view must be between 0 and 180 degrees";
    if (o.view.viewportHeightPx < 1)
        return "the viewport height must be at least one pixel";
    if (!(o.view.pixelThreshold > 0))
        return "the pixel error must be positive";
    return {};
}

void logTable(MeshFilterInterface& plugin, const LodSetResult& r, double seconds)
{
    plugin.Log("CAD LOD set: %d levels in %.2f s (model size %.6g, errors in model units)",
               int(r.levels.size()), seconds, r.modelSize);
    plugin.Log("level  reduction  triangles  hausdorff max  (% diag)  mean  switch out..in  compactness mean  <0.1");
    for (std::size_t k = 0; k < r.levels.size(); ++k) {
        const LodLevel& l = r.levels[k];
        const CompactnessStats& c = r.compactness[k];
        plugin.Log("%5d  %8.1f%%  %9d  %13.6g  (%6.3f%%)  %.6g  %.6g..%.6g  %.3f  %.1f%%", l.level,
                   100.0 * l.reduction, l.faces, l.hausdorffMax,
                   r.modelSize > 0 ? 100.0 * l.hausdorffMax / r.modelSize : 0.0, l.hausdorffMean,
                   l.switchOut, l.switchIn, c.mean, 100.0 * c.shareBelow01);
    }
}

}  // namespace

void lodSetParameters(MeshModel&, RichParameterList& par)
{
    par.addParam(RichString("levels", "50 60 70 80 90", "Levels",
                            "One value per level, coarser each time: reductions in % of the "
                            "original's faces (the paper uses 50 60 70 80 90) or face counts."));
    par.addParam(RichEnum("levelUnit", 0, {"Reduction %", "Face count"}, "Level unit",
                          "How the values in Levels are read."));
    par.addParam(RichBool("fromOriginal", false, "Simplify each level from the original",
                          "Off: level k is made from level k-1 (faster). On: every level is "
                          "made from the original."));
    par.addParam(RichFloat("fovY", 45.0f, "Vertical field of view (deg)",
                           "Camera of the simulator, for the switch distances."));
    par.addParam(RichInt("viewportHeight", 1080, "Viewport height (px)",
                         "Screen height of the simulator, for the switch distances."));
    par.addParam(RichFloat("pixelError", 1.0f, "Pixel error",
                           "A level is switched in once its geometric error (symmetric Hausdorff "
                           "distance to the original) projects to fewer pixels than this."));
    par.addParam(RichInt("samples", 0, "Hausdorff samples",
                         "Surface samples per side for the error of each level; 0 = as many "
                         "as the original has faces."));
    addPlacementParameters(par);
}

bool generateLodSet(MeshFilterInterface& plugin, MeshDocument& md, const RichParameterList& par,
                    vcg::CallBackPos* cb, QString& error)
{
    MeshModel& original = *md.mm();
    LodSetOptions options = readOptions(par);
    error = validateView(options);
    if (!error.isEmpty())
        return false;
    if (original.cm.fn == 0) {
        error = "the current layer has no faces";
        return false;
    }
    options.setId = nextSetId(md);
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
                   qUtf8Printable(original.label()), lodLevelHandle(original.cm)().setId, options.setId,
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
    const LodSetResult result = buildLodSet<CMeshO>(level0->cm, options, newLevel, cb);
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
    for (std::size_t k = 0; k < kept.size(); ++k) {
        kept[k]->setLabel(QString("%1 LOD%2 (%3 faces)").arg(baseName).arg(k + 1).arg(kept[k]->cm.fn));
        kept[k]->UpdateBoxAndNormals();
    }
    logTable(plugin, result, timer.elapsed() / 1000.0);
    return true;
}

}  // namespace cadlod
