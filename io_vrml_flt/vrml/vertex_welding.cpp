#include "vrml/vertex_welding.h"

#include <cstring>

namespace cadlod::vrml {
namespace {

uint32_t bitsOf(float f)
{
    if (f == 0.0f) f = 0.0f;  // -0 and +0 are the same point
    uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

uint64_t hashPoint(const Vec3f& p)
{
    uint64_t h = bitsOf(p[0]) * 0x9E3779B97F4A7C15ull;
    h ^= (h >> 29) ^ bitsOf(p[1]) * 0xC2B2AE3D27D4EB4Full;
    h ^= (h >> 31) ^ bitsOf(p[2]) * 0x165667B19E3779F9ull;
    return h ^ (h >> 32);
}

bool samePoint(const Vec3f& a, const Vec3f& b)
{
    return bitsOf(a[0]) == bitsOf(b[0]) && bitsOf(a[1]) == bitsOf(b[1]) && bitsOf(a[2]) == bitsOf(b[2]);
}

}  // namespace

Welding weldCoincidentVertices(const Scene& scene)
{
    Welding w;
    const size_t n = scene.vertexCount();
    w.weldedIndex.reserve(n);
    size_t capacity = 16;
    while (capacity < 2 * n) capacity *= 2;
    constexpr uint32_t kEmpty = UINT32_MAX;
    std::vector<uint32_t> table(capacity, kEmpty);  // welded index per slot
    std::vector<const Vec3f*> representative;
    representative.reserve(n);
    for (const Part& part : scene.parts)
        for (const Vec3f& p : part.positions) {
            size_t slot = hashPoint(p) & (capacity - 1);
            while (table[slot] != kEmpty && !samePoint(*representative[table[slot]], p))
                slot = (slot + 1) & (capacity - 1);
            if (table[slot] == kEmpty) {
                table[slot] = uint32_t(representative.size());
                representative.push_back(&p);
            }
            w.weldedIndex.push_back(table[slot]);
        }
    w.weldedCount = uint32_t(representative.size());
    return w;
}

}  // namespace cadlod::vrml
