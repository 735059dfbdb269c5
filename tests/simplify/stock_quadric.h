// vcglib's stock TriEdgeCollapseQuadric, set up the way MeshLab 2020.09's "Quadric Edge
// Collapse Decimation" filter sets it up (filter_meshing/quadric_simp.cpp: quadrics in a
// temporary per-vertex attribute, same parameter defaults), for any vcglib mesh type:
// the reference the CAD collapse is compared against in tests and benchmarks.
#pragma once

#include <vcg/complex/algorithms/local_optimization.h>
#include <vcg/complex/algorithms/local_optimization/tri_edge_collapse_quadric.h>
#include <vcg/complex/algorithms/update/topology.h>
#include <vcg/container/simple_temporary_data.h>

namespace cadlod::test {

template <class MeshType>
struct StockQuadricHelper {
    using VertexType = typename MeshType::VertexType;
    using Temp = vcg::SimpleTempData<typename MeshType::VertContainer, vcg::math::Quadric<double>>;
    static void Init() {}
    static vcg::math::Quadric<double>& Qd(VertexType& v) { return (*temp())[v]; }
    static vcg::math::Quadric<double>& Qd(VertexType* v) { return (*temp())[*v]; }
    static typename VertexType::ScalarType W(VertexType*) { return 1.0; }
    static typename VertexType::ScalarType W(VertexType&) { return 1.0; }
    static void Merge(VertexType&, const VertexType&) {}
    static Temp*& temp()
    {
        static Temp* t = nullptr;
        return t;
    }
};

template <class MeshType>
class StockCollapse
    : public vcg::tri::TriEdgeCollapseQuadric<MeshType, vcg::tri::BasicVertexPair<typename MeshType::VertexType>,
                                              StockCollapse<MeshType>, StockQuadricHelper<MeshType>>
{
public:
    using VertexPair = vcg::tri::BasicVertexPair<typename MeshType::VertexType>;
    using Base = vcg::tri::TriEdgeCollapseQuadric<MeshType, VertexPair, StockCollapse<MeshType>,
                                                  StockQuadricHelper<MeshType>>;
    StockCollapse(const VertexPair& p, int mark, vcg::BaseParameterClass* pp) : Base(p, mark, pp) {}
};

// MeshLab's defaults: QualityThr 0.3, optimal placement, no boundary/normal/topology
// preservation, no planar quadrics. `tweak` may change them (e.g. the CAD-friendly options).
template <class MeshType>
vcg::tri::TriEdgeCollapseQuadricParameter stockDefaults()
{
    return vcg::tri::TriEdgeCollapseQuadricParameter();
}

template <class MeshType>
void stockSimplify(MeshType& m, int targetFaces, vcg::tri::TriEdgeCollapseQuadricParameter pp)
{
    using Helper = StockQuadricHelper<MeshType>;
    vcg::math::Quadric<double> zero;
    zero.SetZero();
    typename Helper::Temp temp(m.vert, zero);
    Helper::temp() = &temp;
    vcg::tri::UpdateTopology<MeshType>::VertexFace(m);
    vcg::tri::UpdateFlags<MeshType>::FaceBorderFromVF(m);
    if (pp.PreserveBoundary) {  // as quadric_simp.cpp does without a selection
        pp.FastPreserveBoundary = true;
        pp.PreserveBoundary = false;
    }
    if (pp.NormalCheck)
        pp.NormalThrRad = M_PI / 4.0;
    vcg::LocalOptimization<MeshType> session(m, &pp);
    session.template Init<StockCollapse<MeshType>>();
    session.SetTargetSimplices(targetFaces);
    session.SetTimeBudget(0.5f);
    while (session.DoOptimization() && m.fn > targetFaces) {
    }
    session.template Finalize<StockCollapse<MeshType>>();
    Helper::temp() = nullptr;
}

}  // namespace cadlod::test
