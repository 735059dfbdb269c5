// Where the command line writes: never over an existing file unless forced, always through
// a temporary file in the same directory renamed into place when complete (the
// OpenFlight core's atomic_file.h), so an interrupted run leaves no truncated output.
#pragma once
#include <functional>
#include <string>

namespace cadlod::cli {

// Throws UsageError when `path` exists and `force` is false.
void checkWritable(const std::string& path, bool force);

// Lets `write(temporaryPath)` write the file, then renames it over `path`; throws
// InputError (exit 1) when writing or renaming fails.
void writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write);

// Lower-case extension of `path` without the dot ("" when none); ".wrl.gz" gives "gz".
std::string extensionOf(const std::string& path);

}  // namespace cadlod::cli
