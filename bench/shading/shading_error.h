// Shading error between an input mesh and a simplified result (docs/shading_measure.md,
// design.md §8): both are rendered the same way from 12 fixed views by a deterministic
// software z-buffer rasterizer and the share of pixels a viewer sees differ is reported.
//
//   views      12 directions evenly spread on the sphere (the vertices of an icosahedron
//              turned by a fixed rotation, so that no view looks exactly along a
//              coordinate axis or plane of an axis-aligned CAD part), orthographic,
//              framing the INPUT's bounding sphere (box centre, half the box diagonal);
//              the same cameras render the result.
//   normals    per corner: area-weighted face normals summed over the smooth fan of the
//              corner's vertex; two faces sharing an edge are in one fan when their
//              normals differ by at most `creaseDegrees` (30°), as VRML's creaseAngle
//              does. Vertices at the same position are welded first, so the figure does
//              not depend on how a file splits vertices at creases.
//   faces      back faces culled (what a VR engine does with closed CAD parts: VRML
//              solid TRUE, OpenFlight's default draw mode).
//   lights     directional, fixed to the camera: a key light from the viewer, a little
//              above and left (0.75 diffuse), a fill from the right (0.25 diffuse), and
//              0.10 ambient; intensity clamped to 1 and rounded to 0..255. Per-pixel
//              (Phong) interpolated normals. Background is 0.
//   counts     a pixel covered by either image "differs" when only one image covers it
//              (silhouette) or when the intensities differ by more than `threshold`
//              (8 of 255). Figures are over the pixels covered by either image.
// Input: positions as double xyz and triangles as vertex indices; no MeshLab, no vcglib.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cadlod::shading {

struct MeshRef {
    const double* xyz = nullptr;          // 3 per vertex
    std::size_t vertexCount = 0;
    const std::uint32_t* tri = nullptr;   // 3 per triangle
    std::size_t triangleCount = 0;
};

struct IndexedMesh {
    std::vector<double> xyz;
    std::vector<std::uint32_t> tri;
    MeshRef ref() const { return {xyz.data(), xyz.size() / 3, tri.data(), tri.size() / 3}; }
};

struct Options {
    int resolution = 256;        // pixels per side of each (square) view
    double creaseDegrees = 30.0;
    int threshold = 8;           // |ΔI| above this (0..255) is visible
};

struct ViewFigures {
    std::int64_t either = 0;      // pixels covered by either image
    std::int64_t silhouette = 0;  // covered by one image only
    std::int64_t shading = 0;     // covered by both, |ΔI| > threshold
    double sumAbsDelta = 0;       // over `either` (background 0)
};

struct Result {
    std::vector<ViewFigures> views;
    std::int64_t either = 0, silhouette = 0, shading = 0;
    double visiblePercent = 0;    // 100 * (silhouette + shading) / either: the primary figure
    double silhouettePercent = 0; // 100 * silhouette / either
    double meanAbsDelta = 0;      // mean |ΔI| on 0..255 over `either`
};

// The 12 unit view directions (from the camera towards the part), fixed.
std::vector<std::array<double, 3>> viewDirections();

// The input rendered once, to compare any number of results against.
class Reference {
public:
    explicit Reference(MeshRef input, Options options = {});
    ~Reference();
    Reference(Reference&&) noexcept;
    Reference& operator=(Reference&&) noexcept;
    Reference(const Reference&) = delete;
    Reference& operator=(const Reference&) = delete;

    // Renders `result` with the input's cameras and compares. With `imagePrefix`, writes one
    // PNG per view, `<prefix>view<NN>.png`: input | result | difference (red: silhouette
    // mismatch, yellow: visible shading difference, grey: below the threshold).
    Result compare(MeshRef result, const std::string& imagePrefix = {}) const;

    const Options& options() const;

private:
    struct Impl;
    Impl* impl_;
};

// Unit normal per corner, 9 floats per triangle (the normals the renders use).
std::vector<float> cornerNormals(MeshRef mesh, double creaseDegrees);

// One-shot: Reference(input, options).compare(result).
Result compare(MeshRef input, MeshRef result, const Options& options = {}, const std::string& imagePrefix = {});

// Writes an 8-bit RGB image as PNG (zlib); false on I/O error.
bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb);

}  // namespace cadlod::shading
