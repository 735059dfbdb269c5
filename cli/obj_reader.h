// Wavefront OBJ -> cadlod::CoreMesh for the command line. Our own reader, because
// vcglib 2020.09's ImporterOBJ silently drops every triangle that uses the file's first
// vertex in its second or third corner.
//  - v x y z [w]: a vertex (w ignored); v x y z r g b [a]: a vertex with its colour
//    (0..1, or 0..255 when a component is above 1), kept as the vertex colour.
//  - f with v, v/vt, v//vn or v/vt/vn corners, negative (relative) indices; a polygon is
//    fanned from its first corner. Faces repeating a vertex are kept: the simplifier
//    deletes and counts them, the OpenFlight writer skips and counts them.
//  - o names objects, g groups: with two or more of them owning faces (objects when the
//    file has any, else groups) each face gets its part (layer_metadata.h).
//  - vt, vn, s, mtllib, usemtl, comments and unknown keywords are ignored; a line ending
//    in '\' continues on the next one.
// Vertices are kept as the file lists them (no welding); vertex normals are the
// area-weighted face normals (the file's vn can differ per corner, a mesh vertex cannot).
#pragma once
#include "mesh/core_mesh.h"

#include <cstddef>
#include <istream>
#include <string>

namespace cadlod::cli {

// Reads `in` into `m` (empty); `sourceName` starts every message. Returns the number of
// parts (1 when the file has no part table). Throws InputError "name:line:column: message"
// on a malformed number, an index that is 0 or out of range, or a face under 3 corners.
std::size_t readObj(std::istream& in, const std::string& sourceName, CoreMesh& m);

// The same for the file `path`; throws InputError when it cannot be opened.
std::size_t readObjFile(const std::string& path, CoreMesh& m);

}  // namespace cadlod::cli
