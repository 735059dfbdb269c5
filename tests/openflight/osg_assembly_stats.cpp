// osg_assembly_stats FILE.flt [MODEL_NAME]: loads an assembly .flt with OpenSceneGraph and
// prints, one "key value" per line, its load time, the triangles drawn from up close, the
// placements, the shared nodes and the LOD subgraphs. Exit 1 if OSG cannot read it.
#include "osg_assembly_probe.h"

#include <cstdio>

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s FILE.flt [MODEL_NAME]\n", argv[0]);
        return 2;
    }
    const cadlod::test::OsgAssemblyProbe p = cadlod::test::probeAssemblyWithOsg(argv[1], argc > 2 ? argv[2] : "");
    if (!p.loaded) {
        std::fprintf(stderr, "OpenSceneGraph could not read %s\n", argv[1]);
        return 1;
    }
    std::printf("load_seconds %.3f\nfinest_triangles %zu\nplacements %zu\nshared_nodes %zu\nlod_nodes %zu\n"
                "lod_subgraphs %zu\ndrawables %zu\n",
                p.loadSeconds, p.finestTriangles.size(), p.placements.size(), p.sharedNodes, p.lodNodes,
                p.lodSubgraphs, p.drawables);
    return 0;
}
