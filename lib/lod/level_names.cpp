#include "lod/level_names.h"

#include "lod/lod_chain.h"  // kNeverCulled

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cadlod {

std::string twoSignificantDigits(double value)
{
    if (!(value > 0))
        return "0";
    int magnitude = int(std::floor(std::log10(value)));
    const double rounded = std::round(value / std::pow(10.0, magnitude - 1)) * std::pow(10.0, magnitude - 1);
    if (rounded >= std::pow(10.0, magnitude + 1))  // 0.996 rounds up to 1.0: one decimal less
        ++magnitude;
    const int decimals = std::max(0, 1 - magnitude);
    char text[48];
    std::snprintf(text, sizeof text, "%.*f", decimals, rounded);
    return text;
}

std::string distanceWithUnit(double modelUnits, double metresPerUnit)
{
    if (!std::isfinite(modelUnits) || modelUnits >= kNeverCulled)
        return "inf";
    if (!(metresPerUnit > 0))
        return twoSignificantDigits(modelUnits);
    const double metres = modelUnits * metresPerUnit;
    if (metres < 1.0 && twoSignificantDigits(metres * 1000.0) != "1000")
        return twoSignificantDigits(metres * 1000.0) + " mm";
    return twoSignificantDigits(metres) + " m";
}

std::string levelRangeName(int level, double switchOut, double switchIn, double metresPerUnit)
{
    const std::string name = "LOD" + std::to_string(level);
    if (level > 0)
        return name + " \u2265" + distanceWithUnit(switchOut, metresPerUnit);
    if (!std::isfinite(switchIn) || switchIn >= kNeverCulled)
        return name;
    return name + " <" + distanceWithUnit(switchIn, metresPerUnit);
}

std::string levelLabel(const std::string& base, const std::string& rangeName, const std::string& suffix)
{
    const std::string withBase = base + " " + rangeName;
    // The panel counts characters, not the bytes of '≥'.
    std::size_t chars = 0;
    for (unsigned char c : withBase)
        chars += (c & 0xC0) != 0x80;
    return (base.empty() || chars > kPanelChars ? rangeName : withBase) + suffix;
}

}  // namespace cadlod
