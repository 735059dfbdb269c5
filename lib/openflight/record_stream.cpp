#include "openflight/record_stream.h"

#include "openflight/records.h"

namespace cadlod::flt {

std::string opcodeText(std::uint16_t op) { return "opcode " + std::to_string(op); }

bool RecordStream::next(std::size_t pos, std::uint16_t& op, std::vector<std::uint8_t>& body, std::size_t& next,
                        std::size_t& continuations, std::string& error) const
{
    std::size_t length = 0;
    if (!headerAt(pos, op, length, error))
        return false;
    body.assign(data_ + pos + 4, data_ + pos + length);
    next = pos + length;
    if (op != opcode::LocalVertexPool && op != opcode::MeshPrimitive)
        return true;
    while (next + 4 <= size_ && (data_[next] << 8 | data_[next + 1]) == opcode::Continuation) {
        std::uint16_t continued = 0;
        if (!headerAt(next, continued, length, error))
            return false;
        body.insert(body.end(), data_ + next + 4, data_ + next + length);
        next += length;
        ++continuations;
    }
    return true;
}

bool RecordStream::headerAt(std::size_t pos, std::uint16_t& op, std::size_t& length, std::string& error) const
{
    if (size_ - pos < 4) {
        error = "truncated file: " + std::to_string(size_ - pos) + " byte(s) left at offset " + std::to_string(pos) +
                ", a record header needs 4";
        return false;
    }
    op = std::uint16_t(data_[pos] << 8 | data_[pos + 1]);
    length = std::size_t(data_[pos + 2] << 8 | data_[pos + 3]);
    if (length < 4) {
        error = "corrupt record at offset " + std::to_string(pos) + " (" + opcodeText(op) + "): length " +
                std::to_string(length) + " is shorter than the 4-byte record header";
        return false;
    }
    if (length > size_ - pos) {
        error = "truncated record at offset " + std::to_string(pos) + " (" + opcodeText(op) + "): " +
                std::to_string(length) + " bytes announced, " + std::to_string(size_ - pos) + " left in the file";
        return false;
    }
    return true;
}

}  // namespace cadlod::flt
