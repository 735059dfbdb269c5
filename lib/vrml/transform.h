// VRML transforms as matrices: Transform (T·C·R·SR·S·-SR·-C), VRML 1.0 MatrixTransform.
#pragma once

#include "vrml/math.h"
#include "vrml/node.h"

namespace cadlod::vrml {

struct TransformFields {
    Vec3 translation, center, scale{1, 1, 1};
    Vec3 rotationAxis{0, 0, 1}, scaleAxis{0, 0, 1};
    double rotationAngle = 0, scaleAngle = 0;
};

Mat4 transformMatrix(const TransformFields& t);

// Field readers shared by both evaluators (missing or short fields give `fallback`).
Vec3 vec3Field(const Node& n, const char* name, Vec3 fallback);
// A field that places geometry, in double precision as written (FieldValue::exact).
Vec3 exactVec3Field(const Node& n, const char* name, Vec3 fallback);
std::vector<double> exactNumbersField(const Node& n, const char* name);
float floatField(const Node& n, const char* name, float fallback);
// SFInt32 read as a number; values outside the int32 range give `fallback`.
int32_t intField(const Node& n, const char* name, int32_t fallback);
bool boolField(const Node& n, const char* name, bool fallback);
std::string wordField(const Node& n, const char* name, const std::string& fallback);
// SFRotation: axis, angle.
void rotationField(const Node& n, const char* name, Vec3& axis, double& angle);
const std::vector<float>* floatsField(const Node& n, const char* name);
const std::vector<int32_t>* intsField(const Node& n, const char* name);

// Transform node fields; `scaleName` is "scale" (VRML97) or "scaleFactor" (VRML 1.0).
TransformFields readTransformFields(const Node& n, const char* scaleName);

// VRML 1.0 MatrixTransform: 16 numbers, row vectors (translation in the last row).
Mat4 matrixFromRowVectors(const std::vector<double>& m);

}  // namespace cadlod::vrml
