// Paints faces by triangle compactness on a fixed 0..1 scale: red (0, slivers) through
// yellow (0.5) to green (1, equilateral). A fixed range, not the layer's min..max, so two
// layers (before/after) painted this way compare at a glance.
#pragma once

#include <vcg/complex/complex.h>

#include <algorithm>
#include <cmath>

namespace cadlod {

// The log line that goes with the painting (one %s: the layer's name).
inline constexpr const char* kCompactnessPaintNote =
    "Faces of %s painted by compactness, fixed scale: red 0 (slivers), yellow 0.5, green 1 (equilateral). "
    "This replaced the layer's face colours (CAD part and face colours): open the file again before "
    "exporting if you need them. The colours are not redone when the mesh changes: run the filter again.";

inline vcg::Color4b compactnessColor(double c)
{
    const double t = std::clamp(std::isfinite(c) ? c : 0.0, 0.0, 1.0);
    const auto byte = [](double x) { return static_cast<unsigned char>(std::lround(std::clamp(x, 0.0, 1.0) * 255.0)); };
    return vcg::Color4b(byte(2.0 * (1.0 - t)), byte(2.0 * t), 0, 255);
}

// Sets each live face's colour from its quality (which must hold its compactness).
template <class MeshType>
void paintFacesByCompactness(MeshType& m)
{
    for (auto& f : m.face)
        if (!f.IsD())
            f.C() = compactnessColor(double(f.cQ()));
}

}  // namespace cadlod
