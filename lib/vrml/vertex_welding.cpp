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

// Open addressing; each slot keeps 32 hash bits next to the welded index, so a probe
// only reads a candidate's position when the hashes agree (one cache miss per vertex).
Welding weldCoincidentVertices(const Scene& scene)
{
    Welding w;
    const size_t n = scene.vertexCount();
    w.weldedIndex.reserve(n);
    size_t capacity = 16;
    while (capacity < 2 * n) capacity *= 2;
    constexpr uint64_t kEmpty = UINT64_MAX;
    std::vector<uint64_t> table(capacity, kEmpty);  // (hash tag << 32) | welded index
    std::vector<const Vec3f*> representative;
    representative.reserve(n);
    constexpr size_t kPrefetchDistance = 16;  // the table is far bigger than the caches
    for (const Part& part : scene.parts)
        for (size_t i = 0; i < part.positions.size(); ++i) {
            if (i + kPrefetchDistance < part.positions.size())
                __builtin_prefetch(&table[hashPoint(part.positions[i + kPrefetchDistance]) & (capacity - 1)]);
            const Vec3f& p = part.positions[i];
            const uint64_t h = hashPoint(p);
            const uint64_t tag = h >> 32;
            size_t slot = h & (capacity - 1);
            for (;; slot = (slot + 1) & (capacity - 1)) {
                const uint64_t entry = table[slot];
                if (entry == kEmpty) {
                    table[slot] = (tag << 32) | representative.size();
                    w.weldedIndex.push_back(uint32_t(representative.size()));
                    representative.push_back(&p);
                    break;
                }
                const uint32_t id = uint32_t(entry);
                if ((entry >> 32) == tag && samePoint(*representative[id], p)) {
                    w.weldedIndex.push_back(id);
                    break;
                }
            }
        }
    w.weldedCount = uint32_t(representative.size());
    return w;
}

}  // namespace cadlod::vrml
