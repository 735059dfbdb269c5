// libFuzzer target: the OpenFlight reader on bytes from memory. A success must give a
// model whose triangles use finite vertices inside their part; a failure must say why.
#include "flt_reader.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    cadlod::flt::LodModel model;
    std::string error;
    cadlod::flt::ReadStats stats;
    if (!cadlod::flt::readOpenFlight(data, size, model, error, &stats)) {
        if (error.empty()) std::abort();
        return 0;
    }
    for (const auto& level : model.levels)
        for (const auto& part : level.parts)
            for (const auto& t : part.triangles)
                for (auto index : t)
                    if (index >= part.positions.size() || !std::isfinite(part.positions[index][0]) ||
                        !std::isfinite(part.positions[index][1]) || !std::isfinite(part.positions[index][2]))
                        std::abort();
    return 0;
}
