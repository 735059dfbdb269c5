#include "vrml/importer.h"

#include "vrml/coordinate_precision.h"

#include "vrml/evaluation.h"
#include "vrml/mapped_file.h"
#include "vrml/parser.h"
#include "vrml/proto.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <unordered_map>
#include <unordered_set>

namespace cadlod::vrml {

Part& EvalContext::part(const Owner& owner, const std::array<float, 4>& color, const std::string& texture)
{
    const bool kept = keepsInstances() && !scopes.empty();
    std::vector<Part>& parts = kept ? scene.assembly.geometries[scopes.back().geometry].parts : scene.parts;
    auto& index = kept ? scopes.back().partIndex : partIndex;
    const auto key = std::make_tuple(owner.id, color[0], color[1], color[2], color[3], texture);
    auto it = index.find(key);
    if (it != index.end()) return parts[it->second];
    index[key] = parts.size();
    Part& p = parts.emplace_back();
    p.name = owner.name;
    p.owner = owner.id;
    p.named = owner.named;
    p.color = color;
    p.texture = texture;
    return p;
}

std::string sharedNodeKey(const Node& node)
{
    char key[32];
    std::snprintf(key, sizeof key, "node %p", static_cast<const void*>(&node));
    return key;
}

Owner EvalContext::shapeOwner(const Owner& owner, const std::string& path)
{
    if (owner.id >= 0) return owner;
    if (!keepsInstances() || scopes.empty() || scopes.back().geometry == 0) return newOwner(path);
    GeometryScope& scope = scopes.back();
    if (scope.shapes.id < 0) scope.shapes = newOwner(scene.assembly.geometries[scope.geometry].name);
    return scope.shapes;
}

void EvalContext::placeInstance(const std::string& key, const std::string& name, const Mat4& world,
                                const std::string& where, const std::function<void()>& evaluate)
{
    std::vector<Geometry>& geometries = scene.assembly.geometries;
    const auto [it, fresh] = geometryOfKey.emplace(key, geometries.size());
    const std::size_t g = it->second;
    if (fresh) {
        geometries.push_back(Geometry{name, {}, {}});
        reading.push_back(true);
        scopes.push_back(GeometryScope{g, {}, {}, {}});
        evaluate();
        scopes.pop_back();
        reading[g] = false;
    } else if (reading[g]) {
        scene.diagnostics.warn("recursive instance", where, name + " contains itself; skipped");
        return;
    }
    const std::vector<std::string>& names = scopes.back().names;
    std::string placed;
    for (const std::string& n : names) placed += (placed.empty() ? "" : "/") + n;
    geometries[scopes.back().geometry].children.push_back({g, world * frameInverse, placed.empty() ? name : placed});
}

void EvalContext::noteExpandedUse(const std::string& key)
{
    if (!expandedKeys.insert(key).second) ++scene.stats.expandedCopies;
}

void EvalContext::enterNamed(const Node& node)
{
    if (keepsInstances() && !scopes.empty() && !node.defName.empty() && node.useCount == 0)
        scopes.back().names.push_back(node.defName);
}

void EvalContext::leaveNamed(const Node& node)
{
    if (keepsInstances() && !scopes.empty() && !node.defName.empty() && node.useCount == 0)
        scopes.back().names.pop_back();
}

bool EvalContext::admit(const std::vector<NodePtr>& nodes, const std::vector<UseSite>& useSites, bool vrml1)
{
    if (stopped()) return false;
    const SceneStats& stats = scene.stats;
    const uint64_t limit = triangleLimit(options.maxTriangles, options.maxTrianglesPerInputByte, stats.bytesRead);
    error = budget.check(nodes, useSites, vrml1, stats.meshTriangles + stats.roundPrimitiveTriangles, limit);
    return error.empty();
}

std::string EvalContext::resolveTexture(const std::vector<std::string>& urls, const std::string& where)
{
    for (const std::string& url : urls) {
        std::string path = url.rfind("file://", 0) == 0 ? url.substr(7) : url;
        if (path.find("://") != std::string::npos) continue;
        const std::filesystem::path p(path);
        const std::filesystem::path full = p.is_absolute() ? p : std::filesystem::path(baseDir) / p;
        std::error_code ec;
        if (std::filesystem::exists(full, ec)) return full.lexically_normal().string();
    }
    if (!urls.empty()) scene.diagnostics.warn("missing texture", where, "texture not found: " + urls.front());
    return {};
}

namespace {

namespace fs = std::filesystem;

struct LoadedFile {
    ParsedFile parsed;
};

double nearestPowerOfTwo(double scale) { return std::exp2(std::round(std::log2(scale))); }

std::string directoryOf(const std::string& path)
{
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

std::string stripUrl(std::string url, std::string* fragment = nullptr)
{
    const size_t hash = url.find('#');
    if (hash != std::string::npos) {
        if (fragment) *fragment = url.substr(hash + 1);
        url.resize(hash);
    }
    if (url.rfind("file://", 0) == 0) url = url.substr(7);
    return url;
}

// KiCad StepUp writes "#kicad StepUp wrl exported" right under the VRML header; KiCad's
// 3D model library is made with it. Only the leading comment lines are looked at.
bool isKicadStepUpExport(std::string_view text)
{
    size_t pos = 0;
    for (int line = 0; line < 8 && pos < text.size(); ++line) {
        const size_t end = std::min(text.find('\n', pos), text.size());
        std::string_view l = text.substr(pos, end - pos);
        if (!l.empty() && l[0] == '#') {
            std::string lower(l);
            std::transform(lower.begin(), lower.end(), lower.begin(),
                           [](unsigned char c) { return char(std::tolower(c)); });
            if (lower.find("kicad stepup") != std::string::npos)
                return true;
        } else if (l.find_first_not_of(" \t\r") != std::string_view::npos) {
            return false;  // the first node: no more header comments
        }
        pos = end + 1;
    }
    return false;
}

class Importer {
public:
    explicit Importer(const ImportOptions& options) : options_(options), ctx_(result_.scene, options)
    {
        ctx_.keepInstances = options.instances == Instances::Keep;
        ctx_.emit.recomputeNormals = options.recomputeNormals;
        ctx_.loadInline = [this](const std::vector<std::string>& urls, const std::string& where, const Mat4& world,
                                 const Owner& owner) { loadInline(urls, where, world, owner); };
    }

    // `bytes` is the file as stored (gzip or not); `release` is called once they are
    // no longer needed (after parsing), to free the memory before evaluation.
    ImportResult run(std::string_view bytes, const std::string& fileName, const std::function<void()>& release)
    {
        SourceText source;
        std::string_view text = bytes;
        if (bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
            static_cast<unsigned char>(bytes[1]) == 0x8b) {
            source = decodeSourceBytes(std::string(bytes), fileName, options_.maxInflatedBytes);
            release();
            if (!source.ok()) {
                result_.error = source.error;
                return std::move(result_);
            }
            text = source.text;
        }
        result_.scene.stats.bytesRead += text.size();
        result_.assumed.kicadHeader = isKicadStepUpExport(text);  // before the text is freed
        const bool kicad = options_.detectKicadUnits && result_.assumed.kicadHeader;
        ParseOptions parse = parseOptions(fileName);
        if (options_.progress)
            parse.progress = [this](size_t done, size_t total) {
                options_.progress(total ? double(done) / double(total) : 1.0);
            };
        ParsedFile parsed = parseVrml(text, fileName, result_.scene.diagnostics, parse);
        release();
        source = SourceText{};
        if (!parsed.error.empty()) {
            result_.error = parsed.error;
            return std::move(result_);
        }
        result_.scene.version = parsed.version == VrmlVersion::V1 ? 1 : 2;
        openFiles_.push_back(canonical(fileName));
        const Mat4 root = rootTransform(kicad);
        const std::string rootName = fs::path(fileName).filename().string();
        if (ctx_.keepsInstances()) evaluateKeepingInstances(parsed, fileName, root, rootName);
        else evaluate(parsed, fileName, root, Owner{}, rootName);
        if (ctx_.stopped()) {
            result_.error = ctx_.error;
            result_.scene.parts.clear();
            result_.scene.assembly = {};
            return std::move(result_);
        }
        dropEmptyParts();
        warnOfCoarseCoordinates(result_.scene, fileName);
        return std::move(result_);
    }

private:
    // Unit scale, KiCad's 0.1-inch units when the header says so, and the up axis.
    Mat4 rootTransform(bool kicad)
    {
        ImportAssumptions& a = result_.assumed;
        a.upAxis = options_.upAxis;
        a.kicadUnits = kicad;
        a.fileScale = a.kicadUnits ? 2.54 : 1.0;
        const double unit = a.kicadUnits && options_.kicadUnitScale > 0 ? options_.kicadUnitScale : options_.unitScale;
        const double wanted = unit * a.fileScale;
        const double s = options_.unitScaling == UnitScaling::PowerOfTwo ? nearestPowerOfTwo(wanted) : wanted;
        a.remainingScale = wanted / s;
        const Mat4 scale = Mat4::scale({s, s, s});
        ctx_.frame = scale;
        ctx_.frameInverse = Mat4::scale({1 / s, 1 / s, 1 / s});
        if (options_.upAxis == UpAxis::YUpToZUp)
            return Mat4::rotation({1, 0, 0}, std::acos(-1.0) / 2) * scale;
        return scale;
    }

    // The shapes no shared node holds go to the root geometry, in world coordinates. If no
    // geometry is placed twice there is nothing to share: the file is read again expanded
    // (parsed files are cached), which is what expanding it gives.
    void evaluateKeepingInstances(const ParsedFile& parsed, const std::string& fileName, const Mat4& root,
                                  const std::string& rootName)
    {
        result_.scene.assembly.geometries.push_back(Geometry{rootName, {}, {}});
        ctx_.reading.push_back(true);
        ctx_.scopes.push_back(GeometryScope{});
        evaluate(parsed, fileName, root, Owner{}, rootName);
        ctx_.scopes.clear();
        if (ctx_.stopped()) return;
        const Assembly& assembly = result_.scene.assembly;
        const uint64_t placements = assembly.placementCount();
        if (placements > options_.maxPlacements) {
            ctx_.error = fileName + ": the assembly places " + std::to_string(placements) +
                         " parts, more than the limit of " + std::to_string(options_.maxPlacements);
            return;
        }
        if (assembly.sharesGeometry()) return;
        result_.scene.assembly = {};
        const size_t bytesRead = result_.scene.stats.bytesRead;
        result_.scene.stats = SceneStats{};
        result_.scene.stats.bytesRead = bytesRead;
        readExpandedAgain(parsed, fileName, root, rootName);
    }

    void readExpandedAgain(const ParsedFile& parsed, const std::string& fileName, const Mat4& root,
                           const std::string& rootName)
    {
        const Diagnostics diagnostics = result_.scene.diagnostics;
        ctx_.keepInstances = false;
        ctx_.partIndex.clear();
        evaluate(parsed, fileName, root, Owner{}, rootName);
        result_.scene.diagnostics = diagnostics;  // the first reading said all there was to say
    }

    // Shapes whose geometry was unsupported or all bad leave empty parts behind.
    void dropEmptyParts()
    {
        auto dropEmpty = [](std::vector<Part>& parts) {
            parts.erase(std::remove_if(parts.begin(), parts.end(), [](const Part& p) { return p.triangles.empty(); }),
                        parts.end());
        };
        dropEmpty(result_.scene.parts);
        for (Geometry& g : result_.scene.assembly.geometries) dropEmpty(g.parts);
    }

    static std::string canonical(const std::string& path)
    {
        std::error_code ec;
        const fs::path p = fs::weakly_canonical(fs::path(path), ec);
        return ec ? path : p.string();
    }

    ParseOptions parseOptions(const std::string& fileName)
    {
        ParseOptions parse;
        parse.maxDepth = options_.maxNesting;
        const std::string dir = directoryOf(fileName);
        parse.externProto = [this, dir](const std::string& url, const std::string& name) {
            return resolveExternProto(dir, url, name);
        };
        return parse;
    }

    void evaluate(const ParsedFile& parsed, const std::string& fileName, const Mat4& world, const Owner& owner,
                  const std::string& path)
    {
        const bool vrml1 = parsed.version == VrmlVersion::V1;
        // Kept instances are read once each: their shapes are admitted one by one as they are read.
        if (!ctx_.keepsInstances() && !ctx_.admit(parsed.roots, parsed.rootUseSites, vrml1)) return;
        const std::string savedDir = ctx_.baseDir;
        ctx_.baseDir = directoryOf(fileName);
        if (vrml1) evaluateVrml10(parsed.roots, world, owner, path, ctx_);
        else evaluateVrml97(parsed.roots, world, owner, path, ctx_);
        ctx_.baseDir = savedDir;
    }

    // Parsed once per file: assemblies reference the same part file many times.
    std::shared_ptr<LoadedFile> loadFile(const std::string& path)
    {
        const std::string key = canonical(path);
        auto it = cache_.find(key);
        if (it != cache_.end()) return it->second;
        auto file = std::make_shared<LoadedFile>();
        SourceText source = readSourceText(path, options_.maxInflatedBytes);
        if (!source.ok()) {
            file->parsed.error = source.error;
        } else {
            result_.scene.stats.bytesRead += source.text.size();
            file->parsed = parseVrml(source.text, path, result_.scene.diagnostics, parseOptions(path));
        }
        cache_[key] = file;
        return file;
    }

    std::string resolve(const std::string& baseDir, const std::string& url) const
    {
        const fs::path p(url);
        return p.is_absolute() ? p.string() : (fs::path(baseDir) / p).string();
    }

    void loadInline(const std::vector<std::string>& urls, const std::string& where, const Mat4& world,
                    const Owner& owner)
    {
        Diagnostics& diag = result_.scene.diagnostics;
        if (int(openFiles_.size()) > options_.maxInlineDepth) {
            diag.warn("inline too deep", where, "Inline nesting deeper than " + std::to_string(options_.maxInlineDepth));
            return;
        }
        for (const std::string& raw : urls) {
            const std::string url = stripUrl(raw);
            if (url.find("://") != std::string::npos) continue;  // remote: not fetched
            const std::string path = resolve(ctx_.baseDir, url);
            std::error_code ec;
            if (!fs::exists(path, ec)) continue;
            const std::string key = canonical(path);
            if (std::find(openFiles_.begin(), openFiles_.end(), key) != openFiles_.end()) {
                diag.warn("recursive inline", where, "Inline " + url + " includes itself; skipped");
                return;
            }
            std::shared_ptr<LoadedFile> file = loadFile(path);
            if (!file->parsed.error.empty()) {
                diag.warn("bad inline", where, file->parsed.error);
                return;
            }
            ++result_.scene.stats.inlinesLoaded;
            const std::string name = fs::path(path).filename().string();
            const auto read = [&, key, path](const Mat4& at, const Owner& as) {
                openFiles_.push_back(key);
                evaluate(file->parsed, path, at, as, name);
                openFiles_.pop_back();
            };
            if (ctx_.keepsInstances())
                ctx_.placeInstance("file " + key, fs::path(path).stem().string(), world, where,
                                   [&] { read(ctx_.frame, Owner{}); });
            else {
                ctx_.noteExpandedUse("file " + key);
                const Owner part = inlineOwner(owner, fs::path(path).stem().string());
                readingOwners_.push_back(part.id);
                read(world, part);
                readingOwners_.pop_back();
            }
            return;
        }
        std::string list;
        for (const std::string& u : urls) list += (list.empty() ? "" : ", ") + u;
        diag.warn("missing inline", where, "Inline file not found: " + (list.empty() ? "(no url)" : list));
    }

    // A file placed by Inline is a part the CAD system named (Creo and SolidWorks place every
    // part so): the part of the DEF'd node right above it, as `DEF U1 Transform { children
    // Inline {...} }` names it, else one named by its file. A DEF'd node that places several
    // files (an assembly's root) names the first; each further one is a part of its own. A file
    // that a part's own file places is of that part.
    Owner inlineOwner(const Owner& owner, const std::string& fileStem)
    {
        if (!owner.named) return ctx_.newOwner(fileStem, true);
        const bool insideItsFile =
            std::find(readingOwners_.begin(), readingOwners_.end(), owner.id) != readingOwners_.end();
        if (insideItsFile || ownersOfInlines_.insert(owner.id).second) return owner;
        return ctx_.newOwner(owner.name + "/" + fileStem, true);
    }

    std::shared_ptr<ProtoDecl> resolveExternProto(const std::string& baseDir, const std::string& rawUrl,
                                                  const std::string& name)
    {
        std::string fragment;
        const std::string url = stripUrl(rawUrl, &fragment);
        if (url.find("://") != std::string::npos || url.empty()) return nullptr;
        const std::string path = resolve(baseDir, url);
        std::error_code ec;
        if (!fs::exists(path, ec) || ++externDepth_ > options_.maxInlineDepth) return nullptr;
        std::shared_ptr<LoadedFile> file = loadFile(path);
        --externDepth_;
        auto it = file->parsed.protos.find(fragment.empty() ? name : fragment);
        return it == file->parsed.protos.end() ? nullptr : it->second;
    }

    const ImportOptions& options_;
    ImportResult result_;
    EvalContext ctx_;
    std::vector<std::string> openFiles_;
    std::unordered_map<std::string, std::shared_ptr<LoadedFile>> cache_;
    int externDepth_ = 0;
    std::unordered_set<int> ownersOfInlines_;  // the DEF'd nodes that placed a file (inlineOwner)
    std::vector<int> readingOwners_;           // the parts whose files are being read
};

}  // namespace

ImportResult importVrmlText(std::string text, const std::string& fileName, const ImportOptions& options)
{
    return Importer(options).run(text, fileName, [&text] { std::string().swap(text); });
}

ImportResult importVrmlFile(const std::string& path, const ImportOptions& options)
{
    MappedFile file;
    std::string error;
    if (!file.open(path, error)) {
        ImportResult r;
        r.error = error;
        return r;
    }
    return Importer(options).run(file.bytes(), path, [&file] { file.release(); });
}

std::string ImportAssumptions::describe(double unitScale) const
{
    char text[400];
    std::snprintf(text, sizeof text, "%s; %s",
                  upAxis == UpAxis::YUpToZUp ? "up axis: +Y in the file, rotated to +Z (VRML convention)"
                                             : "up axis: kept as in the file (+Z for CAD exports)",
                  kicadUnits    ? "units: KiCad StepUp header found, file in 0.1 inch, scaled by 2.54 to mm"
                  : kicadHeader ? "units: as in the file (KiCad StepUp header found, its 0.1 inch not applied)"
                                : "units: as in the file");
    std::string out = text;
    if (unitScale != 1.0) {
        std::snprintf(text, sizeof text, ", then unit scale %g", unitScale);
        out += text;
    }
    return out;
}

}  // namespace cadlod::vrml
