#include "vrml/assembly.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <unordered_map>
#include <unordered_set>

namespace cadlod::vrml {
namespace {

constexpr std::uint64_t kSaturated = std::numeric_limits<std::uint64_t>::max();

std::uint64_t saturatingAdd(std::uint64_t a, std::uint64_t b) { return a > kSaturated - b ? kSaturated : a + b; }

std::string joined(const std::string& outer, const std::string& inner)
{
    if (outer.empty()) return inner;
    if (inner.empty()) return outer;
    return outer + "/" + inner;
}

// Placements per geometry, children included, counted once per geometry.
std::vector<std::uint64_t> placementsPerGeometry(const Assembly& a)
{
    std::vector<std::uint64_t> count(a.geometries.size(), 0);
    std::vector<bool> done(a.geometries.size(), false);
    std::function<std::uint64_t(std::size_t)> visit = [&](std::size_t g) -> std::uint64_t {
        if (done[g]) return count[g];
        done[g] = true;  // geometries form no cycle: the importer refuses them
        std::uint64_t n = a.geometries[g].parts.empty() ? 0 : 1;
        for (const ChildPlacement& c : a.geometries[g].children) n = saturatingAdd(n, visit(c.geometry));
        return count[g] = n;
    };
    for (std::size_t g = 0; g < a.geometries.size(); ++g) visit(g);
    return count;
}

void makePathsUnique(std::vector<Placement>& placements)
{
    std::unordered_map<std::string, int> seen;
    for (const Placement& p : placements) ++seen[p.path];
    std::unordered_map<std::string, int> next;
    for (Placement& p : placements) {
        if (seen[p.path] < 2) continue;
        const int k = ++next[p.path];
        if (k > 1) p.path += "[" + std::to_string(k) + "]";
    }
}

}  // namespace

std::size_t Geometry::triangleCount() const
{
    std::size_t n = 0;
    for (const Part& p : parts) n += p.triangleCount();
    return n;
}

double Placement::largestScale() const
{
    double largest = 0;
    for (const Vec3& axis : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}})
        largest = std::max(largest, length(matrix.transformVector(axis)));
    return largest;
}

std::uint64_t Assembly::placementCount() const { return empty() ? 0 : placementsPerGeometry(*this)[0]; }

bool Assembly::sharesGeometry() const
{
    if (empty()) return false;
    // Paths from the root to each geometry, propagated parents first.
    std::vector<std::size_t> order;
    std::vector<bool> visited(geometries.size(), false);
    std::function<void(std::size_t)> postOrder = [&](std::size_t g) {
        visited[g] = true;
        for (const ChildPlacement& c : geometries[g].children)
            if (!visited[c.geometry]) postOrder(c.geometry);
        order.push_back(g);
    };
    postOrder(0);
    std::vector<std::uint64_t> references(geometries.size(), 0);
    references[0] = 1;
    for (auto g = order.rbegin(); g != order.rend(); ++g)
        for (const ChildPlacement& c : geometries[*g].children)
            references[c.geometry] = saturatingAdd(references[c.geometry], references[*g]);
    for (std::size_t g = 0; g < geometries.size(); ++g)
        if (!geometries[g].parts.empty() && references[g] > 1) return true;
    return false;
}

Assembly partsPlacedOnce(std::vector<Part>&& parts)
{
    Assembly assembly;
    assembly.geometries.push_back(Geometry{});
    std::unordered_map<int, std::size_t> byOwner;
    for (Part& part : parts) {
        if (!part.named) {
            assembly.geometries.front().parts.push_back(std::move(part));
            continue;
        }
        const auto [at, added] = byOwner.emplace(part.owner, assembly.geometries.size());
        if (added) {
            assembly.geometries.push_back(Geometry{part.name, {}, {}});
            assembly.geometries.front().children.push_back({at->second, Mat4::identity(), part.name});
        }
        assembly.geometries[at->second].parts.push_back(std::move(part));
    }
    parts.clear();
    return assembly;
}

std::size_t namedParts(const std::vector<Part>& parts)
{
    std::unordered_set<int> owners;
    for (const Part& part : parts)
        if (part.named) owners.insert(part.owner);
    return owners.size();
}

std::vector<Placement> flattenPlacements(const Assembly& assembly, const std::string& rootName)
{
    std::vector<Placement> out;
    if (assembly.empty()) return out;
    std::function<void(std::size_t, const Mat4&, const std::string&)> place = [&](std::size_t g, const Mat4& matrix,
                                                                                 const std::string& path) {
        const Geometry& geometry = assembly.geometries[g];
        if (!geometry.parts.empty()) out.push_back({path.empty() ? geometry.name : path, matrix, g});
        for (const ChildPlacement& c : geometry.children) place(c.geometry, matrix * c.relative, joined(path, c.name));
    };
    place(0, Mat4::identity(), "");
    for (Placement& p : out)
        if (p.path.empty()) p.path = rootName;
    makePathsUnique(out);
    return out;
}

}  // namespace cadlod::vrml
