#include "vrml/triangulate.h"

#include <cmath>

namespace cadlod::vrml {
namespace {

struct P2 {
    double x, y;
};

double cross2(const P2& o, const P2& a, const P2& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

bool insideTriangle(const P2& p, const P2& a, const P2& b, const P2& c)
{
    return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

// Drops the dominant axis of the normal; the 2D polygon is then counter-clockwise.
std::vector<P2> projectToPlane(const std::vector<Vec3>& polygon, const Vec3& normal)
{
    const double ax = std::fabs(normal.x), ay = std::fabs(normal.y), az = std::fabs(normal.z);
    std::vector<P2> out;
    out.reserve(polygon.size());
    for (const Vec3& p : polygon) {
        if (az >= ax && az >= ay) out.push_back(normal.z >= 0 ? P2{p.x, p.y} : P2{p.y, p.x});
        else if (ax >= ay) out.push_back(normal.x >= 0 ? P2{p.y, p.z} : P2{p.z, p.y});
        else out.push_back(normal.y >= 0 ? P2{p.z, p.x} : P2{p.x, p.z});
    }
    return out;
}

bool isEar(const std::vector<P2>& p, const std::vector<uint32_t>& ring, size_t i)
{
    const size_t n = ring.size();
    const P2& a = p[ring[(i + n - 1) % n]];
    const P2& b = p[ring[i]];
    const P2& c = p[ring[(i + 1) % n]];
    if (cross2(a, b, c) <= 0) return false;  // reflex or degenerate corner
    for (size_t k = 0; k < n; ++k) {
        if (k == i || k == (i + 1) % n || k == (i + n - 1) % n) continue;
        const P2& q = p[ring[k]];
        if ((q.x == a.x && q.y == a.y) || (q.x == b.x && q.y == b.y) || (q.x == c.x && q.y == c.y)) continue;
        if (insideTriangle(q, a, b, c)) return false;
    }
    return true;
}

}  // namespace

Vec3 newellNormal(const std::vector<Vec3>& polygon)
{
    Vec3 n;
    const size_t count = polygon.size();
    for (size_t i = 0; i < count; ++i) {
        const Vec3& a = polygon[i];
        const Vec3& b = polygon[(i + 1) % count];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return n;
}

void triangulatePolygon(const std::vector<Vec3>& polygon, std::vector<std::array<uint32_t, 3>>& out)
{
    const size_t n = polygon.size();
    if (n < 3) return;
    if (n == 3) {
        out.push_back({0, 1, 2});
        return;
    }
    const std::vector<P2> p = projectToPlane(polygon, newellNormal(polygon));
    std::vector<uint32_t> ring(n);
    for (size_t i = 0; i < n; ++i) ring[i] = uint32_t(i);
    size_t i = 0, sinceLastEar = 0;
    while (ring.size() > 3) {
        const size_t m = ring.size();
        i %= m;
        if (isEar(p, ring, i) || sinceLastEar >= m) {  // no ear left: clip anyway
            out.push_back({ring[(i + m - 1) % m], ring[i], ring[(i + 1) % m]});
            ring.erase(ring.begin() + long(i));
            sinceLastEar = 0;
        } else {
            ++i;
            ++sinceLastEar;
        }
    }
    out.push_back({ring[0], ring[1], ring[2]});
}

}  // namespace cadlod::vrml
