#include "simplify_filter.h"

#include "core/compactness.h"
#include "core/simplify.h"

#include <vcg/complex/algorithms/clean.h>

namespace cadlod {
namespace {

SimplifyParams readParams(const RichParameterList& par)
{
    SimplifyParams p;
    p.targetFaces = par.getInt("targetFaces");
    p.reductionPerc = par.getFloat("reductionPerc");
    p.maxError = par.getFloat("maxError");
    p.tieTolerance = par.getFloat("tieTolerance");
    p.flatTolerance = par.getFloat("flatTolerance");
    p.candidatesPerEdge = par.getInt("candidatesPerEdge");
    p.optimalPlacement = par.getBool("optimalPlacement");
    p.featureAngle = par.getFloat("featureAngle");
    p.preserveBoundary = par.getBool("preserveBoundary");
    p.boundaryWeight = par.getFloat("boundaryWeight");
    p.preserveTopology = par.getBool("preserveTopology");
    p.normalCheck = par.getBool("normalCheck");
    p.normalThreshold = par.getFloat("normalThreshold");
    p.minCompactness = par.getFloat("minCompactness");
    p.qualityThreshold = par.getFloat("qualityThreshold");
    p.planarQuadric = par.getBool("planarQuadric");
    p.keepPartBorders = par.getBool("keepPartBorders");
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
    const SimplifyParams d;
    const int half = (m.cm.sfn > 0 ? m.cm.sfn : m.cm.fn) / 2;
    par.addParam(RichInt("targetFaces", half, "Target number of faces",
                         "Stop at this many faces (0: not used). With several stop criteria, the first met wins."));
    par.addParam(RichFloat("reductionPerc", 0, "Reduction (%)",
                           "If non-zero, stop after removing this percentage of the faces (90 keeps 10 %)."));
    par.addParam(RichFloat("maxError", 0, "Max error (fraction of bbox diagonal)",
                           "If non-zero, no collapse moves the surface further than this (RMS distance to the "
                           "original planes it replaces), e.g. 0.0001 = 0.01 % of the diagonal."));
    par.addParam(RichFloat("tieTolerance", d.tieTolerance, "Tie tolerance (relative)",
                           "Placements whose quadric cost is within this fraction of the cheapest are tied; the "
                           "tied placement with the most compact triangles wins."));
    par.addParam(RichFloat("flatTolerance", d.flatTolerance, "Flat tolerance (fraction of diagonal)",
                           "Absolute tie floor for flat regions, as an RMS distance relative to the diagonal."));
    par.addParam(RichInt("candidatesPerEdge", d.candidatesPerEdge, "Candidates per edge",
                         "Evenly spaced points tried along each edge, besides its ends and the quadric optimum."));
    par.addParam(RichBool("optimalPlacement", d.optimalPlacement, "Optimal placement",
                          "Also try the quadric optimum (when well conditioned and near the edge)."));
    par.addParam(RichFloat("featureAngle", d.featureAngle, "Feature angle (degrees)",
                           "Edges whose faces meet at a sharper angle are creases: they keep their vertices."));
    par.addParam(RichBool("preserveBoundary", d.preserveBoundary, "Preserve boundary",
                          "Boundary edges are features: boundary vertices stay on the boundary polyline."));
    par.addParam(RichFloat("boundaryWeight", d.boundaryWeight, "Boundary/crease weight",
                           "Weight of the constraint quadrics of boundary edges, creases and part borders."));
    par.addParam(RichBool("preserveTopology", d.preserveTopology, "Preserve topology",
                          "Refuse collapses that would change the genus or make the mesh non-manifold."));
    par.addParam(RichBool("normalCheck", d.normalCheck, "Normal check",
                          "Refuse collapses that turn a face by more than the normal threshold or against its "
                          "input orientation."));
    par.addParam(RichFloat("normalThreshold", d.normalThreshold, "Normal threshold (degrees)",
                           "Largest rotation of a face normal in one collapse."));
    par.addParam(RichFloat("minCompactness", d.minCompactness, "Minimum compactness",
                           "Never create a triangle less compact than this, unless the neighbourhood was already "
                           "worse."));
    par.addParam(RichFloat("qualityThreshold", d.qualityThreshold, "Quality threshold",
                           "Collapses whose new triangles have a mean compactness below this wait longer."));
    par.addParam(RichBool("planarQuadric", d.planarQuadric, "Planar quadrics",
                          "Tiny extra quadrics on every edge: steadier flat regions."));
    par.addParam(RichBool("keepPartBorders", d.keepPartBorders, "Keep part borders",
                          "Edges between faces of different CAD parts (cadlod_part attribute) are features."));
    par.addParam(RichBool("selectedOnly", m.cm.sfn > 0, "Selected faces only",
                          "Only collapse vertices whose faces are all selected."));
    par.addParam(RichBool("autoClean", true, "Post-simplification cleaning",
                          "Remove null faces, duplicated and unreferenced vertices, compact the layer."));
}

bool cadSimplify(MeshFilterInterface& plugin, MeshModel& m, const RichParameterList& par, vcg::CallBackPos* cb,
                 QString& error)
{
    const SimplifyParams params = readParams(par);
    m.updateDataMask(MeshModel::MM_VERTFACETOPO | MeshModel::MM_VERTMARK);
    const CompactnessStats before = meshCompactness(m.cm);
    const SimplifyStats s = simplify(m.cm, params, cb);
    if (!s.ok) {
        error = QString("CAD Quadric Edge Collapse on %1: %2").arg(m.label(), QString::fromStdString(s.message));
        plugin.Log("%s", qUtf8Printable(error));
        return false;
    }
    if (!s.message.empty())
        plugin.Log("CAD Quadric Edge Collapse on %s: %s", qUtf8Printable(m.label()), s.message.c_str());
    if (par.getBool("autoClean"))
        cleanUp(plugin, m);
    m.UpdateBoxAndNormals();
    vcg::tri::UpdateNormal<CMeshO>::NormalizePerFace(m.cm);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexFromCurrentFaceNormal(m.cm);
    vcg::tri::UpdateNormal<CMeshO>::NormalizePerVertex(m.cm);

    const CompactnessStats after = meshCompactness(m.cm);
    plugin.Log("CAD Quadric Edge Collapse on %s: %d -> %d faces (target %d) in %.3f s, %d collapses",
               qUtf8Printable(m.label()), s.facesBefore, m.cm.fn, s.targetFaces, s.seconds, s.collapses);
    plugin.Log("Compactness mean %.4f -> %.4f, p5 %.4f -> %.4f, below 0.1: %.2f%% -> %.2f%%", before.mean,
               after.mean, before.p5, after.p5, 100 * before.shareBelow01, 100 * after.shareBelow01);
    plugin.Log("Largest collapse error %.6g (%.5f%% of the bbox diagonal %.6g)", s.largestError,
               100 * s.largestErrorFraction(), s.diagonal);
    plugin.Log("Features: %d creases/part borders, %d boundary edges, %d non-manifold edges and %d degenerate "
               "faces (their vertices locked); refused: %d flips, %d shape, %d feature, %d error, %d topology",
               s.featureEdges, s.boundaryEdges, s.nonManifoldEdges, s.degenerateFaces, s.rejectedFlip,
               s.rejectedCompactness, s.rejectedFeature, s.rejectedError, s.rejectedTopology);
    return true;
}

}  // namespace cadlod
