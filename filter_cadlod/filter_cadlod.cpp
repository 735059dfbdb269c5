#include "filter_cadlod.h"

#include "compactness_colors.h"
#include "measure/compactness.h"
#include "lod_set_filter.h"
#include "report_filter.h"
#include "simplify_filter.h"

#include "support/progress_lines.h"

#include <vcg/complex/algorithms/stat.h>

FilterCadLodPlugin::FilterCadLodPlugin()
{
    typeList << FP_COMPACTNESS << FP_CAD_SIMPLIFY << FP_LOD_SET << FP_REPORT;
    for (FilterIDType t : types())
        actionList << new QAction(filterName(t), this);
}

QString FilterCadLodPlugin::pluginName() const { return "FilterCadLod"; }

QString FilterCadLodPlugin::filterName(FilterIDType filter) const
{
    switch (filter) {
    case FP_COMPACTNESS: return "Compute Triangle Compactness";
    case FP_LOD_SET: return "Generate CAD LOD Set";
    case FP_CAD_SIMPLIFY: return "Simplification: CAD Quadric Edge Collapse (compactness)";
    case FP_REPORT: return "Simplification Report";
    }
    return {};
}

QString FilterCadLodPlugin::filterInfo(FilterIDType filter) const
{
    switch (filter) {
    case FP_COMPACTNESS:
        return "Stores the compactness of every triangle as face quality: "
               "c = 4&radic;3&middot;A / (l0&sup2;+l1&sup2;+l2&sup2;), 1 for an equilateral "
               "triangle, towards 0 for slivers, 0 for zero-area faces (Gu&eacute;ziec). "
               "Faces are painted by compactness on a fixed scale: red 0, yellow 0.5, green 1 "
               "(this replaces the layer's face colours). "
               "The quality mapper or the face quality histogram show the same values. "
               "The log reports mean, min, 5th percentile and the share of faces below 0.1 and 0.3.";
    case FP_CAD_SIMPLIFY:
        return "Quadric edge collapse for CAD meshes (Tang et al. 2015): of placements of nearly equal "
               "cost, the most compact triangles win; features give way last. The log says what stopped it.";
    case FP_REPORT:
        return "Compares the current layer with the one it was simplified from: face and vertex "
               "counts, the symmetric Hausdorff distance (max, mean, RMS; absolute and in % of the "
               "bounding-box diagonal; vertices plus area-uniform samples, as MeshLab's Hausdorff "
               "Distance filter samples) and triangle compactness before and after, with a "
               "histogram. It can store each vertex's distance as vertex quality and each "
               "triangle's compactness as face quality and paint the faces by it (red 0, yellow "
               "0.5, green 1; this replaces the layer's face colours), so the slivers show at once "
               "and the quality color mapper shows where the error is.";
    case FP_LOD_SET:
        return "One new layer per level of detail, each drawn only where its measured error is below "
               "the pixel error on screen: by screen-space error down to a box per part, or the "
               "paper's list. Saving a level as .flt writes the whole set (see the log).";
    }
    return {};
}

MeshFilterInterface::FilterClass FilterCadLodPlugin::getClass(QAction* action)
{
    switch (ID(action)) {
    case FP_COMPACTNESS: return FilterClass(Quality | Measure | FaceColoring);
    case FP_LOD_SET: return Remeshing;
    case FP_REPORT: return FilterClass(Quality | Measure | FaceColoring);
    case FP_CAD_SIMPLIFY: return Remeshing;
    }
    return Measure;
}

MeshFilterInterface::FILTER_ARITY FilterCadLodPlugin::filterArity(QAction* action) const
{
    return ID(action) == FP_REPORT ? FIXED : SINGLE_MESH;
}

int FilterCadLodPlugin::getRequirements(QAction* action)
{
    switch (ID(action)) {
    case FP_COMPACTNESS: return MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR;
    case FP_LOD_SET: return MeshModel::MM_VERTFACETOPO | MeshModel::MM_VERTMARK;
    case FP_CAD_SIMPLIFY: return MeshModel::MM_VERTFACETOPO | MeshModel::MM_VERTMARK;
    }
    return MeshModel::MM_NONE;
}

int FilterCadLodPlugin::getPreConditions(QAction* action) const
{
    switch (ID(action)) {
    case FP_COMPACTNESS: return MeshModel::MM_FACENUMBER;
    case FP_LOD_SET: return MeshModel::MM_FACENUMBER;
    case FP_REPORT: return MeshModel::MM_FACENUMBER;
    case FP_CAD_SIMPLIFY: return MeshModel::MM_FACENUMBER;
    }
    return MeshModel::MM_NONE;
}

int FilterCadLodPlugin::postCondition(QAction* action) const
{
    switch (ID(action)) {
    case FP_COMPACTNESS: return MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR;
    case FP_LOD_SET: return MeshModel::MM_NONE;  // the original is not changed; levels are new layers
    case FP_REPORT: return MeshModel::MM_VERTQUALITY | MeshModel::MM_FACEQUALITY | MeshModel::MM_FACECOLOR;
    case FP_CAD_SIMPLIFY: return MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE;
    }
    return MeshModel::MM_ALL;
}

void FilterCadLodPlugin::initParameterSet(QAction* action, MeshModel& m, RichParameterList& parlst)
{
    switch (ID(action)) {
    case FP_LOD_SET: cadlod::lodSetParameters(m, parlst); break;
    case FP_CAD_SIMPLIFY: cadlod::cadSimplifyParameters(m, parlst); break;
    }
}

void FilterCadLodPlugin::initParameterSet(QAction* action, MeshDocument& md, RichParameterList& parlst)
{
    if (ID(action) == FP_REPORT)
        cadlod::reportParameters(md, parlst);
    else if (md.mm())
        initParameterSet(action, *md.mm(), parlst);
}

// meshlabserver prints only "Problem with filter" when a filter fails: the reason goes to
// the log as well, so headless users see it. Every filter reports progress through one
// ProgressLines, so that meshlabserver prints its messages one per line.
bool FilterCadLodPlugin::applyFilter(QAction* action, MeshDocument& md, const RichParameterList& par,
                                     vcg::CallBackPos* cb)
{
    errorMessage.clear();
    cadlod::ProgressLines progress(cb);
    const bool ok = apply(ID(action), md, par, progress.callback());
    if (!ok)
        Log(GLLogStream::WARNING, "%s failed: %s", qUtf8Printable(filterName(ID(action))),
            qUtf8Printable(errorMessage));
    return ok;
}

bool FilterCadLodPlugin::apply(FilterIDType filter, MeshDocument& md, const RichParameterList& par,
                               vcg::CallBackPos* cb)
{
    switch (filter) {
    case FP_COMPACTNESS: return computeCompactness(*md.mm(), cb);
    case FP_LOD_SET: return cadlod::generateLodSet(*this, md, par, cb, errorMessage);
    case FP_CAD_SIMPLIFY: return cadlod::cadSimplify(*this, *md.mm(), par, cb, errorMessage);
    case FP_REPORT: return cadlod::simplificationReport(*this, md, par, errorMessage);
    }
    errorMessage = "Unknown filter";
    return false;
}

bool FilterCadLodPlugin::computeCompactness(MeshModel& m, vcg::CallBackPos* cb)
{
    m.updateDataMask(MeshModel::MM_FACEQUALITY);
    std::vector<double> values;
    values.reserve(m.cm.fn);
    std::size_t done = 0;
    for (CFaceO& f : m.cm.face) {
        if (f.IsD())
            continue;
        const double c = cadlod::compactness(f.cP(0), f.cP(1), f.cP(2));
        f.Q() = CFaceO::QualityType(c);
        values.push_back(c);
        if (cb && (++done & 0xFFFF) == 0)
            cb(int(100.0 * done / std::max(1, m.cm.fn)), "Computing triangle compactness");
    }
    const cadlod::CompactnessStats s = cadlod::summarizeCompactness(values);
    Log("Triangle compactness of %s (%zu faces): mean %.4f, min %.4f, p5 %.4f, "
        "below 0.1: %.2f%%, below 0.3: %.2f%%",
        qUtf8Printable(m.label()), s.faces, s.mean, s.min, s.p5,
        100.0 * s.shareBelow01, 100.0 * s.shareBelow03);
    m.updateDataMask(MeshModel::MM_FACECOLOR);
    cadlod::paintFacesByCompactness(m.cm);
    Log(cadlod::kCompactnessPaintNote, qUtf8Printable(m.label()));
    return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterCadLodPlugin)
