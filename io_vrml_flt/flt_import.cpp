// Temporary: replaced by the OpenFlight reader adapter (issue 6).
#include "format_adapters.h"

namespace cadlod {
void fltOpenParameters(RichParameterList&) {}
bool openOpenFlight(MeshIOInterface&, const QString& fileName, MeshModel&, int&,
                    const RichParameterList&, vcg::CallBackPos*, QString& error)
{
    error = fileName + ": OpenFlight import is not available in this build yet";
    return false;
}
}  // namespace cadlod
