// Short names for the levels of an LOD set as MeshLab's layer panel shows them: the panel
// is narrow and drops everything after a label's last '.', as it would a file suffix.
// A level is named by the distance it is switched in at ("LOD1 ≥7.7 mm"), level 0 by the
// distance it gives way at ("LOD0 <7.7 mm").
#pragma once

#include <cstddef>
#include <string>

namespace cadlod {

// Two significant digits, never in exponent form: 0.0077, 7.7, 15, 2900.
std::string twoSignificantDigits(double value);

// A distance with its unit: mm below 1 m, m from 1 m on; without a unit when the metres
// per model unit are unknown (0). Infinite distances read "inf".
std::string distanceWithUnit(double modelUnits, double metresPerUnit);

// "LOD<level> ≥<switch-in>" for a level k > 0 (switchOut is its near end), "LOD0 <<far end>"
// for level 0 ("LOD0" alone when it is drawn at every distance).
std::string levelRangeName(int level, double switchOut, double switchIn, double metresPerUnit);

// The layer label: "<base> <range name>" when it fits the panel (kPanelChars), else the
// range name alone; `suffix` (e.g. ".flt") is appended for the panel to drop, so that the
// decimal point of a distance is not taken for one.
inline constexpr std::size_t kPanelChars = 20;
std::string levelLabel(const std::string& base, const std::string& rangeName, const std::string& suffix);

}  // namespace cadlod
