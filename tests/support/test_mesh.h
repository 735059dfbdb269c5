// A vcglib mesh type for tests and tools, independent of MeshLab's CMeshO, with the
// attributes cadlod's files carry (normals, colors, quality), plus PLY read/write.
#pragma once

#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/io_mask.h>

#include <string>

namespace cadlod::test {

struct TVertex;
struct TFace;
struct TUsedTypes : vcg::UsedTypes<vcg::Use<TVertex>::AsVertexType, vcg::Use<TFace>::AsFaceType> {};
struct TVertex : vcg::Vertex<TUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f,
                             vcg::vertex::Color4b, vcg::vertex::Qualityf, vcg::vertex::BitFlags,
                             vcg::vertex::VFAdj, vcg::vertex::Mark> {};
struct TFace : vcg::Face<TUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::Color4b,
                         vcg::face::Qualityf, vcg::face::BitFlags, vcg::face::VFAdj,
                         vcg::face::FFAdj, vcg::face::Mark> {};
// vcglib 2020.09's ~TriMesh leaves named attributes allocated (ClearAttributes is
// commented out there), so a test mesh frees its own; copying them would free them twice.
struct TestMesh : vcg::tri::TriMesh<std::vector<TVertex>, std::vector<TFace>> {
    TestMesh() = default;
    TestMesh& operator=(const TestMesh&) = delete;
    ~TestMesh() { ClearAttributes(); }
};

// Loads a PLY; returns false (and says why in `error`) when the file is missing or bad.
bool loadPly(const std::string& path, TestMesh& m, int& mask, std::string& error);
bool loadPly(const std::string& path, TestMesh& m);
// Saves with the given vcg::tri::io::Mask bits (e.g. IOM_FACEQUALITY), binary PLY.
bool savePly(const std::string& path, TestMesh& m, int mask = 0);

}  // namespace cadlod::test
