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

// Default bound on inflated size: generous for CAD assemblies, fatal for gzip bombs.
inline constexpr size_t kDefaultMaxInflatedBytes = size_t(8) << 30;

// Raw bytes of a file; false with `error` set when it cannot be read.
bool readFileBytes(const std::string& path, std::string& bytes, std::string& error);

SourceText readSourceText(const std::string& path, size_t maxInflatedBytes = kDefaultMaxInflatedBytes);
// Same on bytes already in memory (tests, inlines); `name` is used in messages.
SourceText decodeSourceBytes(std::string bytes, const std::string& name,
                             size_t maxInflatedBytes = kDefaultMaxInflatedBytes);

}  // namespace cadlod::vrml
