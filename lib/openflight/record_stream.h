// How an OpenFlight file is cut into records: each starts with a 4-byte header (opcode,
// length), and the variable-length records (Local Vertex Pool, Mesh Primitive) go on in the
// Continuation records that follow them.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cadlod::flt {

class RecordStream
{
public:
    RecordStream(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    // Reads the record at `pos` into `op` and `body` (its bytes after the header, with the
    // bodies of its Continuation records glued on, `continuations` of them) and the offset
    // of the record after it into `next`. False, with `error` naming the offset, where a
    // header is cut off or a length is impossible.
    bool next(std::size_t pos, std::uint16_t& op, std::vector<std::uint8_t>& body, std::size_t& next,
              std::size_t& continuations, std::string& error) const;

private:
    bool headerAt(std::size_t pos, std::uint16_t& op, std::size_t& length, std::string& error) const;

    const std::uint8_t* data_;
    std::size_t size_;
};

// "opcode N", for messages.
std::string opcodeText(std::uint16_t op);

}  // namespace cadlod::flt
