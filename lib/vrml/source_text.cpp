#include "vrml/source_text.h"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <sstream>

namespace cadlod::vrml {
namespace {

bool hasGzipMagic(const std::string& bytes)
{
    return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
           static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string overTheBound(const std::string& name, size_t compressedBytes, size_t absoluteCap)
{
    const size_t bound = inflatedSizeBound(compressedBytes, absoluteCap);
    if (bound == absoluteCap)
        return name + ": gzip data inflates beyond " + std::to_string(bound >> 20) + " MB; refusing (gzip bomb?)";
    return name + ": gzip data inflates beyond " + std::to_string(bound >> 20) + " MB from " +
           std::to_string(compressedBytes) + " compressed bytes (at most " + std::to_string(kMaxInflationRatio) +
           " times the compressed size, or " + std::to_string(kInflationFloorBytes >> 20) +
           " MB); refusing (gzip bomb?)";
}

std::string inflateGzip(const std::string& in, const std::string& name, size_t absoluteCap, std::string& out)
{
    const size_t maxBytes = inflatedSizeBound(in.size(), absoluteCap);
    z_stream zs{};
    if (inflateInit2(&zs, 15 + 32) != Z_OK)  // 32: accept gzip and zlib headers
        return name + ": cannot initialise zlib";
    out.clear();
    out.reserve(std::min(maxBytes, in.size() * 4));
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
    zs.avail_in = static_cast<uInt>(std::min<size_t>(in.size(), UINT32_MAX));
    size_t inLeft = in.size() - zs.avail_in;
    char buffer[1 << 16];
    int rc = Z_OK;
    while (rc != Z_STREAM_END) {
        zs.next_out = reinterpret_cast<Bytef*>(buffer);
        zs.avail_out = sizeof buffer;
        rc = inflate(&zs, Z_NO_FLUSH);
        if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR) {
            std::ostringstream msg;
            msg << name << ": corrupt gzip data at compressed offset " << zs.total_in << " ("
                << (zs.msg ? zs.msg : "inflate error") << ")";
            inflateEnd(&zs);
            return msg.str();
        }
        const size_t produced = sizeof buffer - zs.avail_out;
        if (out.size() + produced > maxBytes) {
            inflateEnd(&zs);
            return overTheBound(name, in.size(), absoluteCap);
        }
        out.append(buffer, produced);
        if (zs.avail_in == 0 && inLeft > 0) {
            const size_t chunk = std::min<size_t>(inLeft, UINT32_MAX);
            zs.avail_in = static_cast<uInt>(chunk);
            inLeft -= chunk;
        }
        if (rc == Z_BUF_ERROR && zs.avail_in == 0 && produced == 0) {
            inflateEnd(&zs);
            return name + ": truncated gzip file (stream ends after " + std::to_string(out.size()) +
                   " inflated bytes)";
        }
    }
    inflateEnd(&zs);
    return {};
}

}  // namespace

size_t inflatedSizeBound(size_t compressedBytes, size_t absoluteCap)
{
    const size_t relative = compressedBytes > SIZE_MAX / kMaxInflationRatio ? SIZE_MAX
                                                                            : compressedBytes * kMaxInflationRatio;
    return std::min(absoluteCap, std::max(kInflationFloorBytes, relative));
}

SourceText decodeSourceBytes(std::string bytes, const std::string& name, size_t maxInflatedBytes)
{
    SourceText result;
    if (!hasGzipMagic(bytes)) {
        result.text = std::move(bytes);
        return result;
    }
    result.wasGzip = true;
    result.error = inflateGzip(bytes, name, maxInflatedBytes, result.text);
    return result;
}

bool readFileBytes(const std::string& path, std::string& bytes, std::string& error)
{
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error = path + ": cannot open file";
        return false;
    }
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    in.seekg(0, std::ios::beg);
    bytes.assign(size > 0 ? size_t(size) : 0, '\0');
    if (size > 0 && !in.read(bytes.data(), size)) {
        error = path + ": read error";
        return false;
    }
    return true;
}

SourceText readSourceText(const std::string& path, size_t maxInflatedBytes)
{
    std::string bytes;
    SourceText result;
    if (!readFileBytes(path, bytes, result.error)) return result;
    return decodeSourceBytes(std::move(bytes), path, maxInflatedBytes);
}

}  // namespace cadlod::vrml
