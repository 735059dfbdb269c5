// Writes small OpenFlight files like the OpenFlight tests do (Mesh and Face records, one
// and three levels, per-part and per-level objects) as the reader's fuzz seed corpus.
#include "openflight/flt_writer.h"
#include "model_fixtures.h"

#include <cstdio>
#include <string>

using namespace cadlod;

static bool writeSeed(const std::string& dir, const std::string& name, const flt::LodModel& model,
                      const flt::WriteOptions& options)
{
    std::string error;
    if (!flt::writeOpenFlightFile(dir + "/" + name + ".flt", model, options, error)) {
        std::fprintf(stderr, "%s: %s\n", name.c_str(), error.c_str());
        return false;
    }
    return true;
}

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: flt_seed_writer OUTPUT_DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    flt::WriteOptions meshes, faces, perLevel, doubleSided;
    faces.geometry = flt::GeometryRecords::Faces;
    perLevel.objects = flt::ObjectGrouping::PerLevel;
    doubleSided.drawType = flt::DrawType::TwoSided;
    bool ok = true;
    ok &= writeSeed(dir, "single_meshes", test::singleLevelModel(3), meshes);
    ok &= writeSeed(dir, "single_faces", test::singleLevelModel(2), faces);
    ok &= writeSeed(dir, "three_levels_meshes", test::threeLevelModel(), meshes);
    ok &= writeSeed(dir, "three_levels_faces", test::threeLevelModel(), faces);
    ok &= writeSeed(dir, "three_levels_per_level", test::threeLevelModel(), perLevel);
    ok &= writeSeed(dir, "double_sided", test::singleLevelModel(2), doubleSided);
    return ok ? 0 : 1;
}
