// What cadlod's plugins tell each other through a MeshLab layer, stored as vcglib
// attributes (so it needs no MeshLab header and works on any vcglib mesh):
//  - parts: the VRML importer tags every face with a part id (per-face int attribute
//    "cadlod_part") and stores the part table (per-mesh attribute "cadlod_parts");
//    the simplifier can keep part borders (keepPartBorders), the OpenFlight exporter writes
//    one Object per part.
//  - source: the VRML importer records the file and how it read it (VrmlSource), so that
//    the LOD-set filter can read it again with its shared parts kept as placements.
//  - LOD levels: the LOD-set filter stores a LodLevel (per-mesh attribute "cadlod_lod")
//    on every layer of a set, level 0 being the original; the OpenFlight exporter
//    gathers the layers of one set from the document and writes them as one LOD model.
#pragma once

#include "mesh/lod_level.h"
#include "mesh/part_identity.h"

#include <vcg/complex/complex.h>

#include <string>
#include <vector>

namespace cadlod {

// Indexed by the per-face part id.
using PartTable = std::vector<PartIdentity>;

inline constexpr const char* kPartAttribute = "cadlod_part";
inline constexpr const char* kPartTableAttribute = "cadlod_parts";
inline constexpr const char* kLodAttribute = "cadlod_lod";

// Returns the handle, creating the attribute when the mesh lacks it.
template <class MeshType>
typename MeshType::template PerFaceAttributeHandle<int> facePartHandle(MeshType& m)
{
    return vcg::tri::Allocator<MeshType>::template GetPerFaceAttribute<int>(m, kPartAttribute);
}

template <class MeshType>
typename MeshType::template PerMeshAttributeHandle<PartTable> partTableHandle(MeshType& m)
{
    return vcg::tri::Allocator<MeshType>::template GetPerMeshAttribute<PartTable>(m, kPartTableAttribute);
}

template <class MeshType>
bool hasParts(const MeshType& m)
{
    return vcg::tri::HasPerFaceAttribute(m, kPartAttribute) &&
           vcg::tri::HasPerMeshAttribute(m, kPartTableAttribute);
}

template <class MeshType>
bool hasLodLevel(const MeshType& m)
{
    return vcg::tri::HasPerMeshAttribute(m, kLodAttribute);
}

template <class MeshType>
typename MeshType::template PerMeshAttributeHandle<LodLevel> lodLevelHandle(MeshType& m)
{
    return vcg::tri::Allocator<MeshType>::template GetPerMeshAttribute<LodLevel>(m, kLodAttribute);
}

// How many metres one model unit is, as the importer knew it (VRML's unit is the metre,
// an OpenFlight header names its own); 0 when unknown.
inline constexpr const char* kMetresPerUnitAttribute = "cadlod_metres_per_unit";

template <class MeshType>
void setMetresPerUnit(MeshType& m, double metres)
{
    vcg::tri::Allocator<MeshType>::template GetPerMeshAttribute<double>(m, kMetresPerUnitAttribute)() = metres;
}

template <class MeshType>
double metresPerUnit(MeshType& m)
{
    if (!vcg::tri::HasPerMeshAttribute(m, kMetresPerUnitAttribute))
        return 0.0;
    return vcg::tri::Allocator<MeshType>::template GetPerMeshAttribute<double>(m, kMetresPerUnitAttribute)();
}

// The VRML file a layer was read from, and the import options it was read with.
struct VrmlSource {
    std::string path;
    double unitScale = 1.0;
    bool detectKicadUnits = true;
    bool yUpToZUp = false;
    bool recomputeNormals = false;
    bool mergeVertices = true;
    float mergeTolerance = 0.0f;
};

inline constexpr const char* kVrmlSourceAttribute = "cadlod_vrml_source";

template <class MeshType>
void setVrmlSource(MeshType& m, const VrmlSource& source)
{
    vcg::tri::Allocator<MeshType>::template GetPerMeshAttribute<VrmlSource>(m, kVrmlSourceAttribute)() = source;
}

// False when the layer was not read from a VRML file.
template <class MeshType>
bool vrmlSource(MeshType& m, VrmlSource& source)
{
    if (!vcg::tri::HasPerMeshAttribute(m, kVrmlSourceAttribute))
        return false;
    source = vcg::tri::Allocator<MeshType>::template GetPerMeshAttribute<VrmlSource>(m, kVrmlSourceAttribute)();
    return true;
}

// Takes the mesh out of its LOD set: a level whose geometry changed (simplified again, ...)
// no longer matches its record (faces, error, switch ranges).
template <class MeshType>
void clearLodLevel(MeshType& m)
{
    if (hasLodLevel(m))
        vcg::tri::Allocator<MeshType>::DeletePerMeshAttribute(m, kLodAttribute);
}

}  // namespace cadlod
