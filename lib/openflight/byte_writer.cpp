#include "openflight/byte_writer.h"

#include <algorithm>
#include <cstring>

namespace cadlod::flt {

void ByteWriter::u16(std::uint16_t v)
{
    out_.push_back(static_cast<std::uint8_t>(v >> 8));
    out_.push_back(static_cast<std::uint8_t>(v));
}

void ByteWriter::u32(std::uint32_t v)
{
    for (int shift = 24; shift >= 0; shift -= 8)
        out_.push_back(static_cast<std::uint8_t>(v >> shift));
}

void ByteWriter::f32(float v)
{
    std::uint32_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    u32(bits);
}

void ByteWriter::f64(double v)
{
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    u32(static_cast<std::uint32_t>(bits >> 32));
    u32(static_cast<std::uint32_t>(bits));
}

void ByteWriter::fixedString(const std::string& text, std::size_t width)
{
    if (width == 0)
        return;
    const std::size_t n = std::min(text.size(), width - 1);
    out_.insert(out_.end(), text.begin(), text.begin() + static_cast<std::ptrdiff_t>(n));
    zeros(width - n);
}

void ByteWriter::patchU16(std::size_t at, std::uint16_t v)
{
    out_.at(at) = static_cast<std::uint8_t>(v >> 8);
    out_.at(at + 1) = static_cast<std::uint8_t>(v);
}

void ByteWriter::patchU32(std::size_t at, std::uint32_t v)
{
    patchU16(at, static_cast<std::uint16_t>(v >> 16));
    patchU16(at + 2, static_cast<std::uint16_t>(v));
}

}  // namespace cadlod::flt
