// Connected components (core/components.h): faces that share a vertex are one component,
// every live face is in exactly one, and the smallest come first. Fans are the case to
// watch: a cylinder's cap exported as thousands of faces around one hub vertex.
#include "test_mesh.h"

#include "mesh/components.h"

#include <vcg/complex/algorithms/update/topology.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using namespace cadlod;
using namespace cadlod::test;

namespace {

// A closed fan of `spokes` faces around a hub at `center` (radius `radius`, in the xy
// plane); `hub`: an existing vertex to use as the hub, or null for a new one.
TVertex* addFan(TestMesh& m, const vcg::Point3f& center, float radius, int spokes, TVertex* hub = nullptr)
{
    const std::size_t hubIndex = hub ? std::size_t(hub - &m.vert[0]) : m.vert.size();
    if (!hub)
        vcg::tri::Allocator<TestMesh>::AddVertex(m, center);
    const std::size_t first = m.vert.size();
    auto vi = vcg::tri::Allocator<TestMesh>::AddVertices(m, std::size_t(spokes));
    for (int i = 0; i < spokes; ++i, ++vi) {
        const double a = 2 * M_PI * i / spokes;
        vi->P() = center + vcg::Point3f(float(radius * std::cos(a)), float(radius * std::sin(a)), 0.f);
    }
    for (int i = 0; i < spokes; ++i)
        vcg::tri::Allocator<TestMesh>::AddFace(m, &m.vert[hubIndex], &m.vert[first + std::size_t(i)],
                                               &m.vert[first + std::size_t((i + 1) % spokes)]);
    return &m.vert[hubIndex];
}

// The faces of `components`, each counted once; false if a face is in two of them.
bool eachFaceOnce(const std::vector<Component<TestMesh>>& components, std::set<const TFace*>& faces)
{
    for (const auto& c : components)
        for (const TFace* f : c.faces)
            if (!faces.insert(f).second)
                return false;
    return true;
}

}  // namespace

// Two fans of 3 000 faces and a lone triangle: three components, smallest first, every face
// in one. A fan's faces are all found through its hub.
TEST(Components, LargeFansAreOneComponentEach)
{
    TestMesh m;
    m.vert.reserve(7000);
    addFan(m, vcg::Point3f(0, 0, 0), 1.f, 3000);
    addFan(m, vcg::Point3f(10, 0, 0), 2.f, 3000);
    auto vi = vcg::tri::Allocator<TestMesh>::AddVertices(m, 3);
    vi[0].P() = vcg::Point3f(0, 20, 0);
    vi[1].P() = vcg::Point3f(0.1f, 20, 0);
    vi[2].P() = vcg::Point3f(0, 20.1f, 0);
    vcg::tri::Allocator<TestMesh>::AddFace(m, &vi[0], &vi[1], &vi[2]);
    vcg::tri::UpdateTopology<TestMesh>::VertexFace(m);

    const auto components = connectedComponents(m);
    ASSERT_EQ(components.size(), 3u);
    EXPECT_EQ(components[0].faces.size(), 1u);
    EXPECT_EQ(components[1].faces.size(), 3000u);
    EXPECT_EQ(components[2].faces.size(), 3000u);
    EXPECT_NEAR(components[2].size(), std::sqrt(32.0), 1e-3) << "the larger fan's box: 4 x 4 x 0";
    std::set<const TFace*> faces;
    EXPECT_TRUE(eachFaceOnce(components, faces));
    EXPECT_EQ(faces.size(), std::size_t(m.fn));
}

// Two fans that share only their hub (a bow tie of two caps) are one component; once the
// faces of one are deleted, the other is alone.
TEST(Components, FansSharingTheirHubAreOneComponent)
{
    TestMesh m;
    m.vert.reserve(5000);
    TVertex* hub = addFan(m, vcg::Point3f(0, 0, 0), 1.f, 2000);
    addFan(m, vcg::Point3f(0, 0, 0), 2.f, 2000, hub);
    for (auto& v : m.vert)
        if (&v != hub && v.P()[2] == 0.f && v.P().Norm() > 1.5f)
            v.P()[2] = 1.f;  // the second fan is a cone, not in the first one's plane
    vcg::tri::UpdateTopology<TestMesh>::VertexFace(m);
    auto components = connectedComponents(m);
    ASSERT_EQ(components.size(), 1u);
    EXPECT_EQ(components[0].faces.size(), 4000u);

    for (std::size_t i = 0; i < 2000; ++i)
        vcg::tri::Allocator<TestMesh>::DeleteFace(m, m.face[i]);
    vcg::tri::UpdateTopology<TestMesh>::VertexFace(m);
    components = connectedComponents(m);
    ASSERT_EQ(components.size(), 1u);
    EXPECT_EQ(components[0].faces.size(), 2000u);
    for (const TFace* f : components[0].faces)
        EXPECT_GE(f - &m.face[0], 2000) << "only the cone's faces are left";
}
