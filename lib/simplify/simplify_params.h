// Parameters and results of the CAD Quadric Edge Collapse (cadlod::simplify).
// Plain data, no vcglib or MeshLab types: the MeshLab filter, the LOD-set filter, the
// tests and the benchmarks all fill a SimplifyParams and read a SimplifyStats. How the
// front ends name, explain and offer the parameters: parameter_table.h.
#pragma once

#include <algorithm>
#include <string>
#include <vector>

namespace cadlod {

struct SimplifyParams {
    // Stop criteria. 0 disables a criterion; at least one must be set. The face count to
    // reach comes from reductionPerc when it is set (it wins over targetFaces, as in
    // MeshLab's own quadric filter), else from targetFaces; maxError is never exceeded by
    // a collapse, whatever the face count.
    int targetFaces = 0;         // stop at this many faces
    double reductionPerc = 0.0;  // stop after removing this % of the input faces (0..100)
    double maxError = 0.0;       // never collapse beyond this error (fraction of bbox diagonal)

    // Placement: candidates are both endpoints, `candidatesPerEdge` evenly spaced interior
    // points and (optimalPlacement) the quadric optimum or, where its planes meet in a line,
    // the point of that line nearest the edge's middle. Those whose cost is within
    // tieTolerance (relative) of the cheapest, or within the rounding of float coordinates,
    // are tied; the tied candidate with the best mean compactness of the surrounding
    // triangles wins.
    double tieTolerance = 0.1;
    // A collapse whose RMS error is within flatTolerance (a fraction of the bbox diagonal)
    // is free: it moves no plane a viewer could see. It may slide a feature vertex along its
    // feature, is not checked against the input surface, and must not make a sliver.
    double flatTolerance = 1e-5;
    int candidatesPerEdge = 3;
    bool optimalPlacement = true;

    // CAD protection.
    double featureAngle = 30.0;      // degrees; sharper edges are creases kept sharp
    bool preserveBoundary = true;    // boundary edges get constraint quadrics
    double boundaryWeight = 1.0;     // multiplier of the boundary/crease constraint weight
    bool preserveTopology = true;    // link condition (no new non-manifold/genus change)
    bool closeTunnels = true;        // with preserveTopology: a tunnel whose rim has shrunk to three
                                     // edges may be cut and capped, ranked like a feature break
                                     // (tunnel_cut.h)
    bool normalCheck = true;         // reject collapses that turn a face by > normalThreshold
    double normalThreshold = 60.0;   // degrees
    bool facingCheck = true;         // with normalCheck: a collapse leaving a face turned over 90° from
                                     // the input surface nearest to it is ranked like a feature break
                                     // (input_surface.h); off in the far field (under 5 % of the faces)
    // An error-bounded session (no face target) keeps the input's points for a far field its
    // caller starts (far_field.h), where each operation is held to the distance it opens
    // (CollapseContext::maxDistance): an LOD chain's far levels, whose budgets are distances
    // a viewer sees.
    bool farFieldWithinBound = false;
    double minCompactness = 0.1;     // never create a face below this unless it improves the worst;
                                     // free collapses not below max(0.1, this); 0: no guard
    double qualityThreshold = 0.3;   // free collapses leaving faces below this compactness wait longer
    double sliverFirstShare = 1.0;   // a collapse removing a sliver along its shortest edge is ranked
                                     // at this share of its priority (1: as any other)
    // While the face target keeps at least this share of the input's faces, a collapse may not
    // add to the slivers (compactness < 0.1) around it either, even above the worst of them:
    // near the input a tessellation's strips of slivers are coarsened, not multiplied. Farther
    // down faces must grow long to follow curved strips, and the count would turn faces over
    // (docs/benchmarks.md). Above 1: never.
    double sliverCountShare = 0.25;
    // Quadric weights: every face weighs about the same (its area capped at 1 % of the mean
    // face area, cad_quadrics.h) plus this share of its full area. The capped weights alone
    // make a plate's large top face count as little as a fillet's sliver: moving a plate corner
    // by the plate's thickness then costs as little as a tiny collapse on the fillet, and far
    // reductions tilt plates into wedges a viewer sees over the whole face. A small share keeps
    // small faces' planes weighing about the same while a face many times the mean weighs many
    // times more. Chosen on the corpus for shading (docs/benchmarks.md).
    double largeFaceWeight = 0.005;
    // Shading: a face that turns more than shadingAngle degrees from the face it was in the
    // input is lit differently over its whole area, which a viewer sees even where the surface
    // moved by a hair (a coarse cylinder's trough flattened into a band). A collapse is also
    // ranked by shadingWeight × diagonal² × the sum over such faces of area × (1 − cos of the
    // turn): the share of the model's size that changes shade. 0: geometry alone. Chosen on
    // the corpus for shading and Hausdorff together (docs/benchmarks.md).
    double shadingWeight = 1e-5;
    double shadingAngle = 12.0;      // degrees
    // With the shape guards: no placement may fold two faces around the new vertex past the
    // angle normals are split at (CreaseFans::kCreaseDegrees: VRML's creaseAngle, the
    // OpenFlight export's smooth fans) where they met below it before the collapse (or did not
    // meet: faces around the two endpoints, joined across a removed face). A
    // coarse fillet folded into two or three facets is drawn flat-shaded, band by band, where
    // its strips were smooth. Off by default: it costs distance on parts whose small details
    // go instead; the weight trials try it at far reductions (weight_trials.h).
    bool keepSmoothJoins = false;
    bool planarQuadric = false;      // tiny edge quadrics everywhere: steadier flat regions
    // Edges between faces of different cadlod_part ids as features: off by default. Parts
    // that are separate solids share no edge, so a part border exists only where the
    // importer welded two parts' coincident vertices, which is where an exporter split one
    // body into several IndexedFaceSets: KiCad writes one per B-rep face, about a hundred
    // for a push button. Those borders are the body's face edges. The ones a viewer sees
    // are creases (featureAngle) or colour changes (keepColorBorders), both still kept; the
    // rest would pin every corner of the body's faces and cost distance for nothing a viewer
    // sees (docs/benchmarks.md). On: every part border is a feature.
    bool keepPartBorders = false;
    bool keepColorBorders = true;    // edges between faces of different colours (materials) are features
    // What a collapse that breaks a feature (crosses a crease, moves a corner or boundary
    // vertex) is ranked at: this many times its quadric cost. 0: features are hard locks.
    double featurePenalty = 4.0;
    // What a collapse that leaves a face turned over 90° from the input surface nearest to it
    // (facingCheck) is ranked at: this many times its priority; 0: refused. Below 0,
    // kFacingOverFeature times featurePenalty (facingPenaltyOf).
    double facingPenalty = -1.0;
    // Cut non-manifold edges apart first (non_manifold_split.h); when the face target is not
    // reached with the shape guards on, relax them; then remove the smallest connected
    // components whole (each logged). Off: stop early, non-manifold edges locked.
    bool relaxToReachTarget = true;
    bool selectedOnly = false;       // only collapse vertices whose faces are all selected
    // A mesh with at least this many faces is first collapsed as two halves side by side
    // (collapse_halves.h), on two cores when the caller gives a RunTogether that runs tasks
    // at once; 0: never. Below it a session takes about a second or less.
    int halvesMinFaces = 200000;
    // A mesh with a face target and fewer faces than this is first simplified on copies with
    // a few plane weights (largeFaceWeight and multiples of it, weight_trials.h), and the
    // weight whose result is closest to the input is used; 0: never. Above it the trials
    // would cost more than a second each.
    int weightTrialsMaxFaces = 200000;
};

// Below this share of its input faces a mesh is in the far field, where the input-surface
// check gives way and, toward a face target, operations are ranked by the largest distance
// they open (far_field.h). The paper's levels stop at 95 %, just above it.
inline constexpr double kFacingFarField = 0.05;

// The face count where the far field starts for a mesh of `faces` (CollapseContext::
// farFieldFloor): a collapse from more faces than this is checked against the input surface.
inline int farFieldFloor(int faces)
{
    return int(kFacingFarField * faces);
}

// A collapse that turns a face away from the input surface is priced at this many times the
// feature penalty, unless facingPenalty says otherwise. A broken feature's error is in the
// quadric (its constraint planes); a face lit as the far side is an error the quadric does
// not see at all.
inline constexpr double kFacingOverFeature = 2.0;

inline double facingPenaltyOf(const SimplifyParams& p)
{
    return p.facingPenalty >= 0 ? p.facingPenalty : kFacingOverFeature * p.featurePenalty;
}

struct SimplifyStats {
    bool ok = false;            // false: nothing was done, `message` says why
    std::string message;        // error, or a note (e.g. target not reached)
    int facesBefore = 0;
    int facesAfter = 0;
    int verticesBefore = 0;
    int verticesAfter = 0;
    int targetFaces = 0;        // the face count the stop criteria asked for
    int collapses = 0;
    double largestError = 0.0;  // largest collapse error (RMS distance to the merged planes), model units
    double diagonal = 0.0;      // bbox diagonal of the input
    double seconds = 0.0;
    // What the input carried.
    int featureEdges = 0;       // creases above the feature angle and part borders
    int boundaryEdges = 0;
    int nonManifoldEdges = 0;   // their vertices are locked
    int degenerateFaces = 0;    // faces repeating a vertex (no area): deleted before the first collapse
    // Why candidate collapses were refused (counted at evaluation time).
    int rejectedFlip = 0;
    int rejectedCompactness = 0;
    int rejectedFeature = 0;
    int rejectedError = 0;
    int rejectedTopology = 0;
    // What gave way so that the target could be reached (simplify.h's relaxation ladder).
    int featureBreaks = 0;         // executed collapses that broke a feature (priced, not refused)
    int removedComponents = 0;     // connected components removed whole
    double largestRemovedComponent = 0.0;  // bbox diagonal, model units
    int closedTunnels = 0;         // loops of three edges cut and capped (tunnel_cut.h)
    int boundaryJoins = 0;         // collapses that closed a hole or joined boundary runs (link_condition.h)
    int halvesCollapses = 0;       // collapses made by two half sessions side by side (collapse_halves.h)
    int halvesBandVertices = 0;    // the band between the halves, frozen while they ran
    double widestTunnelCap = 0.0;  // the largest cap inradius, model units
    double errorBound = 0.0;       // the maximum collapse error in force, model units (0: none)
    std::vector<std::string> relaxed;  // one line per relaxation step, for the log
    std::string weightTrials;      // the plane-weight trials and the weight kept (empty: none ran)
    std::string stoppedBy;         // which criterion ended the run: "face target", "max error", ...

    double largestErrorFraction() const { return diagonal > 0 ? largestError / diagonal : 0.0; }
};

// The statistics a collapse session counts up: what sessions on pieces of one model add
// together (the others are sizes, largest values, lists).
inline constexpr int SimplifyStats::*kSessionCounts[] = {
    &SimplifyStats::featureEdges,        &SimplifyStats::boundaryEdges,   &SimplifyStats::nonManifoldEdges,
    &SimplifyStats::degenerateFaces,     &SimplifyStats::collapses,       &SimplifyStats::rejectedFlip,
    &SimplifyStats::rejectedCompactness, &SimplifyStats::rejectedFeature, &SimplifyStats::rejectedError,
    &SimplifyStats::rejectedTopology,    &SimplifyStats::featureBreaks,   &SimplifyStats::removedComponents,
    &SimplifyStats::closedTunnels,       &SimplifyStats::boundaryJoins,   &SimplifyStats::halvesCollapses};

// The face count the stop criteria translate to for an input of `faces` faces
// (0 when only maxError is set).
inline int targetFaceCount(const SimplifyParams& p, int faces)
{
    if (p.reductionPerc > 0.0)
        return int(faces * (1.0 - p.reductionPerc / 100.0) + 0.5);
    return std::max(p.targetFaces, 0);
}

}  // namespace cadlod
