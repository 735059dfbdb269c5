// Appends big-endian values to a growing byte buffer (OpenFlight is big-endian).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cadlod::flt {

class ByteWriter {
public:
    explicit ByteWriter(std::vector<std::uint8_t>& out) : out_(out) {}

    std::size_t size() const { return out_.size(); }
    void u8(std::uint8_t v) { out_.push_back(v); }
    void i8(std::int8_t v) { u8(static_cast<std::uint8_t>(v)); }
    void u16(std::uint16_t v);
    void i16(std::int16_t v) { u16(static_cast<std::uint16_t>(v)); }
    void u32(std::uint32_t v);
    void i32(std::int32_t v) { u32(static_cast<std::uint32_t>(v)); }
    void f32(float v);
    void f64(double v);
    void zeros(std::size_t n) { out_.insert(out_.end(), n, 0); }
    // `text` cut or NUL-padded to exactly `width` bytes; the last byte is always NUL.
    void fixedString(const std::string& text, std::size_t width);
    void bytes(const std::uint8_t* data, std::size_t n) { out_.insert(out_.end(), data, data + n); }
    // Overwrites a big-endian value written earlier.
    void patchU16(std::size_t at, std::uint16_t v);
    void patchU32(std::size_t at, std::uint32_t v);

private:
    std::vector<std::uint8_t>& out_;
};

}  // namespace cadlod::flt
