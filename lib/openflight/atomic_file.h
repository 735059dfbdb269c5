// Writing a file so that it is never seen half-written: the bytes go to a temporary file
// in the same directory (same file system), which is renamed over the final path only
// once complete and flushed. An interrupted writer leaves at most a ".<name>.tmp-XXXXXX"
// file behind, never a truncated output. Used by the OpenFlight writer and the cadlod
// command line (for every format it writes).
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cadlod::flt {

// A temporary path next to `path` (same directory), created empty and unique.
// Empty on failure, with `error`.
std::string createTemporaryNextTo(const std::string& path, std::string& error);

// Renames `temporary` over `path`; removes `temporary` and sets `error` on failure.
bool commitTemporary(const std::string& temporary, const std::string& path, std::string& error);

// Writes `bytes` to `path` through a temporary file and a rename.
bool writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string& error);

// Lets `write(temporaryPath)` produce the file (e.g. a third-party exporter), then renames
// it into place; when `write` returns false the temporary file is removed.
bool writeThroughTemporary(const std::string& path, const std::function<bool(const std::string&)>& write,
                           std::string& error);

}  // namespace cadlod::flt
