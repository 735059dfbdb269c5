#include "openflight/lod_model.h"

namespace cadlod::flt {

std::size_t Level::triangleCount() const
{
    std::size_t n = 0;
    for (const Part& p : parts)
        n += p.triangles.size();
    return n;
}

std::size_t LodModel::triangleCount() const
{
    std::size_t n = 0;
    for (const Level& l : levels)
        n += l.triangleCount();
    return n;
}

const char* unitsName(Units units)
{
    switch (units) {
    case Units::Meters: return "meters";
    case Units::Kilometers: return "kilometers";
    case Units::Feet: return "feet";
    case Units::Inches: return "inches";
    case Units::NauticalMiles: return "nautical miles";
    }
    return "unknown";
}

bool unitsFromCode(int code, Units& units)
{
    switch (code) {
    case 0: case 1: case 4: case 5: case 8:
        units = static_cast<Units>(code);
        return true;
    default:
        return false;
    }
}

}  // namespace cadlod::flt
