#include "vrml/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace cadlod::vrml {

bool MappedFile::open(const std::string& path, std::string& error)
{
    release();
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        error = path + ": cannot open file (" + std::strerror(errno) + ")";
        return false;
    }
    struct stat st {};
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        error = path + ": not a regular file";
        ::close(fd);
        return false;
    }
    size_ = size_t(st.st_size);
    if (size_ > 0) {
        data_ = mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
        if (data_ == MAP_FAILED) {
            data_ = nullptr;
            size_ = 0;
            error = path + ": cannot map file (" + std::strerror(errno) + ")";
            ::close(fd);
            return false;
        }
        madvise(data_, size_, MADV_SEQUENTIAL);
    }
    ::close(fd);
    return true;
}

void MappedFile::release()
{
    if (data_) munmap(data_, size_);
    data_ = nullptr;
    size_ = 0;
}

}  // namespace cadlod::vrml
