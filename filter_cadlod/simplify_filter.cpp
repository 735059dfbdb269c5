#include "simplify_filter.h"

#include "simplify_parameters.h"

#include "measure/compactness.h"
#include "simplify/best_of_trials.h"
#include "mesh/layer_metadata.h"

#include <vcg/complex/algorithms/clean.h>

namespace cadlod {
namespace {

SimplifyParams readParams(const RichParameterList& par)
{
    SimplifyParams p;
    p.targetFaces = par.getInt("targetFaces");
    p.reductionPerc = par.getFloat("reductionPerc");
    p.maxError = par.getFloat("maxError");
    readPlacementParameters(par, p);
    p.selectedOnly = par.getBool("selectedOnly");
    return p;
}

// As MeshLab's own quadric filter does after simplifying.
void cleanUp(MeshFilterInterface& plugin, MeshModel& m)
{
    const int nullFaces = vcg::tri::Clean<CMeshO>::RemoveFaceOutOfRangeArea(m.cm, 0);
    const int duplicates = vcg::tri::Clean<CMeshO>::RemoveDuplicateVertex(m.cm);
    const int unreferenced = vcg::tri::Clean<CMeshO>::RemoveUnreferencedVertex(m.cm);
    if (nullFaces || duplicates || unreferenced)
        plugin.Log("Post-simplification cleaning: removed %d null faces, %d duplicated and %d unreferenced vertices",
                   nullFaces, duplicates, unreferenced);
    m.clearDataMask(MeshModel::MM_FACEFACETOPO);
    vcg::tri::Allocator<CMeshO>::CompactVertexVector(m.cm);
    vcg::tri::Allocator<CMeshO>::CompactFaceVector(m.cm);
}

}  // namespace

void cadSimplifyParameters(MeshModel& m, RichParameterList& par)
{
    // The defaults do not depend on the mesh, so that a script gives in meshlabserver what
    // the same values give in the GUI.
    par.addParam(RichInt("targetFaces", 0, "Target number of faces",
                         "Stop at this many faces; used when Reduction is 0."));
    par.addParam(RichFloat("reductionPerc", 50, "Reduction (%)",
                           "Stop after removing this % of the faces (90 keeps 10 %); wins over the face count."));
    par.addParam(RichFloat("maxError", 0, "Max error (fraction of bbox diagonal)",
                           "No collapse moves the surface further than this, e.g. 0.0001 (0: off)."));
    addPlacementParameters(par);
    par.addParam(RichBool("selectedOnly", m.cm.sfn > 0, "Selected faces only",
                          "Collapse only inside the selection."));
    par.addParam(RichBool("autoClean", true, "Post-simplification cleaning",
                          "Remove null faces and unused vertices."));
}

bool cadSimplify(MeshFilterInterface& plugin, MeshModel& m, const RichParameterList& par, vcg::CallBackPos* cb,
                 QString& error)
{
    const SimplifyParams params = readParams(par);
    m.updateDataMask(MeshModel::MM_VERTFACETOPO | MeshModel::MM_VERTMARK);
    const CompactnessStats before = meshCompactness(m.cm);
    // A mesh of a few hundred thousand faces or more collapses on two cores (collapse_halves.h).
    const SimplifyStats s = bestOfTrials(m.cm, params, cb, runOnTwoThreads);
    if (!s.ok) {
        error = QString("CAD Quadric Edge Collapse on %1: %2").arg(m.label(), QString::fromStdString(s.message));
        plugin.Log("%s", qUtf8Printable(error));
        return false;
    }
    if (!s.message.empty())
        plugin.Log("CAD Quadric Edge Collapse on %s: %s", qUtf8Printable(m.label()), s.message.c_str());
    if (!s.weightTrials.empty())
        plugin.Log("CAD Quadric Edge Collapse on %s: %s", qUtf8Printable(m.label()), s.weightTrials.c_str());
    for (const std::string& step : s.relaxed)
        plugin.Log("CAD Quadric Edge Collapse on %s: relaxed: %s", qUtf8Printable(m.label()), step.c_str());
    if (par.getBool("autoClean"))
        cleanUp(plugin, m);
    // A level of an LOD set simplified again no longer matches its record (faces, error,
    // switch ranges): it leaves the set rather than be exported with stale ranges.
    if (hasLodLevel(m.cm) && (s.collapses > 0 || m.cm.fn != s.facesBefore)) {
        const LodLevel stale = lodLevelHandle(m.cm)();
        clearLodLevel(m.cm);
        plugin.Log("CAD Quadric Edge Collapse on %s: the layer was level %d of LOD set %d; simplified again, it "
                   "leaves the set (its level record no longer matches it)",
                   qUtf8Printable(m.label()), stale.level, stale.setId);
    }
    m.UpdateBoxAndNormals();
    vcg::tri::UpdateNormal<CMeshO>::NormalizePerFace(m.cm);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexFromCurrentFaceNormal(m.cm);
    vcg::tri::UpdateNormal<CMeshO>::NormalizePerVertex(m.cm);

    const CompactnessStats after = meshCompactness(m.cm);
    plugin.Log("CAD Quadric Edge Collapse on %s: %d -> %d faces (target %d) in %.3f s, %d collapses; stopped by: %s",
               qUtf8Printable(m.label()), s.facesBefore, m.cm.fn, s.targetFaces, s.seconds, s.collapses,
               s.stoppedBy.c_str());
    if (s.halvesCollapses > 0)
        plugin.Log("CAD Quadric Edge Collapse on %s: %d of the collapses made on two halves side by side (a band of "
                   "%d vertices between them left to the end)",
                   qUtf8Printable(m.label()), s.halvesCollapses, s.halvesBandVertices);
    plugin.Log("Compactness mean %.4f -> %.4f, p5 %.4f -> %.4f, below 0.1: %.2f%% -> %.2f%%", before.mean,
               after.mean, before.p5, after.p5, 100 * before.shareBelow01, 100 * after.shareBelow01);
    plugin.Log("Largest collapse error %.6g (%.5f%% of the bbox diagonal %.6g)", s.largestError,
               100 * s.largestErrorFraction(), s.diagonal);
    plugin.Log("Features: %d creases/part borders, %d boundary edges, %d non-manifold edges (locked); %d faces "
               "repeating a vertex deleted; %d collapses broke a feature, %d parts removed whole, %d tunnels closed; "
               "refused: %d flips, %d shape, %d feature, %d error, %d topology",
               s.featureEdges, s.boundaryEdges, s.nonManifoldEdges, s.degenerateFaces, s.featureBreaks,
               s.removedComponents, s.closedTunnels, s.rejectedFlip, s.rejectedCompactness, s.rejectedFeature,
               s.rejectedError, s.rejectedTopology);
    return true;
}

}  // namespace cadlod
