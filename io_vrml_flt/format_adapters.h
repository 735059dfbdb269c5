// The per-format halves of the io_vrml_flt plugin. Each function translates between a
// MeshLab layer and one of cadlod's MeshLab-independent cores, logs through `plugin`
// (MeshLabInterface::Log) and, on failure, returns false with `error` set. None of them
// may open a dialog: meshlabserver would block for ever.
#pragma once

#include <common/interfaces.h>

namespace cadlod {

// VRML97 / VRML 1.0, plain or gzip (vrml_import.cpp).
void vrmlOpenParameters(RichParameterList& par);
bool openVrml(MeshIOInterface& plugin, const QString& fileName, MeshModel& m, int& mask,
              const RichParameterList& par, vcg::CallBackPos* cb, QString& error);

// OpenFlight (flt_import.cpp, flt_export.cpp).
void fltOpenParameters(RichParameterList& par);
bool openOpenFlight(MeshIOInterface& plugin, const QString& fileName, MeshModel& m, int& mask,
                    const RichParameterList& par, vcg::CallBackPos* cb, QString& error);
void fltSaveParameters(MeshModel& m, RichParameterList& par);
int fltExportCapability();
bool saveOpenFlight(MeshIOInterface& plugin, const QString& fileName, MeshModel& m, int mask,
                    const RichParameterList& par, vcg::CallBackPos* cb, QString& error);

}  // namespace cadlod
