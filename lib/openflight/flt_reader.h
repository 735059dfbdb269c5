// Reads an OpenFlight database into the neutral LodModel: the k-th LOD record of every LOD
// node becomes level k (geometry outside any LOD goes to one level without a range, or to the
// finest level when there are several LOD nodes), every Object a part; Instance References
// are read as copies of their definitions, moved by the Matrix records above them; Face records (through the Vertex Palette) and Mesh records (Local Vertex Pool +
// strip/fan/polygon primitives) become triangles. Polygons are fanned.
// Corrupt or truncated input gives an error naming the record offset; faces that point
// outside the palette are skipped and counted.
#pragma once

#include "openflight/lod_model.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cadlod::flt {

struct ReadStats {
    int formatRevision = 0;
    std::size_t records = 0;
    std::size_t faces = 0;           // Face records and mesh primitives read
    std::size_t skippedFaces = 0;    // with fewer than 3 valid vertices
    std::size_t unknownRecords = 0;  // opcodes this reader does not interpret (skipped)
    std::size_t instanceDefinitions = 0;
    std::size_t instanceReferences = 0;  // each read as a copy of its definition, where it is placed
};

struct ReadOptions {
    std::function<void(int percent)> progress;  // optional
};

bool readOpenFlight(const std::uint8_t* data, std::size_t size, LodModel& model, std::string& error,
                    ReadStats* stats = nullptr, const ReadOptions& options = {});
bool readOpenFlightFile(const std::string& path, LodModel& model, std::string& error,
                        ReadStats* stats = nullptr, const ReadOptions& options = {});

// The level with the nearest switch-out distance (the finest); 0 for an empty model.
std::size_t finestLevel(const LodModel& model);

}  // namespace cadlod::flt
