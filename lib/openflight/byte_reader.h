// Big-endian reads from a byte range. Reading past the end throws ShortRecord, which
// the OpenFlight reader turns into an error naming the record and its offset.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace cadlod::flt {

struct ShortRecord : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class ByteReader {
public:
    ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    std::size_t position() const { return pos_; }
    std::size_t remaining() const { return size_ - pos_; }
    void seek(std::size_t pos) { require(pos, 0); pos_ = pos; }
    void skip(std::size_t n) { require(pos_, n); pos_ += n; }

    std::uint8_t u8() { require(pos_, 1); return data_[pos_++]; }
    std::uint16_t u16()
    {
        require(pos_, 2);
        const std::uint16_t v = std::uint16_t(data_[pos_] << 8 | data_[pos_ + 1]);
        pos_ += 2;
        return v;
    }
    std::int16_t i16() { return static_cast<std::int16_t>(u16()); }
    std::uint32_t u32()
    {
        const std::uint32_t hi = u16();
        return hi << 16 | u16();
    }
    std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
    float f32()
    {
        const std::uint32_t bits = u32();
        float v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
    double f64()
    {
        const std::uint64_t hi = u32();
        const std::uint64_t bits = hi << 32 | u32();
        double v;
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }
    // A NUL-terminated string in a field of `width` bytes (or up to the end).
    std::string string(std::size_t width)
    {
        if (width == 0)
            return {};  // an empty record body has no data pointer to read from
        require(pos_, width);
        const char* s = reinterpret_cast<const char*>(data_ + pos_);
        pos_ += width;
        return std::string(s, strnlen(s, width));
    }

private:
    void require(std::size_t at, std::size_t n) const
    {
        if (at > size_ || n > size_ - at)
            throw ShortRecord("needs " + std::to_string(n) + " bytes at byte " + std::to_string(at) +
                              " of a " + std::to_string(size_) + "-byte record");
    }

    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
};

}  // namespace cadlod::flt
