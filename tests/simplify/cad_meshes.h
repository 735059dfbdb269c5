// CAD-like tessellations for the simplifier's tests and benchmarks, generated the way CAD
// exporters triangulate B-rep faces: surfaces of revolution as long strips between
// profile rings (two triangles per segment, no interior vertices), flat end faces as
// fans from the centre, big flat faces as zig-zag strips between two sides. Everything shares vertices
// within a part and is consistently oriented (outward normals).
#pragma once

#include "mesh/layer_metadata.h"

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/bounding.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace cadlod::test {

// A triangle soup with shared vertices, built part by part, then turned into any vcglib mesh.
struct CadBuilder {
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> part;  // per triangle
    int currentPart = 0;

    int addPoint(double x, double y, double z)
    {
        points.push_back({x, y, z});
        return int(points.size()) - 1;
    }
    void addTriangle(int a, int b, int c)
    {
        if (a == b || b == c || c == a)
            return;
        triangles.push_back({a, b, c});
        part.push_back(currentPart);
    }
    void translate(int firstPoint, double dx, double dy, double dz)
    {
        for (std::size_t i = firstPoint; i < points.size(); ++i) {
            points[i][0] += dx;
            points[i][1] += dy;
            points[i][2] += dz;
        }
    }

    // Into a vcglib mesh; withParts also stores the cadlod_part attribute and part table.
    template <class MeshType>
    void build(MeshType& m, bool withParts = false) const
    {
        m.Clear();
        auto vi = vcg::tri::Allocator<MeshType>::AddVertices(m, points.size());
        for (std::size_t i = 0; i < points.size(); ++i, ++vi)
            vi->P() = typename MeshType::CoordType(points[i][0], points[i][1], points[i][2]);
        auto fi = vcg::tri::Allocator<MeshType>::AddFaces(m, triangles.size());
        for (std::size_t i = 0; i < triangles.size(); ++i, ++fi)
            for (int j = 0; j < 3; ++j)
                fi->V(j) = &m.vert[triangles[i][j]];
        if (withParts) {
            auto handle = cadlod::facePartHandle(m);
            for (std::size_t i = 0; i < triangles.size(); ++i)
                handle[i] = part[i];
            auto table = cadlod::partTableHandle(m);
            const int parts = part.empty() ? 0 : *std::max_element(part.begin(), part.end()) + 1;
            table().resize(parts);
            for (int p = 0; p < parts; ++p)
                table()[p].name = "part" + std::to_string(p);
        }
        vcg::tri::UpdateBounding<MeshType>::Box(m);
    }
};

// The part `make` builds, twice with its parts: an input to measure against and a mesh to
// simplify.
template <class MeshType, class Make>
void buildInputAndCopy(const Make& make, MeshType& input, MeshType& m)
{
    CadBuilder b;
    make(b);
    b.build(input, true);
    b.build(m, true);
}

struct ProfilePoint {
    double z, r;
};

struct RevolveSpec {
    int segments = 64;         // around the axis
    int cylinderRings = 1;     // subdivisions of spans of constant radius (1: long strips)
    // A keyway milled into the step of radius keywayRadius: one plane x = keywayRadius ·
    // cos(keywayHalfAngle) cuts every ring with z in [z0, z1] and r <= keywayRadius (a ring
    // of a larger step at z0 is the shoulder face's rim, which the cutter does not reach).
    double keywayHalfAngle = 0;  // > 0: there is a keyway
    double keywayRadius = 0;
    double keywayZ0 = 0, keywayZ1 = 0;
};

// The band of triangles between two closed rings of as many points, two per segment, facing
// the side from which ring `a` runs counter-clockwise with `c` beyond it.
inline void ringBand(CadBuilder& b, const std::vector<int>& a, const std::vector<int>& c)
{
    const int n = int(a.size());
    for (int j = 0; j < n; ++j) {
        const int k = (j + 1) % n;
        b.addTriangle(a[j], a[k], c[k]);
        b.addTriangle(a[j], c[k], c[j]);
    }
}

// Surface of revolution of a profile (z increasing along the part, r = 0 closes with a
// fan). Returns the index of the first point added.
inline int revolve(CadBuilder& b, const std::vector<ProfilePoint>& profile, const RevolveSpec& spec)
{
    const int first = int(b.points.size());
    const int n = spec.segments;
    auto addRing = [&](double z, double r) {
        std::vector<int> ring(n);
        if (r == 0) {
            const int c = b.addPoint(0, 0, z);
            std::fill(ring.begin(), ring.end(), c);
            return ring;
        }
        for (int j = 0; j < n; ++j) {
            const double t = 2 * M_PI * j / n;
            double x = r * std::cos(t), y = r * std::sin(t);
            if (spec.keywayHalfAngle > 0 && z >= spec.keywayZ0 && z <= spec.keywayZ1 && r <= spec.keywayRadius)
                x = std::min(x, spec.keywayRadius * std::cos(spec.keywayHalfAngle));
            ring[j] = b.addPoint(x, y, z);
        }
        return ring;
    };
    auto band = [&](const std::vector<int>& a, const std::vector<int>& c) { ringBand(b, a, c); };
    std::vector<int> previous = addRing(profile[0].z, profile[0].r);
    for (std::size_t i = 1; i < profile.size(); ++i) {
        const ProfilePoint& p0 = profile[i - 1];
        const ProfilePoint& p1 = profile[i];
        const int steps = (p0.r == p1.r && p0.r > 0) ? std::max(1, spec.cylinderRings) : 1;
        for (int s = 1; s <= steps; ++s) {
            const double t = double(s) / steps;
            std::vector<int> next = addRing(p0.z + (p1.z - p0.z) * t, p0.r + (p1.r - p0.r) * t);
            band(previous, next);
            previous = std::move(next);
        }
    }
    return first;
}

// A stepped shaft with chamfers, shoulders and a flat keyway on the last step: 101 long,
// radius 10..15. centerBore > 0 replaces the end fans with centre-drill annuli.
inline std::vector<ProfilePoint> shaftProfile(double centerBore = 0)
{
    return {{0, centerBore}, {0, 9},   {1, 10},  {40, 10},  {40, 14},  {41, 15},
            {70, 15},        {70, 12}, {100, 12}, {101, 11}, {101, centerBore}};
}

inline RevolveSpec shaftSpec(int segments, int cylinderRings = 1)
{
    RevolveSpec s;
    s.segments = segments;
    s.cylinderRings = cylinderRings;
    s.keywayHalfAngle = 0.5;  // on the r = 12 step, open through the end chamfer
    s.keywayRadius = 12;
    s.keywayZ0 = 70;
    s.keywayZ1 = 101;
    return s;
}

// Triangles a shaft of shaftProfile() gets with these settings.
inline int shaftTriangles(int segments, int cylinderRings, bool fans)
{
    return segments * ((fans ? 2 : 4) + 2 * 5 + 2 * 3 * cylinderRings);
}

// The shaft (centre-drilled ends) as a CAD exporter tessellates it with about `triangles`
// triangles: a finer chord tolerance (segments ~ sqrt(size)) and more rings along the
// cylinders (a maximum edge length) as it grows. The bench sizes.
inline RevolveSpec shaftSpecForTriangles(int triangles)
{
    const double scale = std::sqrt(triangles / 24000.0);
    const int segments = int(std::lround(1200 * scale));
    const int rings = std::max(1, int(std::lround((double(triangles) / segments - 14) / 6)));
    return shaftSpec(segments, rings);
}

// A closed box (sizeX × sizeY × thickness) whose large faces are zig-zag strips between
// `perEdge` points on each long side, and whose sides are strips: the slivers CAD
// exporters make of big planar faces.
inline int stripPlate(CadBuilder& b, double sizeX, double sizeY, double thickness, int perEdge)
{
    const int first = int(b.points.size());
    std::vector<std::array<double, 2>> outline;  // counter-clockwise seen from +z
    for (int i = 0; i <= perEdge; ++i) outline.push_back({sizeX * i / perEdge, 0});
    for (int i = perEdge; i >= 0; --i) outline.push_back({sizeX * i / perEdge, sizeY});
    const int n = int(outline.size());
    std::vector<int> bottom(n), top(n);
    for (int i = 0; i < n; ++i) {
        bottom[i] = b.addPoint(outline[i][0], outline[i][1], 0);
        top[i] = b.addPoint(outline[i][0], outline[i][1], thickness);
    }
    for (int i = 0; i < perEdge; ++i) {
        const int a0 = i, a1 = i + 1, c0 = n - 1 - i, c1 = n - 2 - i;  // y = 0 row, y = sizeY row
        b.addTriangle(top[a0], top[a1], top[c1]);
        b.addTriangle(top[a0], top[c1], top[c0]);
        b.addTriangle(bottom[a0], bottom[c1], bottom[a1]);
        b.addTriangle(bottom[a0], bottom[c0], bottom[c1]);
    }
    for (int i = 0; i < n; ++i) {
        const int k = (i + 1) % n;
        b.addTriangle(bottom[i], bottom[k], top[k]);
        b.addTriangle(bottom[i], top[k], top[i]);
    }
    return first;
}

// A square plate (side × side × thickness) drilled through at its centre: a tunnel, so a
// closed surface of genus 1. Each flat face is a strip between the square outline and the
// hole's rim, `segments` points on each (a multiple of 4), as CAD exporters make them.
inline int drilledPlate(CadBuilder& b, double side, double thickness, double holeRadius, int segments)
{
    const int first = int(b.points.size());
    auto ring = [&](double z, bool square) {
        std::vector<int> r(segments);
        for (int j = 0; j < segments; ++j) {
            const double t = 2 * M_PI * j / segments, c = std::cos(t), s = std::sin(t);
            const double scale = square ? 0.5 * side / std::max(std::abs(c), std::abs(s)) : holeRadius;
            r[j] = b.addPoint(scale * c, scale * s, z);
        }
        return r;
    };
    auto band = [&](const std::vector<int>& a, const std::vector<int>& c) { ringBand(b, a, c); };
    const std::vector<int> outerBottom = ring(0, true), outerTop = ring(thickness, true);
    const std::vector<int> rimBottom = ring(0, false), rimTop = ring(thickness, false);
    band(outerTop, rimTop);        // top face, facing +z
    band(rimBottom, outerBottom);  // bottom face, facing -z
    band(outerBottom, outerTop);   // the sides, facing out
    band(rimTop, rimBottom);       // the hole's wall, facing its axis
    return first;
}

// A closed tube of radius 10 and length 40 (part 0), `segments` around, with a ring
// halfway, and a fin (part 1: an annulus out to radius 20) welded onto that ring, as a
// welded casting or a flange modelled on a body comes out: every edge of the ring has three
// faces, two of the tube and one of the fin.
inline void tubeWithFin(CadBuilder& b, int segments)
{
    RevolveSpec spec;
    spec.segments = segments;
    spec.cylinderRings = 2;
    b.currentPart = 0;
    const int first = revolve(b, {{0, 0}, {0, 10}, {40, 10}, {40, 0}}, spec);
    std::vector<int> ring(segments), outer(segments);
    for (int j = 0; j < segments; ++j) {
        ring[j] = first + 1 + segments + j;  // after the end's centre and the first ring
        const double t = 2 * M_PI * j / segments;
        outer[j] = b.addPoint(20 * std::cos(t), 20 * std::sin(t), 20);
    }
    b.currentPart = 1;
    ringBand(b, ring, outer);
}

// A small multi-part assembly: a shaft, a base plate, two bolts (separate parts).
inline void assembly(CadBuilder& b, int segments)
{
    b.currentPart = 0;
    revolve(b, shaftProfile(), shaftSpec(segments));
    b.currentPart = 1;
    const int plate = stripPlate(b, 120, 60, 8, std::max(8, segments / 4));
    b.translate(plate, -10, -30, -20);
    for (int bolt = 0; bolt < 2; ++bolt) {
        b.currentPart = 2 + bolt;
        RevolveSpec s;
        s.segments = std::max(8, segments / 2);
        const int first = revolve(b, {{0, 0}, {0, 7}, {5, 7}, {5, 4}, {30, 4}, {30.5, 3.5}, {30.5, 0}}, s);
        b.translate(first, 20 + 60 * bolt, 25, 0);
    }
}

// A printed circuit board assembly as KiCad exports it: a thin board (part 0), a grid of
// chips (boxes), electrolytic capacitors and one tall valve-like tube (cylinders of long
// strips), every component a part of its own. Almost every edge is a crease or a part
// border: at 90 % a simplifier must give features up, and must give up the cheap ones.
inline void circuitBoard(CadBuilder& b)
{
    b.currentPart = 0;
    stripPlate(b, 100, 80, 1.6, 20);
    int part = 1;
    for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 6; ++col) {
            b.currentPart = part++;
            const int chip = stripPlate(b, 7, 5, 1.2, 3);
            b.translate(chip, 6 + 15 * col, 6 + 12 * row, 1.6);
        }
    for (int cap = 0; cap < 8; ++cap) {
        b.currentPart = part++;
        RevolveSpec s;
        s.segments = 24;
        const int first = revolve(b, {{0, 0}, {0, 3}, {7.5, 3}, {8, 2.5}, {8, 0}}, s);
        b.translate(first, 8 + 12 * cap, 72, 1.6);
    }
    b.currentPart = part++;
    RevolveSpec tube;
    tube.segments = 48;
    const int first = revolve(b, {{0, 0}, {0, 6}, {25, 6}, {27, 4}, {27, 0}}, tube);
    b.translate(first, 88, 40, 1.6);
}

// A chip's gull-wing leads: thin strips (0.15 x 0.3) bent twice, each a closed part of its
// own, standing out of a body. Where a simplifier cuts across a bend, a face ends up nearer
// the strip's far side than its own: turned away from the surface a viewer sees.
inline void gullWingChip(CadBuilder& b, int leads)
{
    b.currentPart = 0;
    const double pitch = 0.65, body = pitch * leads;
    const int first = stripPlate(b, 3.0, body, 1.4, 4);
    b.translate(first, -3.0, 0, 0.3);
    const double t = 0.15, w = 0.3, r = 0.25;
    // The lead's centre line in (x, z): out of the body, down, out along the board.
    std::vector<std::array<double, 4>> path;  // x, z, tangent x, tangent z
    for (int i = 0; i <= 6; ++i)
        path.push_back({0.4 * i / 6, 1.0, 1, 0});
    for (int i = 1; i <= 8; ++i) {
        const double a = M_PI / 2 * i / 8;
        path.push_back({0.4 + r * std::sin(a), 1.0 - r + r * std::cos(a), std::cos(a), -std::sin(a)});
    }
    for (int i = 1; i <= 3; ++i)
        path.push_back({0.4 + r, 1.0 - r - (1.0 - 2 * r) * i / 3, 0, -1});
    for (int i = 1; i <= 8; ++i) {
        const double a = M_PI / 2 * i / 8;
        path.push_back({0.4 + 2 * r - r * std::cos(a), r - r * std::sin(a), std::sin(a), -std::cos(a)});
    }
    for (int i = 1; i <= 6; ++i)
        path.push_back({0.4 + 2 * r + 0.6 * i / 6, 0, 1, 0});
    for (int lead = 0; lead < leads; ++lead) {
        b.currentPart = lead + 1;
        const double y = pitch * (lead + 0.5) - w / 2;
        const int base = int(b.points.size());
        for (const auto& q : path) {
            const double nx = -q[3], nz = q[2];  // across the strip, in the bend's plane
            for (const auto& c : {std::array<double, 2>{-1, 0}, {1, 0}, {1, 1}, {-1, 1}})
                b.addPoint(q[0] + c[0] * nx * t / 2, y + c[1] * w, q[1] + c[0] * nz * t / 2);
        }
        const int stations = int(path.size());
        auto at = [&](int station, int corner) { return base + 4 * station + corner % 4; };
        for (int i = 0; i + 1 < stations; ++i)
            for (int k = 0; k < 4; ++k) {
                b.addTriangle(at(i, k), at(i + 1, k), at(i + 1, k + 1));
                b.addTriangle(at(i, k), at(i + 1, k + 1), at(i, k + 1));
            }
        b.addTriangle(at(0, 0), at(0, 2), at(0, 1));
        b.addTriangle(at(0, 0), at(0, 3), at(0, 2));
        const int e = stations - 1;
        b.addTriangle(at(e, 0), at(e, 1), at(e, 2));
        b.addTriangle(at(e, 0), at(e, 2), at(e, 3));
    }
}

}  // namespace cadlod::test
