// An operation of the collapse heap other than an edge collapse (removing a component whole,
// cutting a tunnel): vcglib's LocalModification with a priority fixed when it is offered.
#pragma once

#include "simplify/cad_edge_collapse.h"

#include <vcg/complex/algorithms/local_optimization.h>

namespace cadlod {

template <class MeshType>
class PricedOperation : public vcg::LocalModification<MeshType>
{
public:
    using VertexType = typename MeshType::VertexType;
    using FaceType = typename MeshType::FaceType;
    using ScalarType = typename MeshType::ScalarType;
    using HeapType = typename vcg::LocalOptimization<MeshType>::HeapType;
    using HeapElem = typename vcg::LocalOptimization<MeshType>::HeapElem;
    using Context = CollapseContext<MeshType>;

    // vcglib asks the type only to tell collapses from other kinds of operations it has.
    vcg::ModifierType IsOfType() override { return vcg::TriEdgeCollapseOp; }
    ScalarType ComputePriority(vcg::BaseParameterClass*) override { return priority_; }
    ScalarType Priority() const override { return priority_; }

protected:
    explicit PricedOperation(ScalarType priority) : priority_(priority) {}

    static Context& contextOf(vcg::BaseParameterClass* pp) { return *static_cast<Context*>(pp); }

private:
    ScalarType priority_;
};

}  // namespace cadlod
