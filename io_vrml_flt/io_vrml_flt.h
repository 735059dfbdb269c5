// io_vrml_flt: MeshLab IO adapter. VRML import (vrml/ core -> vrml_import.cpp) and
// OpenFlight import/export (openflight/ core -> flt_import.cpp, flt_export.cpp).
// This class only dispatches by format; each format's translation lives in its own file.
#pragma once

#include <common/interfaces.h>

class IoVrmlFltPlugin : public QObject, public MeshIOInterface
{
    Q_OBJECT
    MESHLAB_PLUGIN_IID_EXPORTER(MESH_IO_INTERFACE_IID)
    Q_INTERFACES(MeshIOInterface)

public:
    QString pluginName() const override;
    QList<Format> importFormats() const override;
    QList<Format> exportFormats() const override;
    void GetExportMaskCapability(QString& format, int& capability, int& defaultBits) const override;
    void initPreOpenParameter(const QString& format, const QString& fileName,
                              RichParameterList& par) override;
    void initSaveParameter(const QString& format, MeshModel& m, RichParameterList& par) override;
    bool open(const QString& format, const QString& fileName, MeshModel& m, int& mask,
              const RichParameterList& par, vcg::CallBackPos* cb, QWidget* parent) override;
    bool save(const QString& format, const QString& fileName, MeshModel& m, const int mask,
              const RichParameterList& par, vcg::CallBackPos* cb, QWidget* parent) override;
};
