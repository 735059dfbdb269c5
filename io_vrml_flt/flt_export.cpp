// Temporary: replaced by the OpenFlight writer adapter (issue 6).
#include "format_adapters.h"

namespace cadlod {
void fltSaveParameters(MeshModel&, RichParameterList&) {}
int fltExportCapability() { return 0; }
bool saveOpenFlight(MeshIOInterface&, const QString& fileName, MeshModel&, int,
                    const RichParameterList&, vcg::CallBackPos*, QString& error)
{
    error = fileName + ": OpenFlight export is not available in this build yet";
    return false;
}
}  // namespace cadlod
