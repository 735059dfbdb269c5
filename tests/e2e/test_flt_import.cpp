// Opening .flt files in meshlabserver: our own output round-trips, OpenSceneGraph's
// output opens, corrupt files fail with the record offset (and never hang).
#include "flt_e2e_meshes.h"
#include "openflight/flt_writer.h"
#include "meshlabserver_runner.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace cadlod::test;

TEST(FltImport, FinestLevelOfAnLodFileOpens)
{
    const std::string dir = scratchDir("flt_import_lod");
    const cadlod::flt::LodModel model = threeLevelModel();
    std::string error;
    ASSERT_TRUE(cadlod::flt::writeOpenFlightFile(dir + "/set.flt", model, {}, error)) << error;
    const std::string ply = dir + "/finest.ply";
    std::filesystem::remove(ply);
    const ServerRun run = runMeshlabServer({"-i", dir + "/set.flt", "-o", ply, "-m", "vn"});
    ASSERT_TRUE(run.ok()) << run.output;
    TestMesh back;
    ASSERT_TRUE(loadPly(ply, back));
    ASSERT_EQ(std::size_t(back.fn), model.levels[0].triangleCount());
    const auto expected = flatTriangles(model.levels[0]);
    const auto got = meshTriangles(back);
    ASSERT_EQ(got.size(), expected.size());
    EXPECT_LT(compareTriangles(expected, got).position, 1e-5f);
    EXPECT_LT(compareTriangles(expected, got).normal, 1e-5f);
    EXPECT_NE(run.output.find("3 LOD level(s), opened level 0"), std::string::npos) << run.output;
}

TEST(FltImport, ExportThenImportRoundTrips)
{
    const std::string dir = scratchDir("flt_import_roundtrip");
    TestMesh torus;
    makeTorusMesh(torus);
    ASSERT_TRUE(savePly(dir + "/torus.ply", torus, vcg::tri::io::Mask::IOM_VERTNORMAL));
    ServerRun run = runMeshlabServer({"-i", dir + "/torus.ply", "-o", dir + "/torus.flt"});
    ASSERT_TRUE(run.ok()) << run.output;
    run = runMeshlabServer({"-i", dir + "/torus.flt", "-o", dir + "/back.ply", "-m", "vn"});
    ASSERT_TRUE(run.ok()) << run.output;
    TestMesh back;
    ASSERT_TRUE(loadPly(dir + "/back.ply", back));
    EXPECT_EQ(back.vn, torus.vn) << "shared vertices stay shared";
    const auto expected = meshTriangles(torus);
    const auto got = meshTriangles(back);
    ASSERT_EQ(got.size(), expected.size());
    EXPECT_LT(compareTriangles(expected, got).position, 1e-6f);
    EXPECT_LT(compareTriangles(expected, got).normal, 1e-6f);
}

TEST(FltImport, CorruptFileFailsWithTheRecordOffset)
{
    const std::string dir = scratchDir("flt_import_corrupt");
    std::vector<std::uint8_t> bytes;
    std::string error;
    ASSERT_TRUE(cadlod::flt::writeOpenFlight(singleLevelModel(3), {}, bytes, error)) << error;
    bytes.resize(bytes.size() - 10);  // cut inside the last records
    const std::string flt = dir + "/cut.flt";
    std::ofstream(flt, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), long(bytes.size()));
    const ServerRun run = runMeshlabServer({"-i", flt, "-o", dir + "/never.ply"}, 60);
    EXPECT_FALSE(run.timedOut) << "a dialog or a hang";
    EXPECT_FALSE(run.ok());
    EXPECT_FALSE(std::filesystem::exists(dir + "/never.ply"));
    EXPECT_NE(run.output.find("offset"), std::string::npos) << run.output;
}
