// Coordinates too coarse for the geometry they hold. The reader keeps 32-bit floats, as
// OpenSceneGraph and MeshLab do: far from the origin (site coordinates, or a part baked
// into world coordinates far off) they are spaced wider than a part's detail, and the part
// is read only to within that spacing. Instances kept place their parts about a local
// origin (openflight/local_origin.h), but geometry already in far coordinates cannot be
// restored: the user is told, and where.
#pragma once

#include "vrml/scene.h"

#include <string>

namespace cadlod::vrml {

// A part reads as it was where floats are spaced at most this share of its size: filling the
// screen, it is then off by about a pixel.
inline constexpr double kReadableVertexSpacing = 1e-3;

// Warns in scene.diagnostics ("coarse coordinates", at `fileName`) when some part's
// coordinates are spaced wider than kReadableVertexSpacing of its size: how many parts,
// how far off, how coarse, and the worst of them.
void warnOfCoarseCoordinates(Scene& scene, const std::string& fileName);

}  // namespace cadlod::vrml
