// An assembly whose instances are kept, to an instanced OpenFlight model: each distinct
// part through a LOD chain of its own, in its own frame (so its switch distances hold in
// every placement, OSG measuring the eye's distance in the part's frame), its switch
// distances pushed out by its radius (so they hold at its nearest point), then one placement
// per use, named by its path.
#pragma once
#include "assembly/level_store.h"
#include "assembly/part_mesh.h"
#include "assembly/progress_spans.h"

#include "lod/lod_builder.h"  // LodSetResult
#include "openflight/instanced_writer.h"
#include "vrml/scene.h"

#include <functional>
#include <string>
#include <vector>

namespace cadlod {

// The chain of one part: `original` is ready for the simplifier, the levels go to `store`,
// its steps to `progress` (null: none; several chains may run at once, parallel_tasks.h).
using BuildChain = std::function<LodSetResult(CoreMesh& original, LevelStore& store, vcg::CallBackPos* progress)>;

struct PartChain {
    std::string name;
    std::size_t placements = 0;
    int triangles = 0;           // level 0
    int weldedVertices = 0;      // as the importer welds a whole model
    int degenerateFaces = 0;     // ... and removes the faces welding left with a vertex twice
    LodSetResult result;         // levels and what the chain said
};

struct AssemblyConversion {
    flt::InstancedModel model;
    std::vector<PartChain> parts;  // one per definition of the model
    std::size_t skippedFaces = 0;  // degenerate faces the level conversion dropped
    std::size_t stretchedPlacements = 0;  // given stretched parts (stretched_placements.h)
};

// `modelName` names the model (its header and root group). `chunkLargeParts`: a part large
// in the assembly is written in chunks (part_chunks.h). The parts' chains run at once
// (parallel_tasks.h); each is a span of `progress`.
// Throws std::runtime_error when a part cannot be converted (its name in the message).
AssemblyConversion convertAssembly(vrml::Scene& scene, const std::string& modelName, const PartWelding& welding,
                                   const BuildChain& buildChain, bool chunkLargeParts = false,
                                   const ProgressSpans& progress = {});

// Multiplies every length of `c` (the model, the proxies, what each part's chain says) by
// `factor`: from the power of two the parts were simplified at to the unit chosen
// (vrml::UnitScaling).
void scaleLengths(AssemblyConversion& c, double factor);

}  // namespace cadlod
