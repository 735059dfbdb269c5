// Times cadlod's VRML core alone on one file: import into the neutral scene, then prints
// one tab-separated line: file MB, seconds, MB/s, triangles, triangles/s, peak RSS MB.
#include "vrml/importer.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s FILE.wrl\n", argv[0]);
        return 2;
    }
    const auto start = std::chrono::steady_clock::now();
    const cadlod::vrml::ImportResult r = cadlod::vrml::importVrmlFile(argv[1]);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!r.ok()) {
        std::fprintf(stderr, "%s\n", r.error.c_str());
        return 1;
    }
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const double mb = r.scene.stats.bytesRead / 1e6;
    const size_t tris = r.scene.triangleCount();
    std::printf("%.1f\t%.3f\t%.1f\t%zu\t%.0f\t%.0f\n", mb, seconds, mb / seconds, tris, tris / seconds,
                usage.ru_maxrss / 1024.0);
    return 0;
}
