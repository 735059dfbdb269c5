// Reads a VRML file into memory, inflating gzip (recognised by the magic bytes 1f 8b,
// whatever the extension) with a bound on the inflated size.
#pragma once

#include <cstddef>
#include <string>

namespace cadlod::vrml {

struct SourceText {
    std::string text;
    bool wasGzip = false;
    std::string error;  // non-empty: unreadable, truncated gzip or over the bound
    bool ok() const { return error.empty(); }
};

// Absolute bound on inflated size: generous for CAD assemblies, fatal for gzip bombs.
inline constexpr size_t kDefaultMaxInflatedBytes = size_t(8) << 30;

// Relative bound, so that memory follows the file size: text VRML compresses 5-40 times
// (docs/reliability.md: 7x for generated CAD files, at most 36x in the corpus), deflate
// at most ~1032 times. Below the floor a file is never refused for its ratio.
inline constexpr size_t kMaxInflationRatio = 256;
inline constexpr size_t kInflationFloorBytes = size_t(16) << 20;

// What `compressedBytes` of gzip may inflate to: the smaller of `absoluteCap` and the
// larger of the floor and kMaxInflationRatio times the compressed size.
size_t inflatedSizeBound(size_t compressedBytes, size_t absoluteCap = kDefaultMaxInflatedBytes);

// Raw bytes of a file; false with `error` set when it cannot be read.
bool readFileBytes(const std::string& path, std::string& bytes, std::string& error);

SourceText readSourceText(const std::string& path, size_t maxInflatedBytes = kDefaultMaxInflatedBytes);
// Same on bytes already in memory (tests, inlines); `name` is used in messages.
SourceText decodeSourceBytes(std::string bytes, const std::string& name,
                             size_t maxInflatedBytes = kDefaultMaxInflatedBytes);

}  // namespace cadlod::vrml
