// Which unit an input's coordinates are in, and why: --unit wins; else the file's own word
// (KiCad StepUp's header: 0.1 inch); else --default-unit (metres unless given). A model
// that comes out implausibly large or small in metres is reported with the unit that
// would fix it.
#pragma once
#include <string>

namespace cadlod::cli {

struct UnitChoice {
    std::string unit = "m";      // mm, cm, m, in, 0.1in or a factor, as given
    double scale = 1.0;          // to metres
    std::string source = "the default";  // "--unit", "--default-unit", "the KiCad StepUp header", "the default"
    // "mm (--unit mm)", "0.1in (the KiCad StepUp header; --unit overrides it)", ...
    std::string describe() const;
};

// The scale to metres of a unit name (mm, cm, m, in, 0.1in) or a positive factor; throws
// UsageError naming `option` otherwise.
double unitScaleOf(const std::string& unit, const std::string& option = "--unit");

// The unit of a VRML file: `given` (--unit, empty when not given) wins; else KiCad's
// header when `kicadApplied`; else `fallback` (--default-unit, `fallbackGiven` when on the
// command line).
UnitChoice chooseUnit(const std::string& given, bool kicadApplied, const std::string& fallback, bool fallbackGiven);

// A length for people: `digits` significant digits, in mm below a metre, never with an
// exponent (whole metres from 10^digits m on).
std::string metresText(double metres, int digits);

// Empty when a model `diagonalMetres` across is a plausible CAD model (1 mm .. 100 m);
// else a warning that says the size, the unit assumed and why, and the --unit that fixes it.
std::string implausibleSizeWarning(double diagonalMetres, const UnitChoice& unit);

}  // namespace cadlod::cli
