// gzip-compresses a string in memory (zlib, gzip wrapper): test inputs for the importer's
// gzip path, bombs and truncations included.
#pragma once

#include <zlib.h>

#include <string>

namespace cadlod::test {

inline std::string gzipText(const std::string& text, int level = Z_BEST_COMPRESSION)
{
    z_stream zs{};
    deflateInit2(&zs, level, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY);
    std::string out(deflateBound(&zs, uLong(text.size())) + 32, '\0');
    zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
    zs.avail_in = uInt(text.size());
    zs.next_out = reinterpret_cast<Bytef*>(out.data());
    zs.avail_out = uInt(out.size());
    deflate(&zs, Z_FINISH);
    out.resize(zs.total_out);
    deflateEnd(&zs);
    return out;
}

}  // namespace cadlod::test
