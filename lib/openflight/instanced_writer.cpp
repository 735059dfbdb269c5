#include "openflight/instanced_writer.h"

#include "mesh/float_spacing.h"
#include "openflight/level_writer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <utility>

namespace cadlod::flt {
namespace {

std::size_t finestTriangles(const PartDefinition& d)
{
    return d.levels.empty() ? 0 : d.levels.front().triangleCount();
}

// A part definition or a proxy shape as written: its index, and whether it is seen in a
// mirror (its faces then turned back).
using WrittenForm = std::pair<std::size_t, bool>;

class InstancedWriter {
public:
    InstancedWriter(const InstancedModel& model, const WriteOptions& options, ByteWriter& w, InstancedWriteStats& stats)
        : model_(model), w_(w), stats_(stats),
          levels_(options, w, stats, model.distinctTriangles() + model.proxyTriangles())
    {
        for (const PartPlacement& p : model.placements)
            ++uses_[{p.definition, p.mirrored()}];
        for (const PlacementCluster& c : model.clusters)
            for (std::size_t shape : c.shapes)
                ++shapeUses_[{shape, c.mirrored()}];
    }

    bool write(std::string& error)
    {
        writeDatabaseHead(w_, model_.name, model_.units);
        openRootGroup(w_, model_.name, model_.origin);
        const bool written = model_.clusters.empty() ? writePlacements(all(model_.placements.size()), error)
                                                     : writeCluster(model_.clusters.front(), error);
        if (!written)
            return false;
        closeRootGroup(w_);
        return true;
    }

private:
    static std::vector<std::size_t> all(std::size_t n)
    {
        std::vector<std::size_t> v(n);
        for (std::size_t i = 0; i < n; ++i)
            v[i] = i;
        return v;
    }

    bool writePlacements(const std::vector<std::size_t>& placements, std::string& error)
    {
        for (std::size_t p : placements)
            if (!writePlacement(model_.placements[p], error))
                return false;
        return true;
    }

    bool writeCluster(const PlacementCluster& c, std::string& error)
    {
        writeGroup(w_, c.name);
        writeLongIdIfNeeded(w_, c.name);
        writePush(w_);
        const bool proxied = !c.proxies.empty();
        if (proxied) {
            const std::string near = c.name + " near";
            writeLod(w_, near, c.nearRange(), 0.0, c.center);
            writeLongIdIfNeeded(w_, near);
            writePush(w_);
            ++stats_.lodNodes;
        }
        for (std::size_t child : c.clusters)
            if (!writeCluster(model_.clusters[child], error))
                return false;
        if (!writePlacements(c.placements, error))
            return false;
        if (proxied) {
            writePop(w_);
            writeProxies(c);
        }
        writePop(w_);
        ++stats_.clusters;
        return true;
    }

    // Each proxy's LOD record, holding its shape: written there when no other cluster draws
    // it, else referenced (the Instance Definition written before its first reference). A
    // copy seen in a mirror draws the shape's mirrored form: its faces turned back.
    void writeProxies(const PlacementCluster& c)
    {
        const bool moved = !isIdentity(c.move);
        for (std::size_t i = 0; i < c.proxies.size(); ++i) {
            const WrittenForm shape{c.shapes[i], c.mirrored()};
            const int number = shapeUses_[shape] > 1 ? definedOnce(shapeNumbers_, shape, [&] { writeShape(shape); }) : 0;
            const Level& range = c.proxies[i];
            writeLod(w_, range.name, range.switchIn, range.switchOut, range.center);
            writeLongIdIfNeeded(w_, range.name);
            writePush(w_);
            ++stats_.lodNodes;
            if (moved) {
                const std::string name = range.name + " moved";
                writeGroup(w_, name);
                writeLongIdIfNeeded(w_, name);
                writeMatrix(w_, c.move);
                writePush(w_);
            }
            if (number) {
                writeInstanceReference(w_, number);
                ++stats_.instanceReferences;
            } else {
                writeShape(shape);
            }
            if (moved)
                writePop(w_);
            writePop(w_);
        }
        stats_.proxyLevels += c.proxies.size();
    }

    void writeShape(const WrittenForm& shape) { levels_.writeGeometry(model_.proxyShapes[shape.first], shape.second); }

    // The instance number of `form` in `numbers` (a part's or a proxy shape's), its Instance
    // Definition, holding what `contents` writes, written before its first reference; 0 when
    // the 16-bit instance numbers are all taken.
    int definedOnce(std::map<WrittenForm, int>& numbers, const WrittenForm& form, const std::function<void()>& contents)
    {
        const auto known = numbers.find(form);
        if (known != numbers.end())
            return known->second;
        const int number = int(numbers_.size() + shapeNumbers_.size()) + 1;
        if (number > kMaxInstanceNumber)
            return 0;
        numbers[form] = number;
        writeInstanceDefinition(w_, number);
        writePush(w_);
        contents();
        writePop(w_);
        ++stats_.instanceDefinitions;
        return number;
    }

    bool writePlacement(const PartPlacement& p, std::string& error)
    {
        const WrittenForm form{p.definition, p.mirrored()};
        const bool shared = uses_[form] > 1;
        const int number = shared ? definedOnce(numbers_, form, [&] { writeLevelsOf(form); }) : 0;
        if (shared && !number) {
            error = "more than " + std::to_string(kMaxInstanceNumber) + " shared parts: instance numbers are 16-bit";
            return false;
        }
        writeGroup(w_, p.name);
        writeLongIdIfNeeded(w_, p.name);
        writeMatrix(w_, p.matrix);
        writePush(w_);
        if (shared) {
            writeInstanceReference(w_, number);
            ++stats_.instanceReferences;
        } else {
            writeLevelsOf(form);
        }
        writePop(w_);
        ++stats_.placements;
        return true;
    }

    // A chunked part: its chunks under a LOD record drawn nearer than its first simplified
    // level, that level and the coarser ones beside it.
    void writeLevelsOf(const WrittenForm& form)
    {
        const PartDefinition& d = model_.definitions[form.first];
        if (d.chunks.empty()) {
            levels_.writeLevels(d.levels, writesLodRecords(d.levels), form.second);
            return;
        }
        writeChunks(d.name, d.name + " chunk ", d.chunks, d.chunksDrawnTo(), d.levels.front().center, form.second);
        levels_.writeLevels({d.levels.begin() + 1, d.levels.end()}, true, form.second, 1);
    }

    // `chunks` under a LOD record drawn nearer than `drawnTo` to `centre`, each in a Group of
    // its name (else `prefix` and its number), its own children nested the same way beside
    // its levels.
    void writeChunks(const std::string& owner, const std::string& prefix, const std::vector<PartChunk>& chunks,
                     double drawnTo, const Vec3d& centre, bool reversed)
    {
        const std::string near = owner + " chunks";
        writeLod(w_, near, drawnTo, 0.0, centre);
        writeLongIdIfNeeded(w_, near);
        writePush(w_);
        ++stats_.lodNodes;
        for (std::size_t c = 0; c < chunks.size(); ++c) {
            const PartChunk& chunk = chunks[c];
            const std::string name = chunk.name.empty() ? prefix + std::to_string(c + 1) : chunk.name;
            writeGroup(w_, name);
            writeLongIdIfNeeded(w_, name);
            writePush(w_);
            if (!chunk.children.empty())
                writeChunks(name, name + ".", chunk.children, chunk.childrenDrawnTo(), chunk.levels.front().center,
                            reversed);
            levels_.writeLevels(chunk.levels, true, reversed);
            writePop(w_);
        }
        writePop(w_);
    }

    const InstancedModel& model_;
    ByteWriter& w_;
    InstancedWriteStats& stats_;
    LevelWriter levels_;
    std::map<WrittenForm, int> uses_;
    std::map<WrittenForm, int> numbers_;
    std::map<WrittenForm, int> shapeUses_;     // per proxy shape and mirror, the clusters that draw it
    std::map<WrittenForm, int> shapeNumbers_;  // the proxy shapes defined, their instance numbers
};

// A tree below clusters[0] that holds every placement once, its proxies' ranges usable.
bool validateClusters(const InstancedModel& model, std::string& error)
{
    if (model.clusters.empty())
        return true;
    std::vector<int> placed(model.placements.size(), 0);
    for (std::size_t c = 0; c < model.clusters.size(); ++c) {
        const PlacementCluster& cluster = model.clusters[c];
        for (std::size_t child : cluster.clusters)
            if (child <= c || child >= model.clusters.size()) {
                error = "cluster " + cluster.name + " holds cluster " + std::to_string(child) + ", not one below it";
                return false;
            }
        for (std::size_t p : cluster.placements)
            if (p >= placed.size() || placed[p]++ > 0) {
                error = "cluster " + cluster.name + " holds placement " + std::to_string(p) +
                        ", unknown or already held";
                return false;
            }
        if (cluster.shapes.size() != cluster.proxies.size()) {
            error = "cluster " + cluster.name + " has " + std::to_string(cluster.proxies.size()) + " proxies and " +
                    std::to_string(cluster.shapes.size()) + " shapes";
            return false;
        }
        for (std::size_t shape : cluster.shapes)
            if (shape >= model.proxyShapes.size()) {
                error = "cluster " + cluster.name + " draws proxy shape " + std::to_string(shape) + " of " +
                        std::to_string(model.proxyShapes.size());
                return false;
            }
    }
    if (std::find(placed.begin(), placed.end(), 0) != placed.end()) {
        error = "a placement is in no cluster";
        return false;
    }
    return true;
}

// Every chunk with levels, those of one with children drawn from some distance on.
bool validateChunks(const std::vector<PartChunk>& chunks, std::string& error)
{
    for (const PartChunk& chunk : chunks) {
        if (!validateLevels(chunk.levels, error) || !validateChunks(chunk.children, error))
            return false;
        if (!chunk.children.empty() && !(chunk.childrenDrawnTo() > 0)) {
            error = "a chunk's children are never drawn";
            return false;
        }
    }
    return true;
}

bool validate(const InstancedModel& model, const WriteOptions& options, std::string& error)
{
    if (options.geometry != GeometryRecords::Meshes) {
        error = "an instanced model is written with Mesh records only";
        return false;
    }
    for (const PartDefinition& d : model.definitions) {
        bool valid = validateLevels(d.levels, error);
        if (valid && !d.chunks.empty() && d.levels.size() < 2) {
            error = "it is in chunks and has one level, drawn by none of them";
            valid = false;
        }
        valid = valid && validateChunks(d.chunks, error);
        if (!valid) {
            error = "part " + d.name + ": " + error;
            return false;
        }
    }
    if (!validateClusters(model, error))
        return false;
    if (!model.proxyShapes.empty() && !validateLevels(model.proxyShapes, error)) {
        error = "proxy shapes: " + error;
        return false;
    }
    for (const PartPlacement& p : model.placements)
        if (p.definition >= model.definitions.size()) {
            error = "placement " + p.name + " refers to part " + std::to_string(p.definition) + " of " +
                    std::to_string(model.definitions.size());
            return false;
        }
    return true;
}

}  // namespace

bool PartPlacement::mirrored() const { return mirrors(matrix); }

std::size_t InstancedModel::distinctTriangles() const
{
    std::size_t n = 0;
    for (const PartDefinition& d : definitions)
        for (const Level& l : d.levels)
            n += l.triangleCount();
    return n;
}

std::size_t InstancedModel::placedTriangles() const
{
    std::size_t n = 0;
    for (const PartPlacement& p : placements)
        n += finestTriangles(definitions.at(p.definition));
    return n;
}

PlacementPrecision placementPrecision(const InstancedModel& model)
{
    PlacementPrecision out;
    std::vector<double> reach;  // per definition, how far its finest level reaches from its centre
    for (const PartDefinition& d : model.definitions)
        reach.push_back(d.levels.empty() ? 0.0 : d.levels.front().reachFrom(d.levels.front().center));
    Vec3d lo{0, 0, 0}, hi{0, 0, 0};
    double& farthest = out.farthest;
    for (std::size_t i = 0; i < model.placements.size(); ++i) {
        const PartPlacement& p = model.placements[i];
        const PartDefinition& d = model.definitions.at(p.definition);
        const Vec3d centre = transformed(p.matrix, d.levels.empty() ? Vec3d{0, 0, 0} : d.levels.front().center);
        const double placedReach = largestScale(p.matrix) * reach[p.definition];
        for (int k = 0; k < 3; ++k) {
            lo[k] = i == 0 ? centre[k] - placedReach : std::min(lo[k], centre[k] - placedReach);
            hi[k] = i == 0 ? centre[k] + placedReach : std::max(hi[k], centre[k] + placedReach);
            farthest = std::max(farthest, std::abs(centre[k]));
        }
    }
    out.spacing = floatSpacing(farthest);
    for (int k = 0; k < 3; ++k)
        out.extent = std::max(out.extent, hi[k] - lo[k]);
    return out;
}

std::size_t InstancedModel::proxyTriangles() const
{
    std::size_t n = 0;
    for (const Level& l : proxyShapes)
        n += l.triangleCount();
    return n;
}

bool writeInstancedOpenFlight(const InstancedModel& model, const WriteOptions& options, std::vector<std::uint8_t>& out,
                              std::string& error, InstancedWriteStats* stats)
{
    if (!validate(model, options, error))
        return false;
    return writeDatabase(out, stats, [&](ByteWriter& w, InstancedWriteStats& s) {
        return InstancedWriter(model, options, w, s).write(error);
    });
}

bool writeInstancedOpenFlightFile(const std::string& path, const InstancedModel& model, const WriteOptions& options,
                                  std::string& error, InstancedWriteStats* stats)
{
    return writeDatabaseFile(
        path,
        [&](std::vector<std::uint8_t>& bytes, std::string& e) {
            return writeInstancedOpenFlight(model, options, bytes, e, stats);
        },
        error);
}

}  // namespace cadlod::flt
