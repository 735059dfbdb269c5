// paper_measure: the mesh measures of the paper's experiments on PLY files, with
// cadlod's cores (design.md §8):
//   paper_measure compactness MESH.ply [HIST.dat [BINS]]   compactness stats (+ histogram)
//   paper_measure hausdorff A.ply B.ply [SAMPLES]            symmetric Hausdorff distance
//   paper_measure simplify IN.ply OUT.ply PERCENT            CAD Quadric Edge Collapse with
//       default parameters, for when the MeshLab filter is not available
//   paper_measure lodset IN.ply OUTDIR "50 60 70 80 90"       the LOD-set builder with
//       default parameters: OUTDIR/level<K>.ply and OUTDIR/lodset.flt, for when the
//       "Generate CAD LOD Set" filter is not available
// Output: one "key value" line per figure.
#include "measure/compactness.h"
#include "measure/hausdorff.h"
#include "lod/lod_builder.h"
#include "simplify/best_of_trials.h"
#include "openflight/flt_writer.h"

#include "test_mesh.h"

#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/io_mask.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <string>
#include <vector>

namespace {

using cadlod::test::TestMesh;

[[noreturn]] void usage(const char* why)
{
    std::fprintf(stderr,
                 "paper_measure: %s\n"
                 "usage: paper_measure compactness MESH.ply [HIST.dat [BINS]]\n"
                 "       paper_measure hausdorff A.ply B.ply [SAMPLES]\n"
                 "       paper_measure simplify IN.ply OUT.ply PERCENT\n"
                 "       paper_measure lodset IN.ply OUTDIR LEVELS\n",
                 why);
    std::exit(2);
}

void load(const std::string& path, TestMesh& m)
{
    int mask = 0;
    std::string error;
    if (!cadlod::test::loadPly(path, m, mask, error)) {
        std::fprintf(stderr, "paper_measure: %s\n", error.c_str());
        std::exit(1);
    }
    if (m.fn == 0) {
        std::fprintf(stderr, "paper_measure: %s has no faces\n", path.c_str());
        std::exit(1);
    }
}

// Fraction of faces per compactness bin over [0, 1], one "center fraction" line per bin.
bool writeHistogram(const std::vector<double>& values, int bins, const std::string& path)
{
    std::vector<std::size_t> count(std::size_t(bins), 0);
    for (double c : values)
        ++count[std::size_t(std::min(bins - 1, int(c * bins)))];
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f)
        return false;
    std::fprintf(f, "# compactness_bin_center fraction_of_faces\n");
    for (int b = 0; b < bins; ++b)
        std::fprintf(f, "%.4f %.6f\n", (b + 0.5) / bins, double(count[std::size_t(b)]) / values.size());
    return std::fclose(f) == 0;
}

int compactness(int argc, char** argv)
{
    if (argc < 3)
        usage("compactness needs a mesh");
    TestMesh m;
    load(argv[2], m);
    std::vector<double> values = cadlod::faceCompactness(m);
    if (argc > 3) {
        const int bins = argc > 4 ? std::atoi(argv[4]) : 20;
        if (bins < 1 || !writeHistogram(values, bins, argv[3])) {
            std::fprintf(stderr, "paper_measure: cannot write the histogram %s\n", argv[3]);
            return 1;
        }
    }
    std::size_t repeatedVertex = 0;
    for (const auto& f : m.face)
        repeatedVertex += f.cV(0) == f.cV(1) || f.cV(1) == f.cV(2) || f.cV(0) == f.cV(2);
    const std::size_t zeroArea = std::size_t(std::count(values.begin(), values.end(), 0.0));
    std::printf("repeated_vertex_faces %zu\nzero_area_faces %zu\n", repeatedVertex, zeroArea);
    const cadlod::CompactnessStats s = cadlod::summarizeCompactness(values);
    std::printf("faces %zu\nmean %.4f\nmin %.4f\np5 %.4f\nbelow01 %.4f\nbelow03 %.4f\n", s.faces, s.mean, s.min,
                s.p5, s.shareBelow01, s.shareBelow03);
    return 0;
}

int hausdorff(int argc, char** argv)
{
    if (argc < 4)
        usage("hausdorff needs two meshes");
    TestMesh a, b;
    load(argv[2], a);
    load(argv[3], b);
    const std::size_t samples = argc > 4 ? std::size_t(std::atol(argv[4])) : std::size_t(a.fn);
    const cadlod::SymmetricHausdorff h = cadlod::symmetricHausdorff(a, b, samples);
    std::printf("samples_per_side %zu\ndiagonal %.6g\nmax %.6g\nmean %.6g\nmax_pct_diag %.4f\nmean_pct_diag %.5f\n",
                samples, h.diagonal, h.max(), h.mean(), 100 * h.maxFraction(), 100 * h.meanFraction());
    return 0;
}

void prepareForCollapse(TestMesh& m)
{
    vcg::tri::Allocator<TestMesh>::CompactEveryVector(m);
    vcg::tri::UpdateTopology<TestMesh>::VertexFace(m);
}

bool saveWithNormals(const std::string& path, TestMesh& m)
{
    vcg::tri::UpdateNormal<TestMesh>::PerVertexNormalizedPerFace(m);
    if (cadlod::test::savePly(path, m, vcg::tri::io::Mask::IOM_VERTNORMAL))
        return true;
    std::fprintf(stderr, "paper_measure: cannot write %s\n", path.c_str());
    return false;
}

// One level as the OpenFlight writer wants it: a single part (PLY files carry no parts).
cadlod::flt::Level fltLevel(TestMesh& m, const cadlod::LodLevel& info)
{
    cadlod::flt::Part part;
    part.name = "level" + std::to_string(info.level);
    for (const auto& v : m.vert) {
        part.positions.push_back({double(v.cP()[0]), double(v.cP()[1]), double(v.cP()[2])});
        part.normals.push_back({v.cN()[0], v.cN()[1], v.cN()[2]});
    }
    for (const auto& f : m.face)
        part.triangles.push_back({std::uint32_t(vcg::tri::Index(m, f.cV(0))),
                                  std::uint32_t(vcg::tri::Index(m, f.cV(1))),
                                  std::uint32_t(vcg::tri::Index(m, f.cV(2)))});
    cadlod::flt::Level level;
    level.name = part.name;
    level.switchIn = info.switchIn;
    level.switchOut = info.switchOut;
    level.center = info.center;
    level.parts.push_back(std::move(part));
    return level;
}

int lodSet(int argc, char** argv)
{
    if (argc < 5)
        usage("lodset needs IN OUTDIR LEVELS");
    const std::string dir = argv[3];
    std::deque<TestMesh> levels(1);
    load(argv[2], levels.front());
    prepareForCollapse(levels.front());
    cadlod::LodSetOptions options;
    options.levels = argv[4];
    const cadlod::LodSetResult r = cadlod::buildLodSet<TestMesh>(
        levels.front(), options, [&](int) -> TestMesh& { return levels.emplace_back(); });
    if (!r.ok()) {
        std::fprintf(stderr, "paper_measure: %s\n", r.error.c_str());
        return 1;
    }
    cadlod::flt::LodModel model;
    model.name = "lodset";
    for (std::size_t k = 0; k < levels.size(); ++k) {
        if (!saveWithNormals(dir + "/level" + std::to_string(k) + ".ply", levels[k]))
            return 1;
        model.levels.push_back(fltLevel(levels[k], r.levels[k]));
        const cadlod::LodLevel& l = r.levels[k];
        std::printf("level %zu faces %d hausdorff_max %.6g switch_out %.6g switch_in %.6g\n", k, l.faces,
                    l.hausdorffMax, l.switchOut, l.switchIn);
    }
    std::string error;
    if (!cadlod::flt::writeOpenFlightFile(dir + "/lodset.flt", model, cadlod::flt::WriteOptions{}, error)) {
        std::fprintf(stderr, "paper_measure: %s\n", error.c_str());
        return 1;
    }
    return 0;
}

int simplify(int argc, char** argv)
{
    if (argc < 5)
        usage("simplify needs IN OUT PERCENT");
    TestMesh m;
    load(argv[2], m);
    prepareForCollapse(m);
    cadlod::SimplifyParams p;
    p.reductionPerc = std::atof(argv[4]);
    const cadlod::SimplifyStats s = cadlod::bestOfTrials(m, p);
    if (!s.ok) {
        std::fprintf(stderr, "paper_measure: %s\n", s.message.c_str());
        return 1;
    }
    vcg::tri::Allocator<TestMesh>::CompactEveryVector(m);
    if (!saveWithNormals(argv[3], m))
        return 1;
    std::printf("faces_before %d\nfaces_after %d\nseconds %.3f\n", s.facesBefore, s.facesAfter, s.seconds);
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 2)
        usage("no command");
    const std::string command = argv[1];
    if (command == "compactness")
        return compactness(argc, argv);
    if (command == "hausdorff")
        return hausdorff(argc, argv);
    if (command == "simplify")
        return simplify(argc, argv);
    if (command == "lodset")
        return lodSet(argc, argv);
    usage(("unknown command " + command).c_str());
}
