// Temporary: replaced by the VRML adapter (issue 5).
#include "format_adapters.h"

namespace cadlod {
void vrmlOpenParameters(RichParameterList&) {}
bool openVrml(MeshIOInterface&, const QString& fileName, MeshModel&, int&, const RichParameterList&,
              vcg::CallBackPos*, QString& error)
{
    error = fileName + ": VRML import is not available in this build yet";
    return false;
}
}  // namespace cadlod
