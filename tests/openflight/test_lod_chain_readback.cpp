// The screen-space LOD chain as a viewer's engine gets it: built on the demo assembly,
// written as OpenFlight, read back by OpenSceneGraph (an independent reader), and every
// level measured again against level 0 as OSG sees both: none may be drawn where its error
// projects to more than the pixel error (5 % sampling slack).
#include "osg_probe.h"
#include "test_mesh.h"

#include "measure/hausdorff.h"
#include "lod/lod_chain.h"
#include "openflight/flt_writer.h"
#include "convert/mesh_to_lod_model.h"
#include "convert/scene_to_mesh.h"
#include "vrml/importer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

using namespace cadlod;
using cadlod::test::TestMesh;

namespace {

void meshFromOsg(const std::vector<test::OsgTriangle>& triangles, TestMesh& m)
{
    auto vi = vcg::tri::Allocator<TestMesh>::AddVertices(m, 3 * triangles.size());
    auto fi = vcg::tri::Allocator<TestMesh>::AddFaces(m, triangles.size());
    for (const test::OsgTriangle& t : triangles) {
        for (int k = 0; k < 3; ++k, ++vi) {
            vi->P() = vcg::Point3f(t.position[k][0], t.position[k][1], t.position[k][2]);
            fi->V(k) = &*vi;
        }
        ++fi;
    }
}

}  // namespace

TEST(LodChainReadBack, NoLevelIsDrawnWhereItsErrorExceedsThePixelError)
{
    // The demo assembly, in millimetres.
    vrml::ImportResult imported =
        vrml::importVrmlFile(std::string(CADLOD_SOURCE_DIR) + "/docs/sample/cad_assembly.wrl.gz", {});
    ASSERT_TRUE(imported.ok()) << imported.error;
    TestMesh input, scratch;
    mesh_io::sceneToMesh(imported.scene, input, mesh_io::SceneToMeshOptions{});

    LodChainOptions options;
    std::vector<std::unique_ptr<TestMesh>> levels;
    const LodSetResult chain = buildLodChain<TestMesh>(input, scratch, options, [&](int) -> TestMesh& {
        levels.push_back(std::make_unique<TestMesh>());
        return *levels.back();
    });
    ASSERT_TRUE(chain.ok()) << chain.error;
    ASSERT_GE(chain.levels.size(), 5u);  // the demo target
    EXPECT_LE(chain.levels.back().faces, 0.02 * chain.levels.front().faces);

    std::vector<mesh_io::LodLayer<TestMesh>> layers{{&input, {}}};
    for (auto& m : levels)
        if (hasLodLevel(*m))
            layers.push_back({m.get(), {}});
    flt::LodModel model;
    mesh_io::LevelStats stats;
    std::string error;
    ASSERT_TRUE(mesh_io::lodSetToModel(layers, options.setId, model, stats, error)) << error;
    const std::string path = (std::filesystem::temp_directory_path() / "cadlod_chain_readback.flt").string();
    ASSERT_TRUE(flt::writeOpenFlightFile(path, model, flt::WriteOptions{}, error)) << error;

    const test::OsgProbe probe = test::probeWithOsg(path);
    ASSERT_TRUE(probe.loaded);
    ASSERT_EQ(probe.lods.size(), chain.levels.size());
    TestMesh level0;
    meshFromOsg(probe.lods[0].triangles, level0);
    ASSERT_EQ(level0.fn, chain.levels[0].faces);
    EXPECT_EQ(probe.lods[0].minRange, 0.0f);
    const double tanHalf = std::tan(0.5 * options.view.fovYDegrees * M_PI / 180.0);
    for (std::size_t k = 1; k < probe.lods.size(); ++k) {
        const test::OsgLodChild& child = probe.lods[k];
        EXPECT_FLOAT_EQ(child.minRange, probe.lods[k - 1].maxRange);  // contiguous
        EXPECT_GT(child.maxRange, child.minRange);                     // monotone
        TestMesh level;
        meshFromOsg(child.triangles, level);
        const std::size_t samples = 4 * std::size_t(level0.fn);
        const double measured = std::max(oneSidedHausdorff(level0, level, samples, 21).max,
                                         oneSidedHausdorff(level, level0, samples, 22).max);
        const double pixels = measured * options.view.viewportHeightPx / (2.0 * child.minRange * tanHalf);
        EXPECT_LE(pixels, options.view.pixelThreshold * 1.05)
            << "level " << k << " (" << level.fn << " triangles) is drawn from " << child.minRange;
    }
    std::filesystem::remove(path);
}
