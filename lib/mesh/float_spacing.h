// How far apart 32-bit floats are at a value: how finely a coordinate stored as a float
// stands there (MeshLab's meshes, the VRML scene, OpenFlight's Matrix records and
// OpenSceneGraph's vertices all keep floats).
#pragma once

#include <cmath>
#include <limits>

namespace cadlod {

inline double floatSpacing(double x)
{
    return x == 0 ? 0.0 : std::ldexp(1.0, std::ilogb(std::abs(x)) - (std::numeric_limits<float>::digits - 1));
}

}  // namespace cadlod
