#include "vrml/transform.h"

namespace cadlod::vrml {

Mat4 Mat4::translation(const Vec3& t)
{
    Mat4 r;
    r.m[0][3] = t.x;
    r.m[1][3] = t.y;
    r.m[2][3] = t.z;
    return r;
}

Mat4 Mat4::scale(const Vec3& s)
{
    Mat4 r;
    r.m[0][0] = s.x;
    r.m[1][1] = s.y;
    r.m[2][2] = s.z;
    return r;
}

Mat4 Mat4::rotation(const Vec3& axis, double angle)
{
    Mat4 r;
    const Vec3 a = normalized(axis);
    if (length(a) == 0 || angle == 0) return r;
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    r.m[0][0] = t * a.x * a.x + c;
    r.m[0][1] = t * a.x * a.y - s * a.z;
    r.m[0][2] = t * a.x * a.z + s * a.y;
    r.m[1][0] = t * a.x * a.y + s * a.z;
    r.m[1][1] = t * a.y * a.y + c;
    r.m[1][2] = t * a.y * a.z - s * a.x;
    r.m[2][0] = t * a.x * a.z - s * a.y;
    r.m[2][1] = t * a.y * a.z + s * a.x;
    r.m[2][2] = t * a.z * a.z + c;
    return r;
}

Mat4 Mat4::operator*(const Mat4& o) const
{
    Mat4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += m[i][k] * o.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}

Vec3 Mat4::transformPoint(const Vec3& p) const
{
    return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
            m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
            m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
}

Vec3 Mat4::transformVector(const Vec3& v) const
{
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

double Mat4::determinant3() const
{
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Mat4 Mat4::normalMatrix() const
{
    // Cofactor matrix = det * inverse transpose; the scale does not matter for normals
    // except its sign, which is fixed by dividing by the determinant's sign.
    Mat4 r;
    const double sign = determinant3() < 0 ? -1.0 : 1.0;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            r.m[i][j] = sign * (m[i1][j1] * m[i2][j2] - m[i1][j2] * m[i2][j1]);
        }
    return r;
}

Mat4 transformMatrix(const TransformFields& t)
{
    const Vec3 minusCenter = t.center * -1.0;
    return Mat4::translation(t.translation) * Mat4::translation(t.center) *
           Mat4::rotation(t.rotationAxis, t.rotationAngle) * Mat4::rotation(t.scaleAxis, t.scaleAngle) *
           Mat4::scale(t.scale) * Mat4::rotation(t.scaleAxis, -t.scaleAngle) * Mat4::translation(minusCenter);
}

const std::vector<float>* floatsField(const Node& n, const char* name)
{
    const FieldValue* v = n.field(name);
    if (!v) return nullptr;
    if (v->kind == FieldValue::Kind::Floats) return v->floats.get();
    return nullptr;
}

const std::vector<int32_t>* intsField(const Node& n, const char* name)
{
    const FieldValue* v = n.field(name);
    if (!v || v->kind != FieldValue::Kind::Ints) return nullptr;
    return v->ints.get();
}

Vec3 vec3Field(const Node& n, const char* name, Vec3 fallback)
{
    const std::vector<float>* f = floatsField(n, name);
    if (!f || f->size() < 3) return fallback;
    return {(*f)[0], (*f)[1], (*f)[2]};
}

std::vector<double> exactNumbersField(const Node& n, const char* name)
{
    const FieldValue* v = n.field(name);
    if (!v || v->kind != FieldValue::Kind::Floats)
        return {};
    if (v->exact)
        return *v->exact;
    return {v->floats->begin(), v->floats->end()};
}

Vec3 exactVec3Field(const Node& n, const char* name, Vec3 fallback)
{
    const std::vector<double> f = exactNumbersField(n, name);
    if (f.size() < 3) return fallback;
    return {f[0], f[1], f[2]};
}

float floatField(const Node& n, const char* name, float fallback)
{
    const std::vector<float>* f = floatsField(n, name);
    return f && !f->empty() ? (*f)[0] : fallback;
}

int32_t intField(const Node& n, const char* name, int32_t fallback)
{
    const float f = floatField(n, name, float(fallback));
    return f >= -2147483648.0f && f < 2147483648.0f ? int32_t(f) : fallback;
}

bool boolField(const Node& n, const char* name, bool fallback)
{
    const FieldValue* v = n.field(name);
    if (!v || v->kind != FieldValue::Kind::Words || v->strings.empty()) return fallback;
    if (v->strings[0] == "TRUE" || v->strings[0] == "true") return true;
    if (v->strings[0] == "FALSE" || v->strings[0] == "false") return false;
    return fallback;
}

std::string wordField(const Node& n, const char* name, const std::string& fallback)
{
    const FieldValue* v = n.field(name);
    if (!v || v->kind != FieldValue::Kind::Words || v->strings.empty()) return fallback;
    return v->strings[0];
}

void rotationField(const Node& n, const char* name, Vec3& axis, double& angle)
{
    const std::vector<float>* f = floatsField(n, name);
    if (!f || f->size() < 4) return;
    axis = {(*f)[0], (*f)[1], (*f)[2]};
    angle = (*f)[3];
}

TransformFields readTransformFields(const Node& n, const char* scaleName)
{
    TransformFields t;
    t.translation = exactVec3Field(n, "translation", t.translation);
    t.center = exactVec3Field(n, "center", t.center);
    t.scale = vec3Field(n, scaleName, t.scale);
    rotationField(n, "rotation", t.rotationAxis, t.rotationAngle);
    rotationField(n, "scaleOrientation", t.scaleAxis, t.scaleAngle);
    return t;
}

Mat4 matrixFromRowVectors(const std::vector<double>& v)
{
    Mat4 r;
    if (v.size() < 16) return r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[j][i] = v[size_t(i * 4 + j)];
    return r;
}

}  // namespace cadlod::vrml
