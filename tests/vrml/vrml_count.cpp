// Prints what cadlod's VRML core reads from each file given: triangles, parts,
// vertices, skipped faces and warnings (one line per file). Used by the Coin3D
// conformance comparison and handy when triaging a user's file.
#include "vrml/importer.h"

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv)
{
    int failures = 0;
    for (int i = 1; i < argc; ++i) {
        const cadlod::vrml::ImportResult r = cadlod::vrml::importVrmlFile(argv[i]);
        if (!r.ok()) {
            std::printf("%s\terror\t%s\n", argv[i], r.error.c_str());
            ++failures;
            continue;
        }
        std::printf("%s\tmesh %zu\tround %zu\tparts %zu\tvertices %zu\tskipped %zu\twarnings %d\n", argv[i],
                    r.scene.stats.meshTriangles, r.scene.stats.roundPrimitiveTriangles, r.scene.parts.size(),
                    r.scene.vertexCount(), r.scene.stats.skippedFaces, r.scene.diagnostics.total());
        if (std::getenv("VRML_COUNT_VERBOSE"))
            for (const auto& d : r.scene.diagnostics.kept())
                std::printf("  %s: %s: %s\n", d.where.c_str(), d.kind.c_str(), d.message.c_str());
    }
    return failures ? 1 : 0;
}
