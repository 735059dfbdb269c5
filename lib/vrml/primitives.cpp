#include "vrml/primitives.h"

#include <algorithm>
#include <cmath>

namespace cadlod::vrml {
namespace {

int32_t addPoint(OwnedFaceSet& f, const Vec3& p)
{
    f.coords.insert(f.coords.end(), {float(p.x), float(p.y), float(p.z)});
    return int32_t(f.coords.size() / 3 - 1);
}

void addFace(OwnedFaceSet& f, std::initializer_list<int32_t> corners)
{
    f.coordIndex.insert(f.coordIndex.end(), corners);
    f.coordIndex.push_back(-1);
}

double angleOf(int i) { return 2.0 * M_PI * i / kRoundSegments; }

// A ring of points around the y axis at height y, starting at +z, counter-clockwise seen from +y.
std::vector<int32_t> addRing(OwnedFaceSet& f, double radius, double y)
{
    std::vector<int32_t> ring;
    for (int i = 0; i < kRoundSegments; ++i)
        ring.push_back(addPoint(f, {radius * std::sin(angleOf(i)), y, radius * std::cos(angleOf(i))}));
    return ring;
}

void addCap(OwnedFaceSet& f, const std::vector<int32_t>& ring, bool facingUp)
{
    if (facingUp) f.coordIndex.insert(f.coordIndex.end(), ring.begin(), ring.end());
    else f.coordIndex.insert(f.coordIndex.end(), ring.rbegin(), ring.rend());
    f.coordIndex.push_back(-1);
}

}  // namespace

OwnedFaceSet makeBox(const Vec3& size)
{
    OwnedFaceSet f;
    f.creaseAngle = 0;
    const double x = size.x / 2, y = size.y / 2, z = size.z / 2;
    for (int i = 0; i < 8; ++i) addPoint(f, {i & 1 ? x : -x, i & 2 ? y : -y, i & 4 ? z : -z});
    addFace(f, {0, 4, 6, 2});  // -x
    addFace(f, {1, 3, 7, 5});  // +x
    addFace(f, {0, 1, 5, 4});  // -y
    addFace(f, {2, 6, 7, 3});  // +y
    addFace(f, {0, 2, 3, 1});  // -z
    addFace(f, {4, 5, 7, 6});  // +z
    return f;
}

OwnedFaceSet makeSphere(double radius)
{
    OwnedFaceSet f;
    f.creaseAngle = float(M_PI);
    const int stacks = kRoundSegments / 2;
    const int32_t top = addPoint(f, {0, radius, 0});
    std::vector<std::vector<int32_t>> rings;
    for (int s = 1; s < stacks; ++s) {
        const double phi = M_PI * s / stacks;
        rings.push_back(addRing(f, radius * std::sin(phi), radius * std::cos(phi)));
    }
    const int32_t bottom = addPoint(f, {0, -radius, 0});
    const int n = kRoundSegments;
    for (int i = 0; i < n; ++i) {
        const int j = (i + 1) % n;
        addFace(f, {top, rings.front()[size_t(i)], rings.front()[size_t(j)]});
        for (size_t r = 0; r + 1 < rings.size(); ++r)
            addFace(f, {rings[r][size_t(i)], rings[r + 1][size_t(i)], rings[r + 1][size_t(j)], rings[r][size_t(j)]});
        addFace(f, {bottom, rings.back()[size_t(j)], rings.back()[size_t(i)]});
    }
    return f;
}

OwnedFaceSet makeCylinder(double radius, double height, bool side, bool top, bool bottom)
{
    OwnedFaceSet f;
    const std::vector<int32_t> up = addRing(f, radius, height / 2), down = addRing(f, radius, -height / 2);
    const int n = kRoundSegments;
    if (side)
        for (int i = 0; i < n; ++i) {
            const size_t a = size_t(i), b = size_t((i + 1) % n);
            addFace(f, {up[a], down[a], down[b], up[b]});
        }
    if (top) addCap(f, up, true);
    if (bottom) addCap(f, down, false);
    return f;
}

OwnedFaceSet makeCone(double bottomRadius, double height, bool side, bool bottom)
{
    OwnedFaceSet f;
    const std::vector<int32_t> down = addRing(f, bottomRadius, -height / 2);
    const int n = kRoundSegments;
    if (side)
        for (int i = 0; i < n; ++i) {
            // one apex point per segment so the side normals stay smooth around the axis
            const int32_t apex = addPoint(f, {0, height / 2, 0});
            addFace(f, {apex, down[size_t(i)], down[size_t((i + 1) % n)]});
        }
    if (bottom) addCap(f, down, false);
    return f;
}

OwnedFaceSet makeElevationGrid(int xDimension, int zDimension, double xSpacing, double zSpacing,
                               const std::vector<float>& heights)
{
    OwnedFaceSet f;
    if (xDimension < 2 || zDimension < 2) return f;
    for (int j = 0; j < zDimension; ++j)
        for (int i = 0; i < xDimension; ++i) {
            const size_t k = size_t(j) * size_t(xDimension) + size_t(i);
            addPoint(f, {i * xSpacing, k < heights.size() ? heights[k] : 0.0, j * zSpacing});
        }
    for (int j = 0; j + 1 < zDimension; ++j)
        for (int i = 0; i + 1 < xDimension; ++i) {
            const int32_t a = j * xDimension + i;
            addFace(f, {a, a + xDimension, a + xDimension + 1, a + 1});
        }
    return f;
}

namespace {

Vec3 spinePoint(const std::vector<float>& s, size_t i) { return {s[3 * i], s[3 * i + 1], s[3 * i + 2]}; }

struct Frame {
    Vec3 x, y, z;
};

// Spine-aligned cross-section planes (VRML97 6.18).
std::vector<Frame> spineFrames(const std::vector<float>& spine)
{
    const size_t n = spine.size() / 3;
    const bool closed = n > 2 && length(spinePoint(spine, 0) - spinePoint(spine, n - 1)) < 1e-9;
    std::vector<Frame> frames(n);
    for (size_t i = 0; i < n; ++i) {
        const Vec3 p = spinePoint(spine, i);
        const Vec3 prev = i > 0 ? spinePoint(spine, i - 1) : (closed ? spinePoint(spine, n - 2) : p);
        const Vec3 next = i + 1 < n ? spinePoint(spine, i + 1) : (closed ? spinePoint(spine, 1) : p);
        frames[i].y = normalized(next - prev);
        if ((i > 0 && i + 1 < n) || closed) frames[i].z = normalized(cross(next - p, prev - p));
    }
    if (!closed && n > 2) {
        frames[0].z = frames[1].z;
        frames[n - 1].z = frames[n - 2].z;
    }
    // Collinear spine: rotate the standard z axis the way y was rotated.
    for (size_t i = 0; i < n; ++i) {
        if (length(frames[i].z) == 0) {
            const Vec3 yAxis{0, 1, 0};
            const Vec3 axis = cross(yAxis, frames[i].y);
            const double angle = std::acos(std::clamp(dot(yAxis, frames[i].y), -1.0, 1.0));
            frames[i].z = length(axis) > 1e-12 ? Mat4::rotation(axis, angle).transformVector({0, 0, 1})
                                               : Vec3{0, 0, dot(yAxis, frames[i].y) < 0 ? -1.0 : 1.0};
        }
        if (i > 0 && dot(frames[i].z, frames[i - 1].z) < 0) frames[i].z = frames[i].z * -1.0;
        if (length(frames[i].y) == 0) frames[i].y = i > 0 ? frames[i - 1].y : Vec3{0, 1, 0};
        frames[i].x = cross(frames[i].y, frames[i].z);
    }
    return frames;
}

}  // namespace

OwnedFaceSet makeExtrusion(const ExtrusionSpec& spec)
{
    OwnedFaceSet f;
    const size_t sections = spec.crossSection.size() / 2, spines = spec.spine.size() / 3;
    if (sections < 2 || spines < 2) return f;
    const std::vector<Frame> frames = spineFrames(spec.spine);
    for (size_t i = 0; i < spines; ++i) {
        const size_t si = std::min(i, spec.scale.size() / 2 - 1);
        const size_t oi = std::min(i, spec.orientation.size() / 4 - 1);
        const Vec3 sc{spec.scale.size() >= 2 ? spec.scale[2 * si] : 1.0, 1.0,
                      spec.scale.size() >= 2 ? spec.scale[2 * si + 1] : 1.0};
        Mat4 orient;
        if (spec.orientation.size() >= 4)
            orient = Mat4::rotation({spec.orientation[4 * oi], spec.orientation[4 * oi + 1], spec.orientation[4 * oi + 2]},
                                    spec.orientation[4 * oi + 3]);
        const Frame& fr = frames[i];
        for (size_t j = 0; j < sections; ++j) {
            const Vec3 local = orient.transformVector({spec.crossSection[2 * j] * sc.x, 0, spec.crossSection[2 * j + 1] * sc.z});
            addPoint(f, spinePoint(spec.spine, i) + fr.x * local.x + fr.y * local.y + fr.z * local.z);
        }
    }
    const auto at = [&](size_t i, size_t j) { return int32_t(i * sections + j); };
    for (size_t i = 0; i + 1 < spines; ++i)
        for (size_t j = 0; j + 1 < sections; ++j)
            addFace(f, {at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j)});
    const bool closedSection = spec.crossSection[0] == spec.crossSection[2 * sections - 2] &&
                               spec.crossSection[1] == spec.crossSection[2 * sections - 1];
    const size_t capCount = closedSection ? sections - 1 : sections;
    // With the spec's default (clockwise seen from +y) cross-section every face points out.
    if (spec.beginCap) {
        for (size_t j = capCount; j-- > 0;) f.coordIndex.push_back(at(0, j));
        f.coordIndex.push_back(-1);
    }
    if (spec.endCap) {
        for (size_t j = 0; j < capCount; ++j) f.coordIndex.push_back(at(spines - 1, j));
        f.coordIndex.push_back(-1);
    }
    return f;
}

}  // namespace cadlod::vrml
