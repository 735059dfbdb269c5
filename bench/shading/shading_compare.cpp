// shading_compare INPUT.ply RESULT.ply [--resolution N] [--images PREFIX]
// Prints the shading error of RESULT against INPUT (docs/shading_measure.md), per view and
// in total; with --images writes PREFIXviewNN.png (input | result | difference).
#include "ply_read.h"
#include "shading_error.h"

#include <chrono>
#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
    std::string files[2], images;
    int nFiles = 0;
    cadlod::shading::Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--resolution" && i + 1 < argc)
            options.resolution = std::stoi(argv[++i]);
        else if (a == "--images" && i + 1 < argc)
            images = argv[++i];
        else if (!a.empty() && a[0] != '-' && nFiles < 2)
            files[nFiles++] = a;
        else {
            std::fprintf(stderr, "usage: shading_compare INPUT.ply RESULT.ply [--resolution N] [--images PREFIX]\n");
            return 2;
        }
    }
    if (nFiles != 2) {
        std::fprintf(stderr, "usage: shading_compare INPUT.ply RESULT.ply [--resolution N] [--images PREFIX]\n");
        return 2;
    }
    cadlod::shading::IndexedMesh mesh[2];
    for (int k = 0; k < 2; ++k) {
        std::string error;
        if (!cadlod::shading::readPly(files[k], mesh[k], error)) {
            std::fprintf(stderr, "%s: %s\n", files[k].c_str(), error.c_str());
            return 1;
        }
    }
    const auto t = std::chrono::steady_clock::now();
    const cadlod::shading::Result r = cadlod::shading::compare(mesh[0].ref(), mesh[1].ref(), options, images);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
    std::printf("view  covered  silhouette  shading  visible%%  mean|dI|\n");
    for (std::size_t v = 0; v < r.views.size(); ++v) {
        const auto& f = r.views[v];
        std::printf("%4zu %8lld %11lld %8lld %8.3f %9.3f\n", v, (long long)f.either, (long long)f.silhouette,
                    (long long)f.shading, f.either ? 100.0 * (f.silhouette + f.shading) / f.either : 0.0,
                    f.either ? f.sumAbsDelta / f.either : 0.0);
    }
    std::printf("visible difference %.3f %% of covered pixels (silhouette %.3f %%), mean |dI| %.3f; "
                "%zu vs %zu triangles, %.2f s\n",
                r.visiblePercent, r.silhouettePercent, r.meanAbsDelta, mesh[0].tri.size() / 3, mesh[1].tri.size() / 3,
                seconds);
    return 0;
}
