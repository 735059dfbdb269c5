#include "filter_cadlod.h"

#include "core/compactness.h"

#include <vcg/complex/algorithms/stat.h>

FilterCadLodPlugin::FilterCadLodPlugin()
{
    typeList << FP_COMPACTNESS;
    for (FilterIDType t : types())
        actionList << new QAction(filterName(t), this);
}

QString FilterCadLodPlugin::pluginName() const { return "FilterCadLod"; }

QString FilterCadLodPlugin::filterName(FilterIDType filter) const
{
    switch (filter) {
    case FP_COMPACTNESS: return "Compute Triangle Compactness";
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
               "Use the quality mapper or the face quality histogram to see where slivers are. "
               "The log reports mean, min, 5th percentile and the share of faces below 0.1 and 0.3.";
    }
    return {};
}

MeshFilterInterface::FilterClass FilterCadLodPlugin::getClass(QAction* action)
{
    switch (ID(action)) {
    case FP_COMPACTNESS: return FilterClass(Quality | Measure);
    }
    return Measure;
}

MeshFilterInterface::FILTER_ARITY FilterCadLodPlugin::filterArity(QAction*) const
{
    return SINGLE_MESH;
}

int FilterCadLodPlugin::getRequirements(QAction* action)
{
    switch (ID(action)) {
    case FP_COMPACTNESS: return MeshModel::MM_FACEQUALITY;
    }
    return MeshModel::MM_NONE;
}

int FilterCadLodPlugin::getPreConditions(QAction* action) const
{
    switch (ID(action)) {
    case FP_COMPACTNESS: return MeshModel::MM_FACENUMBER;
    }
    return MeshModel::MM_NONE;
}

int FilterCadLodPlugin::postCondition(QAction* action) const
{
    switch (ID(action)) {
    case FP_COMPACTNESS: return MeshModel::MM_FACEQUALITY;
    }
    return MeshModel::MM_ALL;
}

void FilterCadLodPlugin::initParameterSet(QAction*, MeshModel&, RichParameterList&) {}

bool FilterCadLodPlugin::applyFilter(QAction* action, MeshDocument& md, const RichParameterList&,
                                     vcg::CallBackPos* cb)
{
    switch (ID(action)) {
    case FP_COMPACTNESS: return computeCompactness(*md.mm(), cb);
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
    return true;
}

MESHLAB_PLUGIN_NAME_EXPORTER(FilterCadLodPlugin)
