// A copy of a mesh that keeps cadlod's part attributes (layer_metadata.h), which vcglib's
// Append leaves behind: how a LOD level starts from another mesh.
#pragma once

#include "mesh/layer_metadata.h"

#include <vcg/complex/append.h>

namespace cadlod::detail {

// Copies `from` into `to`, keeping cadlod's part attributes.
template <class MeshType>
void copyWithParts(MeshType& to, MeshType& from)
{
    to.Clear();
    if (hasParts(from)) {
        facePartHandle(to);
        partTableHandle(to)() = partTableHandle(from)();
    }
    vcg::tri::Append<MeshType, MeshType>::MeshCopy(to, from, false, false);
}

}  // namespace cadlod::detail
