#include "simplify_parameters.h"

namespace cadlod {

void addFeatureParameters(RichParameterList& par)
{
    const SimplifyParams d;
    par.addParam(RichFloat("featureAngle", d.featureAngle, "Feature angle (degrees)",
                           "Sharper edges are creases: their vertices only move along them."));
    par.addParam(RichBool("preserveBoundary", d.preserveBoundary, "Preserve boundary",
                          "Boundary edges are features: boundary vertices stay on the boundary."));
    par.addParam(RichBool("keepPartBorders", d.keepPartBorders, "Keep part borders",
                          "Edges between CAD parts (cadlod_part attribute) are features, also where the parts "
                          "meet flat and in one colour. Off: creases and colour borders between parts are "
                          "still kept."));
    par.addParam(RichBool("keepColorBorders", d.keepColorBorders, "Keep colour borders",
                          "Edges between face colours are features (ignored above 256 colours)."));
    par.addParam(RichFloat("featurePenalty", d.featurePenalty, "Feature penalty",
                           "A feature gives way only where that costs this many times less (0: never)."));
}

void addPlacementParameters(RichParameterList& par)
{
    const SimplifyParams d;
    par.addParam(RichFloat("tieTolerance", d.tieTolerance, "Tie tolerance (relative)",
                           "Placements within this fraction of the cheapest cost are tied; compactness decides."));
    par.addParam(RichFloat("flatTolerance", d.flatTolerance, "Flat tolerance (fraction of diagonal)",
                           "Collapses within this RMS distance (a fraction of the diagonal) are free: they may slide a "
                           "feature vertex along its feature, but must not make a sliver."));
    par.addParam(RichInt("candidatesPerEdge", d.candidatesPerEdge, "Candidates per edge",
                         "Points tried along each edge, besides its ends and the quadric optimum."));
    par.addParam(RichBool("optimalPlacement", d.optimalPlacement, "Optimal placement",
                          "Also try the quadric optimum or, where its planes meet in a line, the point of that line "
                          "nearest the edge's middle (when near the edge)."));
    par.addParam(RichFloat("boundaryWeight", d.boundaryWeight, "Boundary/crease weight",
                           "Weight of the constraint quadrics of boundaries, creases and borders."));
    par.addParam(RichBool("preserveTopology", d.preserveTopology, "Preserve topology",
                          "Refuse collapses that change the genus or make the mesh non-manifold."));
    par.addParam(RichBool("closeTunnels", d.closeTunnels, "Close tunnels",
                          "With Preserve topology: a tunnel (a through-hole) whose rim has shrunk to three edges may be cut and capped, priced like a feature break (logged); in the far field of a screen-space LOD chain the topology gives way altogether (thin parts flatten into two-sided sheets, holes close). Off: both are kept."));
    par.addParam(RichBool("normalCheck", d.normalCheck, "Normal check",
                          "Refuse collapses that turn a face too far or against its input side; price like a feature break one that turns a face away from the input surface nearest to it."));
    par.addParam(RichFloat("normalThreshold", d.normalThreshold, "Normal threshold (degrees)",
                           "Largest turn of a face normal in one collapse."));
    par.addParam(RichFloat("minCompactness", d.minCompactness, "Minimum compactness",
                           "No new triangle less compact than this unless it was worse already (0: off)."));
    par.addParam(RichFloat("qualityThreshold", d.qualityThreshold, "Quality threshold",
                           "Free collapses making triangles less compact than this wait longer."));
    par.addParam(RichFloat("largeFaceWeight", d.largeFaceWeight, "Large-face weight",
                           "Share of a face's full area added to the nearly equal weight every face's plane gets: large faces (a plate's top) keep their place. 0: all faces weigh the same."));
    par.addParam(RichBool("weightTrials", d.weightTrialsMaxFaces > 0, "Try plane weights",
                          "A mesh of fewer than 200 000 faces with a face target is first simplified on copies with the large-face weight times 1, 10 and 40, and once with the boundary/crease weight at a quarter (and, where at most a tenth of the faces is left, times 200 with features at their plain quadric cost, with and without their constraint planes, and times 10 with no new fold past 30° between faces that met smoothly; where at least half of the faces stay, once without the shape guard and with the boundary/crease weight at a tenth), two at a time on two cores, and the weights whose result is nearest the input (Hausdorff distance, the share of the surface lit differently, slivers, faces turned over) are used (logged), or, where it has at least a point fewer slivers within 1.1 times the distance and 1.15 times the shading, their run with slivers removed first. Off: the large-face weight as given."));
    par.addParam(RichFloat("shadingWeight", d.shadingWeight, "Shading weight",
                           "A collapse that turns faces more than the shading angle from their input faces also costs this times the squared bbox diagonal times their area times (1 - cos of the turn). 0: geometry alone."));
    par.addParam(RichFloat("shadingAngle", d.shadingAngle, "Shading angle (degrees)",
                           "Faces turned less than this from their input faces keep their shade: not priced."));
    par.addParam(RichBool("planarQuadric", d.planarQuadric, "Planar quadrics",
                          "Tiny extra quadrics on every edge: steadier flat regions."));
    par.addParam(RichBool("relaxToReachTarget", d.relaxToReachTarget, "Reach the target",
                          "Cut non-manifold edges apart; when blocked: allow less compact triangles, then drop small parts (logged)."));
    addFeatureParameters(par);
}

void readPlacementParameters(const RichParameterList& par, SimplifyParams& p)
{
    if (par.hasParameter("tieTolerance"))
        p.tieTolerance = par.getFloat("tieTolerance");
    if (par.hasParameter("weightTrials") && !par.getBool("weightTrials"))
        p.weightTrialsMaxFaces = 0;
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
    if (par.hasParameter("closeTunnels"))
        p.closeTunnels = par.getBool("closeTunnels");
    if (par.hasParameter("normalCheck"))
        p.normalCheck = par.getBool("normalCheck");
    if (par.hasParameter("normalThreshold"))
        p.normalThreshold = par.getFloat("normalThreshold");
    if (par.hasParameter("minCompactness"))
        p.minCompactness = par.getFloat("minCompactness");
    if (par.hasParameter("qualityThreshold"))
        p.qualityThreshold = par.getFloat("qualityThreshold");
    if (par.hasParameter("largeFaceWeight"))
        p.largeFaceWeight = par.getFloat("largeFaceWeight");
    if (par.hasParameter("shadingWeight"))
        p.shadingWeight = par.getFloat("shadingWeight");
    if (par.hasParameter("shadingAngle"))
        p.shadingAngle = par.getFloat("shadingAngle");
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
