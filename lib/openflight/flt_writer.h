// Writes a neutral LodModel as an OpenFlight 16.1 database (design.md §7):
//   Header, Color Palette, Material Palette, [Vertex Palette + vertices],
//   Push Group Push { [LOD Push] { Object Push {geometry} Pop }* [Pop] }* Pop Pop
// LOD records are written when the model has several levels or a level has a range.
#pragma once

#include "openflight/lod_model.h"
#include "openflight/records.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace cadlod::flt {

enum class GeometryRecords {
    Meshes,  // Mesh + Local Vertex Pool + one triangle-strip primitive per part (triangle_strip.h)
    Faces,   // shared Vertex Palette + one Face record (with Vertex List) per triangle
};
enum class ObjectGrouping { PerPart, PerLevel };

struct WriteOptions {
    DrawType drawType = DrawType::SingleSided;
    GeometryRecords geometry = GeometryRecords::Meshes;
    ObjectGrouping objects = ObjectGrouping::PerPart;
    std::function<void(int percent)> progress;  // optional
};

struct WriteStats {
    std::size_t bytes = 0;
    std::size_t triangles = 0;
    std::size_t vertices = 0;
    std::size_t objects = 0;
    std::size_t lodNodes = 0;
};

// Checks the model (indices in range, attribute arrays sized like the positions, a level
// at least); false with `error` saying which level/part/triangle is wrong.
bool validateModel(const LodModel& model, std::string& error);
bool validateLevels(const std::vector<Level>& levels, std::string& error);

bool writeOpenFlight(const LodModel& model, const WriteOptions& options, std::vector<std::uint8_t>& out,
                     std::string& error, WriteStats* stats = nullptr);
// Writes through a temporary file in the same directory, renamed over `path` once
// complete (atomic_file.h): an interrupted write never leaves a truncated .flt.
bool writeOpenFlightFile(const std::string& path, const LodModel& model, const WriteOptions& options,
                         std::string& error, WriteStats* stats = nullptr);

}  // namespace cadlod::flt
