// Read-only memory map of a whole file (no zero-fill, no copy: big VRML files parse
// straight from the page cache). Unmapped on destruction or release().
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace cadlod::vrml {

class MappedFile {
public:
    MappedFile() = default;
    MappedFile(const MappedFile&) = delete;
    MappedFile& operator=(const MappedFile&) = delete;
    ~MappedFile() { release(); }

    // False with `error` set when the file cannot be opened or mapped.
    bool open(const std::string& path, std::string& error);
    std::string_view bytes() const { return {static_cast<const char*>(data_), size_}; }
    void release();

private:
    void* data_ = nullptr;
    size_t size_ = 0;
};

}  // namespace cadlod::vrml
