// An assembly as the file writes it: distinct geometries, each read once in a frame of its
// own, and the placements that put them in the world. A geometry is what a shared node
// holds: a DEF'd node that is also USE'd, or an Inline file. Its own shapes are its parts;
// the shared nodes inside it are child placements, relative to its frame, so a board that
// holds connectors places them again wherever the board is placed.
//
// A geometry's frame is the file's, scaled to output units (the unit scale is uniform, so it
// moves into the geometry and out of the matrices); placement matrices hold the rest.
#pragma once

#include "vrml/math.h"
#include "vrml/part.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cadlod::vrml {

struct ChildPlacement {
    std::size_t geometry = 0;
    Mat4 relative;      // child frame -> parent frame
    std::string name;   // the DEF names between the parent and the child, or the child's own name
};

struct Geometry {
    std::string name;   // the DEF name, or the Inline's file name
    std::vector<Part> parts;
    std::vector<ChildPlacement> children;

    std::size_t triangleCount() const;
};

// A geometry where it stands: its frame -> the world.
struct Placement {
    std::string path;   // unique: the names along the way from the root, "Rack_1/Board_2/J3"
    Mat4 matrix;
    std::size_t geometry = 0;

    bool mirrored() const { return matrix.determinant3() < 0; }
    double largestScale() const;
};

struct Assembly {
    // [0] is the root: the shapes no shared node holds, in world coordinates.
    std::vector<Geometry> geometries;

    bool empty() const { return geometries.empty(); }
    // How many placements of geometry with parts the assembly expands to (saturating).
    std::uint64_t placementCount() const;
    // Some geometry with parts is placed more than once.
    bool sharesGeometry() const;
};

// A file that shares nothing as an assembly of its parts, each placed once where it stands:
// one geometry per named part (Part::named; its shapes, one per colour, stay together), in
// file order; the shapes no DEF names stay in the root. A viewer inside the model then meets
// LOD nodes the size of parts, not one for the whole model.
Assembly partsPlacedOnce(std::vector<Part>&& parts);

// How many parts the CAD system named (Part::named) `parts` holds.
std::size_t namedParts(const std::vector<Part>& parts);

// Every placement of a geometry that has parts, depth first in file order, with unique
// paths (a repeated path gets "[2]", "[3]"...). The root's placement is named `rootName`.
std::vector<Placement> flattenPlacements(const Assembly& assembly, const std::string& rootName);

}  // namespace cadlod::vrml
