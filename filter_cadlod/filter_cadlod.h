// filter_cadlod: the MeshLab adapter for cadlod's mesh cores (compactness measure,
// CAD Quadric Edge Collapse, LOD sets, inspection). The algorithms live in core/;
// this class only translates parameters, logs and progress.
#pragma once

#include <common/interfaces.h>

class FilterCadLodPlugin : public QObject, public MeshFilterInterface
{
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_FILTER_INTERFACE_IID)
    Q_INTERFACES(MeshFilterInterface)

public:
    enum { FP_COMPACTNESS, FP_LOD_SET, FP_CAD_SIMPLIFY, FP_REPORT };

    FilterCadLodPlugin();

    QString pluginName() const override;
    QString filterName(FilterIDType filter) const override;
    QString filterInfo(FilterIDType filter) const override;
    FilterClass getClass(QAction* action) override;
    FILTER_ARITY filterArity(QAction* action) const override;
    int getRequirements(QAction* action) override;
    int getPreConditions(QAction* action) const override;
    int postCondition(QAction* action) const override;
    void initParameterSet(QAction* action, MeshModel& m, RichParameterList& parlst) override;
    void initParameterSet(QAction* action, MeshDocument& md, RichParameterList& parlst) override;
    bool applyFilter(QAction* action, MeshDocument& md, const RichParameterList& par,
                     vcg::CallBackPos* cb) override;

private:
    bool apply(FilterIDType filter, MeshDocument& md, const RichParameterList& par, vcg::CallBackPos* cb);
    bool computeCompactness(MeshModel& m, vcg::CallBackPos* cb);
};
