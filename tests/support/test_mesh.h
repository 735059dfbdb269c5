// The tests' vcglib mesh: cadlod::CoreMesh (lib/mesh/core_mesh.h), plus PLY
// read/write.
#pragma once

#include "mesh/core_mesh.h"

#include <vcg/complex/complex.h>
#include <wrap/io_trimesh/io_mask.h>

#include <array>
#include <initializer_list>
#include <string>

namespace cadlod::test {

using TVertex = CoreVertex;
using TFace = CoreFace;
using TestMesh = CoreMesh;

// Loads a PLY; returns false (and says why in `error`) when the file is missing or bad.
bool loadPly(const std::string& path, TestMesh& m, int& mask, std::string& error);
bool loadPly(const std::string& path, TestMesh& m);
// Saves with the given vcg::tri::io::Mask bits (e.g. IOM_FACEQUALITY), binary PLY.
bool savePly(const std::string& path, TestMesh& m, int mask = 0);

// Adds these vertices and the faces on them (indices into `points`) to `m`.
inline void addFaces(TestMesh& m, std::initializer_list<vcg::Point3f> points,
                     std::initializer_list<std::array<int, 3>> faces)
{
    const std::size_t first = m.vert.size();
    vcg::tri::Allocator<TestMesh>::AddVertices(m, points.size());
    std::size_t i = first;
    for (const vcg::Point3f& p : points)
        m.vert[i++].P() = p;
    for (const std::array<int, 3>& f : faces)
        vcg::tri::Allocator<TestMesh>::AddFace(m, &m.vert[first + std::size_t(f[0])], &m.vert[first + std::size_t(f[1])],
                                               &m.vert[first + std::size_t(f[2])]);
}

}  // namespace cadlod::test
