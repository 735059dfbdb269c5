// "Generate CAD LOD Set" with Hierarchy "per part and cluster": the MeshLab side of the
// assembly/ core, as `cadlod convert --hlod auto` runs it. A MeshLab layer is one mesh and
// cannot hold instances, so the layer's VRML file is read again with its shared parts kept
// as placements (the import options recorded on the layer, mesh/layer_metadata.h), every
// distinct part goes through the LOD chain once, the placements go into clusters with
// merged proxies, and the OpenFlight model is written straight to the file chosen. The
// document is left as it was.
#pragma once

#include "assembly/hierarchical_lod.h"  // ClusterMode
#include "lod/lod_chain.h"

#include <common/interfaces.h>

namespace cadlod {

// The file the hierarchy goes to when none is chosen: beside the layer's own, "_hlod.flt"
// (a meshlabserver script cannot know the input's name).
QString defaultHierarchyFile(const MeshModel& layer);

// Writes the hierarchical LOD of `layer`'s assembly to `output` (empty: the default file),
// the chain planned by `chain`, the placements clustered as `mode` says (assembly/
// hierarchical_lod.h; Auto as `--hlod auto`). False with `error` (the file and what went wrong) when the
// layer was not read from VRML, the output is not a .flt file, or the conversion fails;
// nothing is written then.
bool writeHierarchicalLod(MeshFilterInterface& plugin, MeshModel& layer, const LodChainOptions& chain,
                          ClusterMode mode, const QString& chosen, vcg::CallBackPos* cb, QString& error);

}  // namespace cadlod
