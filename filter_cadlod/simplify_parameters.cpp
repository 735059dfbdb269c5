#include "simplify_parameters.h"

namespace cadlod {

void addFeatureParameters(RichParameterList& par)
{
    const SimplifyParams d;
    par.addParam(RichFloat("featureAngle", d.featureAngle, "Feature angle (degrees)",
                           "Edges whose faces meet at a sharper angle are creases: they stay sharp, and their "
                           "vertices only move along them."));
    par.addParam(RichBool("preserveBoundary", d.preserveBoundary, "Preserve boundary",
                          "Boundary edges are features: boundary vertices stay on the boundary polyline."));
    par.addParam(RichBool("keepPartBorders", d.keepPartBorders, "Keep part borders",
                          "Edges between faces of different CAD parts (cadlod_part attribute) are features."));
    par.addParam(RichBool("keepColorBorders", d.keepColorBorders, "Keep colour borders",
                          "Edges between faces of different colours (materials) are features; ignored when "
                          "the faces have more than 256 colours (a painted measure)."));
    par.addParam(RichFloat("featurePenalty", d.featurePenalty, "Feature penalty",
                           "A collapse that breaks a feature (crease, corner, boundary, border) runs only when "
                           "it costs this many times less than the alternatives. 0: features never give way."));
}

void addPlacementParameters(RichParameterList& par)
{
    const SimplifyParams d;
    par.addParam(RichFloat("tieTolerance", d.tieTolerance, "Tie tolerance (relative)",
                           "Placements whose quadric cost is within this fraction of the cheapest are tied; the "
                           "tied placement with the most compact triangles wins."));
    par.addParam(RichFloat("flatTolerance", d.flatTolerance, "Flat tolerance (fraction of diagonal)",
                           "Absolute tie floor for flat regions, as an RMS distance relative to the diagonal."));
    par.addParam(RichInt("candidatesPerEdge", d.candidatesPerEdge, "Candidates per edge",
                         "Evenly spaced points tried along each edge, besides its ends and the quadric optimum."));
    par.addParam(RichBool("optimalPlacement", d.optimalPlacement, "Optimal placement",
                          "Also try the quadric optimum (when well conditioned and near the edge)."));
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
                           "worse. Collapses that cost no error (flat regions, straight lines) must not create one "
                           "below 0.1 either. 0: no shape guard."));
    par.addParam(RichFloat("qualityThreshold", d.qualityThreshold, "Quality threshold",
                           "Collapses that cost (almost) no error, in flat regions and along straight lines, wait longer "
                           "when their new triangles have a mean compactness below this. 0: ordered by area only."));
    par.addParam(RichBool("planarQuadric", d.planarQuadric, "Planar quadrics",
                          "Tiny extra quadrics on every edge: steadier flat regions."));
    par.addParam(RichBool("relaxToReachTarget", d.relaxToReachTarget, "Reach the target",
                          "When the face target is blocked: allow less compact triangles, and remove the "
                          "smallest separate parts whole when cheaper; each step is logged."));
    addFeatureParameters(par);
}

void readPlacementParameters(const RichParameterList& par, SimplifyParams& p)
{
    if (par.hasParameter("tieTolerance"))
        p.tieTolerance = par.getFloat("tieTolerance");
    if (par.hasParameter("flatTolerance"))
        p.flatTolerance = par.getFloat("flatTolerance");
    if (par.hasParameter("candidatesPerEdge"))
        p.candidatesPerEdge = par.getInt("candidatesPerEdge");
    if (par.hasParameter("optimalPlacement"))
        p.optimalPlacement = par.getBool("optimalPlacement");
    if (par.hasParameter("featureAngle"))
        p.featureAngle = par.getFloat("featureAngle");
    if (par.hasParameter("preserveBoundary"))
        p.preserveBoundary = par.getBool("preserveBoundary");
    if (par.hasParameter("boundaryWeight"))
        p.boundaryWeight = par.getFloat("boundaryWeight");
    if (par.hasParameter("preserveTopology"))
        p.preserveTopology = par.getBool("preserveTopology");
    if (par.hasParameter("normalCheck"))
        p.normalCheck = par.getBool("normalCheck");
    if (par.hasParameter("normalThreshold"))
        p.normalThreshold = par.getFloat("normalThreshold");
    if (par.hasParameter("minCompactness"))
        p.minCompactness = par.getFloat("minCompactness");
    if (par.hasParameter("qualityThreshold"))
        p.qualityThreshold = par.getFloat("qualityThreshold");
    if (par.hasParameter("planarQuadric"))
        p.planarQuadric = par.getBool("planarQuadric");
    if (par.hasParameter("keepPartBorders"))
        p.keepPartBorders = par.getBool("keepPartBorders");
    if (par.hasParameter("keepColorBorders"))
        p.keepColorBorders = par.getBool("keepColorBorders");
    if (par.hasParameter("featurePenalty"))
        p.featurePenalty = par.getFloat("featurePenalty");
    if (par.hasParameter("relaxToReachTarget"))
        p.relaxToReachTarget = par.getBool("relaxToReachTarget");
}

}  // namespace cadlod
