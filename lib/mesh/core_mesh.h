// One concrete vcglib mesh type with everything cadlod's cores use, for programs and tests
// that do not run inside MeshLab (MeshLab's CMeshO has the same components, optional):
// VF and FF adjacency and marks (the simplifier), per-vertex normal, colour, texture
// coordinate and quality, per-face normal, colour, quality and mark.
#pragma once

#include <vcg/complex/complex.h>

#include <vector>

namespace cadlod {

struct CoreVertex;
struct CoreFace;
struct CoreUsedTypes
    : vcg::UsedTypes<vcg::Use<CoreVertex>::AsVertexType, vcg::Use<CoreFace>::AsFaceType> {};
struct CoreVertex : vcg::Vertex<CoreUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f,
                                vcg::vertex::Color4b, vcg::vertex::TexCoord2f, vcg::vertex::Qualityf,
                                vcg::vertex::BitFlags, vcg::vertex::VFAdj, vcg::vertex::Mark> {};
struct CoreFace : vcg::Face<CoreUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::Color4b,
                            vcg::face::Qualityf, vcg::face::BitFlags, vcg::face::VFAdj, vcg::face::FFAdj,
                            vcg::face::Mark> {};

// vcglib 2020.09's ~TriMesh leaves named attributes allocated (ClearAttributes is
// commented out there), so this mesh frees its own; assigning one would free them twice.
struct CoreMesh : vcg::tri::TriMesh<std::vector<CoreVertex>, std::vector<CoreFace>> {
    CoreMesh() = default;
    CoreMesh& operator=(const CoreMesh&) = delete;
    ~CoreMesh() { ClearAttributes(); }
};

}  // namespace cadlod
