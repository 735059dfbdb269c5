#include "openflight/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace cadlod::flt {
namespace {

std::string directoryOf(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

std::string baseNameOf(const std::string& path)
{
    const std::size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

bool writeAll(int fd, const std::uint8_t* data, std::size_t size)
{
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0 && errno == EINTR)
            continue;
        if (n <= 0)
            return false;
        data += n;
        size -= std::size_t(n);
    }
    return true;
}

}  // namespace

std::string createTemporaryNextTo(const std::string& path, std::string& error)
{
    std::string pattern = directoryOf(path) + "." + baseNameOf(path) + ".tmp-XXXXXX";
    const int fd = ::mkstemp(pattern.data());
    if (fd < 0) {
        error = path + ": cannot create a temporary file next to it: " + std::strerror(errno);
        return {};
    }
    const mode_t mask = ::umask(0);  // mkstemp makes it 0600: give it the usual 0666 & ~umask
    ::umask(mask);
    ::fchmod(fd, 0666 & ~mask);
    ::close(fd);
    return pattern;
}

bool commitTemporary(const std::string& temporary, const std::string& path, std::string& error)
{
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        error = path + ": cannot rename the temporary file into place: " + std::strerror(errno);
        std::remove(temporary.c_str());
        return false;
    }
    return true;
}

bool writeFileAtomically(const std::string& path, const std::vector<std::uint8_t>& bytes, std::string& error)
{
    return writeThroughTemporary(
        path,
        [&](const std::string& temporary) {
            const int fd = ::open(temporary.c_str(), O_WRONLY | O_TRUNC);
            if (fd < 0)
                return false;
            const bool ok = writeAll(fd, bytes.data(), bytes.size()) && ::fsync(fd) == 0;
            return ::close(fd) == 0 && ok;
        },
        error);
}

bool writeThroughTemporary(const std::string& path, const std::function<bool(const std::string&)>& write,
                           std::string& error)
{
    const std::string temporary = createTemporaryNextTo(path, error);
    if (temporary.empty())
        return false;
    if (!write(temporary)) {
        std::remove(temporary.c_str());
        if (error.empty())
            error = path + ": cannot write the file";
        return false;
    }
    return commitTemporary(temporary, path, error);
}

}  // namespace cadlod::flt
