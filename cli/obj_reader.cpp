#include "obj_reader.h"

#include "cli_errors.h"
#include "mesh/layer_metadata.h"
#include "convert/scene_to_mesh.h"

#include <vcg/complex/algorithms/update/normal.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace cadlod::cli {
namespace {

// Names of objects or groups, each with a stable id; faces before the first name belong
// to "default", as in the OBJ specification.
class NameTable {
public:
    NameTable() : current_(idOf("default")) {}
    void select(std::string_view name) { current_ = idOf(name.empty() ? "default" : name); }
    int current() const { return current_; }
    const std::string& name(int id) const { return names_[std::size_t(id)]; }
    std::size_t size() const { return names_.size(); }

private:
    int idOf(std::string_view name)
    {
        auto [it, added] = ids_.emplace(std::string(name), int(names_.size()));
        if (added)
            names_.push_back(it->first);
        return it->second;
    }
    std::vector<std::string> names_;
    std::unordered_map<std::string, int> ids_;
    int current_;
};

using Triangle = std::array<std::uint32_t, 3>;

struct ObjContents {
    std::vector<vcg::Point3f> positions;
    std::vector<vcg::Color4b> colors;
    std::vector<Triangle> triangles;
    std::vector<int> objectOfTriangle;  // ids in `objects`
    std::vector<int> groupOfTriangle;   // ids in `groups`
    NameTable objects, groups;
    bool namesObjects = false;  // an `o` line: objects make the parts, not groups
};

struct Token {
    std::string_view text;
    std::size_t column;  // 1-based
};

// The logical line being parsed, for messages.
struct Where {
    const std::string& source;
    std::size_t line;
};

[[noreturn]] void fail(const Where& at, std::size_t column, const std::string& message)
{
    throw InputError(at.source + ":" + std::to_string(at.line) + ":" + std::to_string(column) + ": " + message);
}

// The grey of a part without a colour of its own (PartIdentity's default).
const vcg::Color4b kDefaultGrey = mesh_io::detail::toColor(PartIdentity{}.color);

void splitTokens(std::string_view line, std::vector<Token>& tokens)
{
    tokens.clear();
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
            ++i;
        const std::size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t')
            ++i;
        if (i > start)
            tokens.push_back({line.substr(start, i - start), start + 1});
    }
}

// from_chars refuses the leading '+' that some exporters write.
std::string_view withoutPlus(std::string_view s)
{
    return s.size() > 1 && s[0] == '+' ? s.substr(1) : s;
}

double parseNumber(const Token& token, const Where& at)
{
    const std::string_view s = withoutPlus(token.text);
    double value = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec == std::errc::result_out_of_range)
        fail(at, token.column, "number out of range '" + std::string(token.text) + "'");
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(value))
        fail(at, token.column, "malformed number '" + std::string(token.text) + "'");
    return value;
}

float parseCoordinate(const Token& token, const Where& at)
{
    const double value = parseNumber(token, at);
    if (std::abs(value) > double(std::numeric_limits<float>::max()))
        fail(at, token.column, "coordinate beyond float range '" + std::string(token.text) + "'");
    return float(value);
}

long long parseInteger(std::string_view s, std::size_t column, const Where& at)
{
    const std::string_view digits = withoutPlus(s);
    long long value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (ec != std::errc() || end != digits.data() + digits.size())
        fail(at, column, "malformed index '" + std::string(s) + "'");
    return value;
}

// Exporters write colours as 0..1 (MeshLab, most) or as bytes; any component above 1 means bytes.
vcg::Color4b parseColor(const std::vector<Token>& tokens, const Where& at)
{
    std::array<double, 4> c{1, 1, 1, 1};
    for (std::size_t k = 4; k < tokens.size(); ++k)
        c[k - 4] = parseNumber(tokens[k], at);
    const bool bytes = std::any_of(c.begin(), c.begin() + 3, [](double x) { return x > 1; });
    if (bytes && tokens.size() < 8)
        c[3] = 255;
    auto byte = [&](double x) { return (unsigned char)std::lround(std::clamp(bytes ? x : x * 255, 0.0, 255.0)); };
    return vcg::Color4b(byte(c[0]), byte(c[1]), byte(c[2]), byte(c[3]));
}

void readVertex(const std::vector<Token>& tokens, const Where& at, ObjContents& obj)
{
    const std::size_t values = tokens.size() - 1;
    if (values != 3 && values != 4 && values != 6 && values != 7)
        fail(at, tokens[0].column, "vertex with " + std::to_string(values) +
                                       " numbers: expected x y z [w] or x y z r g b [a]");
    obj.positions.emplace_back(parseCoordinate(tokens[1], at), parseCoordinate(tokens[2], at),
                               parseCoordinate(tokens[3], at));
    if (values == 4)
        parseNumber(tokens[4], at);  // w: only checked
    obj.colors.push_back(values >= 6 ? parseColor(tokens, at) : kDefaultGrey);
}

// 1-based, or negative counting back from the last vertex read.
std::uint32_t resolveIndex(long long index, std::size_t column, const Where& at, const ObjContents& obj)
{
    const long long count = (long long)obj.positions.size();
    if (index == 0)
        fail(at, column, "vertex index 0 (OBJ counts vertices from 1)");
    const long long resolved = index > 0 ? index - 1 : count + index;
    if (resolved < 0 || resolved >= count)
        fail(at, column, "vertex index " + std::to_string(index) + " out of range (" + std::to_string(count) +
                             " vertices so far)");
    return std::uint32_t(resolved);
}

// v, v/vt, v//vn or v/vt/vn: the vertex index; vt and vn must be integers but are not used.
std::uint32_t parseCorner(const Token& token, const Where& at, const ObjContents& obj)
{
    std::size_t start = 0;
    long long vertex = 0;
    for (int field = 0; start <= token.text.size(); ++field) {
        const std::size_t slash = std::min(token.text.find('/', start), token.text.size());
        const std::string_view part = token.text.substr(start, slash - start);
        if (field > 2)
            fail(at, token.column, "face corner '" + std::string(token.text) + "' has more than v/vt/vn");
        if (field == 0 || !part.empty()) {
            const long long value = parseInteger(part, token.column + start, at);
            if (field == 0)
                vertex = value;
        }
        start = slash + 1;
    }
    return resolveIndex(vertex, token.column, at, obj);
}

// A polygon fanned from its first corner.
void readFace(const std::vector<Token>& tokens, const Where& at, ObjContents& obj)
{
    if (tokens.size() < 4)
        fail(at, tokens[0].column, "face with " + std::to_string(tokens.size() - 1) + " vertices (at least 3)");
    const std::uint32_t first = parseCorner(tokens[1], at, obj);
    std::uint32_t previous = parseCorner(tokens[2], at, obj);
    for (std::size_t k = 3; k < tokens.size(); ++k) {
        const std::uint32_t next = parseCorner(tokens[k], at, obj);
        obj.triangles.push_back({first, previous, next});
        obj.objectOfTriangle.push_back(obj.objects.current());
        obj.groupOfTriangle.push_back(obj.groups.current());
        previous = next;
    }
}

// The rest of the line after the keyword: names may hold spaces.
std::string_view nameAfterKeyword(std::string_view line, const std::vector<Token>& tokens)
{
    if (tokens.size() < 2)
        return {};
    const std::size_t start = tokens[1].column - 1;
    const Token& last = tokens.back();
    return line.substr(start, last.column - 1 + last.text.size() - start);
}

void parseLine(std::string_view line, const Where& at, std::vector<Token>& tokens, ObjContents& obj)
{
    line = line.substr(0, line.find('#'));
    splitTokens(line, tokens);
    if (tokens.empty())
        return;
    const std::string_view keyword = tokens[0].text;
    if (keyword == "v")
        readVertex(tokens, at, obj);
    else if (keyword == "f")
        readFace(tokens, at, obj);
    else if (keyword == "o") {
        obj.objects.select(nameAfterKeyword(line, tokens));
        obj.namesObjects = true;
    } else if (keyword == "g")
        obj.groups.select(nameAfterKeyword(line, tokens));
}

// One logical line: physical lines ending in '\' are joined. `lines` counts the physical
// lines read; messages give the first one of the logical line.
bool readLogicalLine(std::istream& in, std::string& line, std::size_t& lines)
{
    line.clear();
    std::string piece;
    bool any = false;
    while (std::getline(in, piece)) {
        any = true;
        ++lines;
        if (!piece.empty() && piece.back() == '\r')
            piece.pop_back();
        if (piece.empty() || piece.back() != '\\') {
            line += piece;
            return true;
        }
        piece.back() = ' ';
        line += piece;
    }
    return any;
}

void checkVertexCount(const ObjContents& obj, const Where& at)
{
    if (obj.positions.size() > std::numeric_limits<std::uint32_t>::max())
        fail(at, 1, "more vertices than a mesh can hold");
}

ObjContents parseObj(std::istream& in, const std::string& sourceName)
{
    ObjContents obj;
    std::string line;
    std::vector<Token> tokens;
    std::size_t lines = 0;
    for (std::size_t first = 1; readLogicalLine(in, line, lines); first = lines + 1) {
        const Where at{sourceName, first};
        parseLine(line, at, tokens, obj);
        checkVertexCount(obj, at);
    }
    if (in.bad())
        throw InputError(sourceName + ": read error");
    return obj;
}

void buildMesh(const ObjContents& obj, CoreMesh& m)
{
    auto v = vcg::tri::Allocator<CoreMesh>::AddVertices(m, obj.positions.size());
    for (std::size_t i = 0; i < obj.positions.size(); ++i, ++v) {
        v->P() = obj.positions[i];
        v->C() = obj.colors[i];
        v->N() = vcg::Point3f(0, 0, 0);  // PerVertexNormalized leaves unreferenced vertices alone
    }
    auto f = vcg::tri::Allocator<CoreMesh>::AddFaces(m, obj.triangles.size());
    for (const Triangle& t : obj.triangles) {
        for (int k = 0; k < 3; ++k)
            f->V(k) = &m.vert[t[std::size_t(k)]];
        f->C() = kDefaultGrey;
        ++f;
    }
    vcg::tri::UpdateNormal<CoreMesh>::PerVertexNormalized(m);
}

// Parts in the order their first face comes; names owning no face make no part.
std::size_t assignParts(const ObjContents& obj, CoreMesh& m)
{
    const NameTable& names = obj.namesObjects ? obj.objects : obj.groups;
    const std::vector<int>& ownerOf = obj.namesObjects ? obj.objectOfTriangle : obj.groupOfTriangle;
    std::vector<int> partOfOwner(names.size(), -1);
    PartTable table;
    for (int owner : ownerOf)
        if (partOfOwner[std::size_t(owner)] < 0) {
            partOfOwner[std::size_t(owner)] = int(table.size());
            table.push_back(PartIdentity{names.name(owner)});
        }
    if (table.size() < 2)
        return 1;
    auto partOf = facePartHandle(m);
    for (std::size_t i = 0; i < ownerOf.size(); ++i)
        partOf[i] = partOfOwner[std::size_t(ownerOf[i])];
    partTableHandle(m)() = table;
    return table.size();
}

}  // namespace

std::size_t readObj(std::istream& in, const std::string& sourceName, CoreMesh& m)
{
    const ObjContents obj = parseObj(in, sourceName);
    buildMesh(obj, m);
    return assignParts(obj, m);
}

std::size_t readObjFile(const std::string& path, CoreMesh& m)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw InputError(path + ": cannot open file");
    return readObj(in, path, m);
}

}  // namespace cadlod::cli
