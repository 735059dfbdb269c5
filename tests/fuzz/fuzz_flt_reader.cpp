// libFuzzer target: the OpenFlight reader on bytes from memory. A success must give a
// model whose triangles use finite vertices inside their part, and whose size stays a
// fixed multiple of the input (no memory amplification); a failure must say why.
#include "openflight/flt_reader.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {

// Each stored vertex or triangle needs at least 4 bytes of input (a palette offset, a
// pool stride, a strip index of 1 byte makes one 12-byte triangle): 32x is ample.
constexpr std::size_t kMaxBytesPerInputByte = 32;
constexpr std::size_t kFixedOverhead = std::size_t(64) << 10;

std::size_t modelBytes(const cadlod::flt::LodModel& model)
{
    std::size_t bytes = sizeof model + model.name.size();
    for (const auto& level : model.levels) {
        bytes += sizeof level + level.name.size();
        for (const auto& part : level.parts)
            bytes += sizeof part + part.name.size() + part.positions.size() * sizeof part.positions[0] +
                     part.normals.size() * sizeof part.normals[0] + part.uvs.size() * sizeof part.uvs[0] +
                     part.triangles.size() * sizeof part.triangles[0];
    }
    return bytes;
}

void requireValidModel(const cadlod::flt::LodModel& model)
{
    for (const auto& level : model.levels)
        for (const auto& part : level.parts)
            for (const auto& t : part.triangles)
                for (auto index : t)
                    if (index >= part.positions.size() || !std::isfinite(part.positions[index][0]) ||
                        !std::isfinite(part.positions[index][1]) || !std::isfinite(part.positions[index][2]))
                        std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    cadlod::flt::LodModel model;
    std::string error;
    cadlod::flt::ReadStats stats;
    if (!cadlod::flt::readOpenFlight(data, size, model, error, &stats)) {
        if (error.empty()) std::abort();
        return 0;
    }
    requireValidModel(model);
    if (modelBytes(model) > kMaxBytesPerInputByte * size + kFixedOverhead) std::abort();
    return 0;
}
