#include "output_file.h"

#include "openflight/atomic_file.h"
#include "cli_errors.h"

#include <algorithm>
#include <cctype>
#include <sys/stat.h>

namespace cadlod::cli {

void checkWritable(const std::string& path, bool force)
{
    struct stat st {};
    if (!force && ::stat(path.c_str(), &st) == 0)
        throw UsageError(path + ": exists; not overwritten (use --force)");
}

void writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write)
{
    std::string error;
    if (!flt::writeThroughTemporary(path, write, error))
        throw InputError(error);
}

std::string extensionOf(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    const std::size_t dot = path.find_last_of('.');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return {};
    std::string ext = path.substr(dot + 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

}  // namespace cadlod::cli
