#include "output_file.h"

#include "openflight/atomic_file.h"
#include "cli_errors.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

namespace cadlod::cli {
namespace {

namespace fs = std::filesystem;

std::string folderOf(const std::string& path)
{
    const fs::path parent = fs::path(path).parent_path();
    return parent.empty() ? std::string(".") : parent.string();
}

// The same file whatever the spelling ("out/./a.flt", "out//a.flt", a relative path).
std::string normalised(const std::string& path)
{
    std::error_code ec;
    const fs::path p = fs::weakly_canonical(fs::absolute(fs::path(path), ec), ec);
    return ec ? fs::path(path).lexically_normal().string() : p.string();
}

}  // namespace

void checkWritable(const std::string& path, bool force)
{
    const std::string folder = folderOf(path);
    struct stat st {};
    if (::stat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
        throw InputError(path + ": the folder " + folder + " does not exist");
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        throw InputError(path + ": the folder " + folder + " is not writable (" + std::strerror(errno) + ")");
    if (::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
        throw UsageError(path + ": is a folder; give a file name");
    if (!force && ::stat(path.c_str(), &st) == 0)
        throw UsageError(path + ": exists; not overwritten (use --force)");
}

void writeAtomically(const std::string& path, const std::function<bool(const std::string&)>& write)
{
    std::string error;
    if (!flt::writeThroughTemporary(path, write, error))
        throw InputError(error);
}

bool writeBytesTo(const std::string& file, const std::vector<std::uint8_t>& bytes)
{
    const int fd = ::open(file.c_str(), O_WRONLY | O_TRUNC);
    if (fd < 0)
        return false;
    const std::uint8_t* data = bytes.data();
    std::size_t left = bytes.size();
    bool ok = true;
    while (ok && left > 0) {
        const ssize_t n = ::write(fd, data, left);
        if (n < 0 && errno == EINTR)
            continue;
        ok = n > 0;
        if (ok) {
            data += n;
            left -= std::size_t(n);
        }
    }
    ok = ok && ::fsync(fd) == 0;
    return ::close(fd) == 0 && ok;
}

OutputSet::~OutputSet()
{
    for (const Output& o : outputs_)
        if (!o.temporary.empty())
            std::remove(o.temporary.c_str());
}

void OutputSet::add(const std::string& path, const std::string& option)
{
    for (const Output& o : outputs_)
        if (normalised(o.path) == normalised(path))
            throw UsageError(option + " " + path + " is the same file as " + o.option + " " + o.path +
                             ": give each output its own path");
    checkWritable(path, force_);
    outputs_.push_back({path, option, {}});
}

OutputSet::Output& OutputSet::find(const std::string& path)
{
    for (Output& o : outputs_)
        if (o.path == path)
            return o;
    throw std::logic_error(path + ": not an output of this run");
}

void OutputSet::write(const std::string& path, const std::function<bool(const std::string& temporary)>& write)
{
    Output& o = find(path);
    std::string error;
    if (o.temporary.empty())
        o.temporary = flt::createTemporaryNextTo(path, error);
    if (o.temporary.empty())
        throw InputError(error);
    if (!write(o.temporary))
        throw InputError(path + ": cannot write the temporary file " + o.temporary);
}

// Renamed last to first: when a rename fails, the outputs already in place are removed,
// so that the run leaves all of them or none (an output replaced with --force is lost).
void OutputSet::commit()
{
    std::vector<const Output*> placed;
    for (auto it = outputs_.rbegin(); it != outputs_.rend(); ++it) {
        if (it->temporary.empty())  // not written
            continue;
        std::string error;
        if (!flt::commitTemporary(it->temporary, it->path, error)) {
            it->temporary.clear();  // commitTemporary removed it
            for (const Output* done : placed)
                std::remove(done->path.c_str());
            throw InputError(error);
        }
        it->temporary.clear();
        placed.push_back(&*it);
    }
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
