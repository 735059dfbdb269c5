// osg_flt_probe FILE.flt [osgDB options]: loads a .flt with OpenSceneGraph and prints
// its LOD nodes, triangles per LOD child and node names. Exit 1 if OSG cannot read it.
#include "osg_probe.h"

#include <cstdio>

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s FILE.flt [osgDB options]\n", argv[0]);
        return 2;
    }
    const cadlod::test::OsgProbe p = cadlod::test::probeWithOsg(argv[1], argc > 2 ? argv[2] : "");
    if (!p.loaded) {
        std::fprintf(stderr, "OpenSceneGraph could not read %s\n", argv[1]);
        return 1;
    }
    std::printf("lod_children %zu\n", p.lods.size());
    for (std::size_t i = 0; i < p.lods.size(); ++i) {
        const auto& l = p.lods[i];
        std::printf("lod %zu range %g %g center %g %g %g triangles %zu\n", i, l.minRange, l.maxRange,
                    l.center[0], l.center[1], l.center[2], l.triangles.size());
    }
    std::printf("triangles_outside_lods %zu\n", p.outsideLods.size());
    for (const auto& n : p.names)
        std::printf("name %s\n", n.c_str());
    return 0;
}
