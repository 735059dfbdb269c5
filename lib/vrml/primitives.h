// VRML geometry nodes other than IndexedFaceSet, expressed as indexed face sets so
// they share the face-set emitter: Box/Cube, Sphere, Cylinder, Cone, ElevationGrid,
// Extrusion. Tessellation of round primitives uses kRoundSegments around the axis.
#pragma once

#include "vrml/math.h"

#include <cstdint>
#include <vector>

namespace cadlod::vrml {

inline constexpr int kRoundSegments = 24;

struct OwnedFaceSet {
    std::vector<float> coords;
    std::vector<int32_t> coordIndex;
    float creaseAngle = 0.5f;  // smooth round sides, sharp rims
    bool convex = true;
    bool ccw = true;
};

OwnedFaceSet makeBox(const Vec3& size);
OwnedFaceSet makeSphere(double radius);
OwnedFaceSet makeCylinder(double radius, double height, bool side, bool top, bool bottom);
OwnedFaceSet makeCone(double bottomRadius, double height, bool side, bool bottom);
// heights row-major, x fastest; missing heights count as 0.
OwnedFaceSet makeElevationGrid(int xDimension, int zDimension, double xSpacing, double zSpacing,
                               const std::vector<float>& heights);

struct ExtrusionSpec {
    std::vector<float> crossSection{1, 1, 1, -1, -1, -1, -1, 1, 1, 1};  // 2D points
    std::vector<float> spine{0, 0, 0, 0, 1, 0};                         // 3D points
    std::vector<float> scale{1, 1};                                     // 2D per spine point
    std::vector<float> orientation{0, 0, 1, 0};                         // rotation per spine point
    bool beginCap = true, endCap = true;
};
OwnedFaceSet makeExtrusion(const ExtrusionSpec& spec);

}  // namespace cadlod::vrml
