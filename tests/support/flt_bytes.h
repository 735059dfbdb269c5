// The bytes of an OpenFlight file that do not depend on when it was written: two runs that
// make the same model write the same bytes after the header record, which holds the date.
#pragma once

#include <algorithm>
#include <cstddef>
#include <string>

namespace cadlod::test {

inline std::string afterHeader(const std::string& bytes)
{
    if (bytes.size() < 4)
        return {};
    const std::size_t length = (std::size_t((unsigned char)bytes[2]) << 8) | (unsigned char)bytes[3];
    return bytes.substr(std::min(length, bytes.size()));
}

}  // namespace cadlod::test
