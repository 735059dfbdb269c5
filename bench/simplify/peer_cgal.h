// CGAL's Surface_mesh_simplification with the Garland–Heckbert plane policies on a copy
// of a vcglib mesh (converted in and out, conversion not timed by the caller).
#pragma once

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include <vcg/complex/complex.h>

#include <vector>

namespace cadlod::bench {

using CgalKernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<CgalKernel::Point_3>;

template <class MeshType>
CgalMesh toCgal(const MeshType& m)
{
    CgalMesh sm;
    std::vector<CgalMesh::Vertex_index> v;
    v.reserve(m.vert.size());
    for (const auto& p : m.vert)
        v.push_back(sm.add_vertex(CgalKernel::Point_3(p.cP()[0], p.cP()[1], p.cP()[2])));
    for (const auto& f : m.face)
        if (!f.IsD())
            sm.add_face(v[f.cV(0) - &m.vert[0]], v[f.cV(1) - &m.vert[0]], v[f.cV(2) - &m.vert[0]]);
    return sm;
}

// Timed part: the collapse alone. Edges of a closed mesh = 3/2 faces.
inline void cgalSimplify(CgalMesh& sm, int targetFaces)
{
    namespace SMS = CGAL::Surface_mesh_simplification;
    SMS::Count_stop_predicate<CgalMesh> stop(std::size_t(targetFaces) * 3 / 2);
    SMS::GarlandHeckbert_plane_policies<CgalMesh, CgalKernel> gh(sm);
    SMS::edge_collapse(sm, stop, CGAL::parameters::get_cost(gh.get_cost()).get_placement(gh.get_placement()));
}

template <class MeshType>
void fromCgal(const CgalMesh& sm, MeshType& m)
{
    m.Clear();
    std::vector<int> index(sm.number_of_vertices() + sm.number_of_removed_vertices(), -1);
    auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, sm.number_of_vertices());
    int next = 0;
    for (auto v : sm.vertices()) {
        const auto& p = sm.point(v);
        vi->P() = typename MeshType::CoordType(p.x(), p.y(), p.z());
        ++vi;
        index[v.idx()] = next++;
    }
    auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, sm.number_of_faces());
    for (auto f : sm.faces()) {
        int j = 0;
        for (auto v : sm.vertices_around_face(sm.halfedge(f)))
            if (j < 3)
                fi->V(j++) = &m.vert[index[v.idx()]];
        ++fi;
    }
}

}  // namespace cadlod::bench
