#include "unit_choice.h"

#include "cli_errors.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace cadlod::cli {
namespace {

constexpr double kSmallestPlausible = 0.001;  // metres
constexpr double kLargestPlausible = 100.0;

bool plausible(double metres) { return metres >= kSmallestPlausible && metres <= kLargestPlausible; }

std::string lengthText(double metres) { return metresText(metres, 3); }

}  // namespace

std::string metresText(double metres, int digits)
{
    // printf's %g writes an exponent for what rounds to 10^digits or more, and below 1e-4.
    const double exponentFrom = std::pow(10.0, digits) - 0.5;
    const double size = std::fabs(metres);
    char text[64];
    if (size >= exponentFrom)
        std::snprintf(text, sizeof text, "%.0f m", metres);
    else if (size == 0 || size >= 1 || size * 1000 >= exponentFrom)
        std::snprintf(text, sizeof text, "%.*g m", digits, metres);
    else if (size >= 1e-7)
        std::snprintf(text, sizeof text, "%.*g mm", digits, metres * 1000);
    else
        std::snprintf(text, sizeof text, "%.10f mm", metres * 1000);
    return text;
}

double unitScaleOf(const std::string& unit, const std::string& option)
{
    static const std::map<std::string, double> named{
        {"mm", 0.001}, {"cm", 0.01}, {"m", 1.0}, {"in", 0.0254}, {"0.1in", 0.00254}};
    if (auto it = named.find(unit); it != named.end())
        return it->second;
    char* end = nullptr;
    const double factor = std::strtod(unit.c_str(), &end);
    if (unit.empty() || *end != '\0' || !(factor > 0) || !std::isfinite(factor))
        throw UsageError(option + ": '" + unit + "' is neither mm, cm, m, in, 0.1in nor a positive factor");
    return factor;
}

std::string UnitChoice::describe() const
{
    if (source == "--unit" || source == "--default-unit")
        return unit + " (" + source + " " + unit + ")";
    if (source == "the KiCad StepUp header")
        return unit + " (" + source + "; --unit overrides it)";
    if (source == "the default")
        return unit + " (" + source + ": no --unit given)";
    return unit + " (" + source + ")";
}

UnitChoice chooseUnit(const std::string& given, bool kicadApplied, const std::string& fallback, bool fallbackGiven)
{
    UnitChoice c;
    if (!given.empty()) {
        c.unit = given;
        c.scale = unitScaleOf(given);
        c.source = "--unit";
    } else if (kicadApplied) {
        c.unit = "0.1in";
        c.scale = 2.54 * 0.001;  // as the importer composes it: 0.1 inch to mm, mm to metres
        c.source = "the KiCad StepUp header";
    } else {
        c.unit = fallback;
        c.scale = unitScaleOf(fallback, "--default-unit");
        c.source = fallbackGiven ? "--default-unit" : "the default";
    }
    return c;
}

std::string implausibleSizeWarning(double diagonalMetres, const UnitChoice& unit)
{
    if (!(diagonalMetres > 0) || plausible(diagonalMetres))
        return {};
    const double inFileUnits = diagonalMetres / unit.scale;
    std::string fix;
    for (const char* candidate : {"mm", "m", "in", "cm", "0.1in"}) {
        const double metres = inFileUnits * unitScaleOf(candidate);
        if (candidate != unit.unit && plausible(metres)) {
            fix = std::string("if the file is in ") + candidate + ", --unit " + candidate + " makes it " +
                  lengthText(metres) + " across";
            break;
        }
    }
    if (fix.empty())
        fix = "no unit of mm, cm, m, in or 0.1in brings it between 1 mm and 100 m: give --unit a factor to metres";
    return "the model is " + lengthText(diagonalMetres) + " across (bounding-box diagonal), " +
           (diagonalMetres > kLargestPlausible ? "large" : "small") + " for a CAD model, with its coordinates taken in " +
           unit.describe() + "; " + fix;
}

}  // namespace cadlod::cli
