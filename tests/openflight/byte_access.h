// Big-endian reads at byte offsets of a written buffer, for record layout tests.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace cadlod::test {

using Bytes = std::vector<std::uint8_t>;

inline std::uint16_t be16(const Bytes& b, std::size_t at) { return std::uint16_t(b.at(at) << 8 | b.at(at + 1)); }
inline std::uint32_t be32(const Bytes& b, std::size_t at) { return std::uint32_t(be16(b, at)) << 16 | be16(b, at + 2); }
inline std::int16_t bei16(const Bytes& b, std::size_t at) { return std::int16_t(be16(b, at)); }
inline std::int32_t bei32(const Bytes& b, std::size_t at) { return std::int32_t(be32(b, at)); }
inline float bef32(const Bytes& b, std::size_t at)
{
    const std::uint32_t bits = be32(b, at);
    float v;
    std::memcpy(&v, &bits, 4);
    return v;
}
inline double bef64(const Bytes& b, std::size_t at)
{
    const std::uint64_t bits = std::uint64_t(be32(b, at)) << 32 | be32(b, at + 4);
    double v;
    std::memcpy(&v, &bits, 8);
    return v;
}
inline std::string cstr(const Bytes& b, std::size_t at, std::size_t width)
{
    std::string s(reinterpret_cast<const char*>(b.data() + at), width);
    return s.substr(0, s.find('\0'));
}

// Opcode and length of every record in a buffer, in order.
struct RecordSpan {
    std::uint16_t opcode;
    std::size_t offset, length;
};
inline std::vector<RecordSpan> recordSpans(const Bytes& b)
{
    std::vector<RecordSpan> out;
    for (std::size_t at = 0; at + 4 <= b.size();) {
        const std::size_t len = be16(b, at + 2);
        out.push_back({be16(b, at), at, len});
        if (len < 4)
            break;
        at += len;
    }
    return out;
}

}  // namespace cadlod::test
