// A large part seen from up close, in chunks (design.md §5, HLOD below the part): a viewer
// beside a long housing is near one end of it and far from the other, but the part's one LOD
// node switches by the distance to its centre, so it must hold its finest level until the
// viewer is several radii off (lod/nearest_point.h). Cut into a grid of chunks, the finest
// level's triangles go to the chunk of their centroid; each chunk is an LOD node of its own,
// with its own centre and reach, so the chunks away from the viewer coarsen early. The finest
// triangles longer than a chunk (a face's slivers, a plate's two triangles) are chunks of their
// own, which span the part along the axes they are long on and are cells along the others:
// taken by a cell, one of them would hold that cell's whole chunk back to its length. A coarse
// triangle goes to every chunk whose finest triangles it stands for, cut to the box of the
// chunk's finest triangles grown by the level's error: each chunk's levels cover the surface
// its finest level does and reach no farther, and where two chunks show different levels they
// overlap, but open no hole. Nearer than where its own first simplified level holds, a chunk is
// cut again the same way: wherever the viewer stands, the pieces about them are small enough to
// coarsen at the distance they are seen from. The levels are the part's own chain, simplified
// whole: only the switch distances are the chunk's.
#pragma once

#include "openflight/instanced_writer.h"  // PartChunk

#include <cstddef>
#include <string>
#include <vector>

namespace cadlod {

// A part is first cut into at most this many chunks along each axis.
inline constexpr int kChunksPerAxis = 4;
// A chunk is cut again into at most this many along each axis: its pieces are half its size,
// and so may coarsen at half the distance. A part whose finest level is too few triangles for
// kChunksPerAxis is cut into as many: a bolt in two along its length.
inline constexpr int kSubchunksPerAxis = 2;
// A part is cut when its radius is at least this share of the assembly's: smaller parts
// are as small as the chunks would be, and chunks of them would only add draw calls.
inline constexpr double kChunkedPartShare = 1.0 / 16.0;
// A part is cut only where its finest level gives its chunks at least this many triangles
// each, on average: every chunk is a draw call of its own, and a board of a dozen triangles
// cut into ten would draw ten calls for what one draws. A chunk is cut again only where its
// pieces would hold as many triangles each as a draw call costs (kDrawCallTriangles,
// hierarchical_lod.h): they coarsen nearer, but near the viewer they draw their finest level
// in more calls.
inline constexpr std::size_t kLeastChunkTriangles = 64;

// `levels`: the chain of the part named `partName` (its chunks' levels are named after it),
// finest first, each switched in where its error projects to the pixel error at the centre (not
// yet held at the nearest point); the chunks are drawn while the eye is nearer than `drawnTo`
// to the part's centre (where its first simplified level, held at its nearest point, takes
// over): a chunk keeps the levels it shows there. Empty when chunks would not let any level
// switch nearer, the part's radius is below `smallestRadius`, or even its halves would hold
// fewer than kLeastChunkTriangles each. `errors[k]`: how far level k stands from the finest at most
// (its Hausdorff distance).
std::vector<flt::PartChunk> chunkLevels(const std::string& partName, const std::vector<flt::Level>& levels,
                                        const std::vector<double>& errors, double smallestRadius, double drawnTo);

// How many chunks `chunks` hold, at every depth.
std::size_t chunkCount(const std::vector<flt::PartChunk>& chunks);

}  // namespace cadlod
