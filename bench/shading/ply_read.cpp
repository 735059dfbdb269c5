#include "ply_read.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace cadlod::shading {

namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64, Bad };

Type typeOf(const std::string& s)
{
    if (s == "char" || s == "int8") return Type::Int8;
    if (s == "uchar" || s == "uint8") return Type::UInt8;
    if (s == "short" || s == "int16") return Type::Int16;
    if (s == "ushort" || s == "uint16") return Type::UInt16;
    if (s == "int" || s == "int32") return Type::Int32;
    if (s == "uint" || s == "uint32") return Type::UInt32;
    if (s == "float" || s == "float32") return Type::Float32;
    if (s == "double" || s == "float64") return Type::Float64;
    return Type::Bad;
}

int sizeOf(Type t)
{
    switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
    default: return 0;
    }
}

struct Property {
    std::string name;
    Type type = Type::Bad;
    bool list = false;
    Type countType = Type::Bad;
};

struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> props;
};

template <class T>
double load(const char* p)
{
    T v;
    std::memcpy(&v, p, sizeof v);
    return double(v);
}

double readBinary(std::istream& in, Type t, bool& ok)
{
    char b[8];
    const int n = sizeOf(t);
    if (!in.read(b, n)) {
        ok = false;
        return 0;
    }
    switch (t) {
    case Type::Int8: return load<std::int8_t>(b);
    case Type::UInt8: return load<std::uint8_t>(b);
    case Type::Int16: return load<std::int16_t>(b);
    case Type::UInt16: return load<std::uint16_t>(b);
    case Type::Int32: return load<std::int32_t>(b);
    case Type::UInt32: return load<std::uint32_t>(b);
    case Type::Float32: return load<float>(b);
    case Type::Float64: return load<double>(b);
    default: ok = false; return 0;
    }
}

}  // namespace

bool readPly(const std::string& path, IndexedMesh& mesh, std::string& error, std::vector<int>* faceParts)
{
    mesh = {};
    if (faceParts)
        faceParts->clear();
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = "cannot open " + path;
        return false;
    }
    std::string line;
    std::getline(in, line);
    if (line.rfind("ply", 0) != 0) {
        error = "not a PLY file";
        return false;
    }
    bool ascii = false;
    std::vector<Element> elements;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        std::istringstream words(line);
        std::string word;
        words >> word;
        if (word == "format") {
            std::string format;
            words >> format;
            if (format == "ascii")
                ascii = true;
            else if (format != "binary_little_endian") {
                error = "unsupported PLY format " + format;
                return false;
            }
        } else if (word == "element") {
            Element e;
            words >> e.name >> e.count;
            elements.push_back(e);
        } else if (word == "property" && !elements.empty()) {
            Property p;
            std::string type;
            words >> type;
            if (type == "list") {
                std::string countType, itemType;
                words >> countType >> itemType;
                p.list = true;
                p.countType = typeOf(countType);
                p.type = typeOf(itemType);
            } else {
                p.type = typeOf(type);
            }
            words >> p.name;
            if (p.type == Type::Bad || (p.list && p.countType == Type::Bad)) {
                error = "unsupported property type in: " + line;
                return false;
            }
            elements.back().props.push_back(p);
        } else if (word == "end_header") {
            break;
        }
    }
    bool ok = true;
    std::vector<double> values;
    for (const Element& e : elements) {
        const bool isVertex = e.name == "vertex", isFace = e.name == "face";
        int xyz[3] = {-1, -1, -1};
        int indexList = -1, partProp = -1;
        for (std::size_t k = 0; k < e.props.size(); ++k) {
            const std::string& n = e.props[k].name;
            if (isVertex && !e.props[k].list && (n == "x" || n == "y" || n == "z"))
                xyz[n[0] - 'x'] = int(k);
            if (isFace && e.props[k].list && (n == "vertex_indices" || n == "vertex_index"))
                indexList = int(k);
            if (isFace && !e.props[k].list && n == "part")
                partProp = int(k);
        }
        if (isVertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0)) {
            error = "vertex element without x y z";
            return false;
        }
        if (isVertex)
            mesh.xyz.reserve(3 * e.count);
        std::vector<std::uint32_t> polygon;
        for (std::size_t i = 0; i < e.count && ok; ++i) {
            std::istringstream asciiLine;
            if (ascii) {
                if (!std::getline(in, line)) {
                    ok = false;
                    break;
                }
                asciiLine.str(line);
            }
            auto scalar = [&](Type t) {
                if (!ascii)
                    return readBinary(in, t, ok);
                double v = 0;
                if (!(asciiLine >> v))
                    ok = false;
                return v;
            };
            double pos[3] = {0, 0, 0};
            double part = 0;
            const std::size_t trianglesBefore = mesh.tri.size() / 3;
            for (std::size_t k = 0; k < e.props.size() && ok; ++k) {
                const Property& p = e.props[k];
                if (!p.list) {
                    const double v = scalar(p.type);
                    if (int(k) == partProp)
                        part = v;
                    for (int a = 0; a < 3; ++a)
                        if (int(k) == xyz[a])
                            pos[a] = v;
                    continue;
                }
                const double count = scalar(p.countType);
                if (count < 0 || count > 1e6) {
                    ok = false;
                    break;
                }
                polygon.clear();
                for (int c = 0; c < int(count) && ok; ++c)
                    polygon.push_back(std::uint32_t(scalar(p.type)));
                if (int(k) == indexList)
                    for (std::size_t c = 2; c < polygon.size(); ++c)
                        mesh.tri.insert(mesh.tri.end(), {polygon[0], polygon[c - 1], polygon[c]});
            }
            if (isVertex)
                mesh.xyz.insert(mesh.xyz.end(), pos, pos + 3);
            if (isFace && faceParts) {
                faceParts->resize(mesh.tri.size() / 3, 0);
                std::fill(faceParts->begin() + std::ptrdiff_t(trianglesBefore), faceParts->end(), int(part));
            }
        }
        if (!ok) {
            error = "truncated or bad " + e.name + " data";
            return false;
        }
    }
    const std::size_t nv = mesh.xyz.size() / 3;
    for (std::uint32_t v : mesh.tri)
        if (v >= nv) {
            error = "face index out of range";
            return false;
        }
    return true;
}

}  // namespace cadlod::shading
