// The simplifier's parameters as the front ends offer them, one row each: the MeshLab
// filters' parameters (name, label, help), the `cadlod` options and the keys of the JSON
// report all come from these rows, and every default from SimplifyParams{}. The stop
// criteria and the selection are not here: each front end words and defaults them its own
// way (a dialog proposes a reduction, the command line another, an LOD set sets them per
// level).
#pragma once

#include "simplify/simplify_params.h"

#include <cstddef>
#include <iterator>
#include <limits>
#include <type_traits>

namespace cadlod {

enum class ParameterKind { Bool, Int, Float };

// How a row reads and writes its value on a SimplifyParams. Values travel as double, which
// holds every bool and int exactly.
struct ParameterField {
    ParameterKind kind;
    double (*get)(const SimplifyParams&);
    void (*set)(SimplifyParams&, double);
};

namespace detail {
template <class Member>
struct MemberType;
template <class T>
struct MemberType<T SimplifyParams::*> {
    using type = T;
};
}  // namespace detail

// The field of a plain SimplifyParams member; its kind follows from the member's type.
template <auto Member>
constexpr ParameterField memberField()
{
    using T = typename detail::MemberType<decltype(Member)>::type;
    static_assert(std::is_same_v<T, bool> || std::is_same_v<T, int> || std::is_same_v<T, double>);
    constexpr ParameterKind kind = std::is_same_v<T, bool>  ? ParameterKind::Bool
                                   : std::is_same_v<T, int> ? ParameterKind::Int
                                                            : ParameterKind::Float;
    return {kind, [](const SimplifyParams& p) { return double(p.*Member); },
            [](SimplifyParams& p, double v) { p.*Member = T(v); }};
}

// The weight trials as a switch: off sets their mesh-size limit to 0, on keeps the limit
// the caller had.
constexpr ParameterField weightTrialsSwitch()
{
    return {ParameterKind::Bool, [](const SimplifyParams& p) { return p.weightTrialsMaxFaces > 0 ? 1.0 : 0.0; },
            [](SimplifyParams& p, double on) {
                if (on == 0)
                    p.weightTrialsMaxFaces = 0;
            }};
}

// The values that make sense, both ends included unless minExcluded; an unbounded end is
// infinite.
struct ParameterRange {
    double min = 0;
    double max = std::numeric_limits<double>::infinity();
    bool minExcluded = false;
};
inline constexpr ParameterRange kNonNegative{};
inline constexpr ParameterRange kDegrees{0, 180};
inline constexpr ParameterRange kShare{0, 1};
inline constexpr ParameterRange kSwitch{0, 1};

// How `cadlod` offers a row: an option taking the value, a flag turning it on or off
// (unset, the default stands), or not at all.
enum class CliForm { None, Option, FlagOn, FlagOff };
struct CliSpec {
    CliForm form = CliForm::None;
    const char* names = nullptr;  // CLI11 names, aliases after a comma
    const char* help = nullptr;   // what giving the option or the flag does
    int position = -1;            // its place in `--help` among the simplifier's options
};

struct SimplifyParameter {
    const char* name;  // the .mlx script name
    ParameterField field;
    const char* label;  // the MeshLab dialog's label
    const char* help;   // the MeshLab tooltip, also docs/mlx-parameters.md's meaning
    ParameterRange range;
    bool inLodSetFilter;  // what is a feature and how dearly it gives way: the LOD set's user decides it too
    CliSpec cli;
    const char* jsonKey;  // in the `cadlod convert --report` options; nullptr: not reported
};

// In the order of the simplification filter's dialog (and of a complete .mlx script).
inline constexpr SimplifyParameter kSimplifyParameters[] = {
    {"tieTolerance", memberField<&SimplifyParams::tieTolerance>(), "Tie tolerance (relative)",
     "Placements within this fraction of the cheapest cost are tied; compactness decides.", kNonNegative, false, {},
     nullptr},
    {"flatTolerance", memberField<&SimplifyParams::flatTolerance>(), "Flat tolerance (fraction of diagonal)",
     "Collapses within this RMS distance (share of the diagonal) are free if they make no sliver.",
     kNonNegative, false, {}, nullptr},
    {"candidatesPerEdge", memberField<&SimplifyParams::candidatesPerEdge>(), "Candidates per edge",
     "Points tried along each edge, besides its ends and the quadric optimum.", kNonNegative, false, {}, nullptr},
    {"optimalPlacement", memberField<&SimplifyParams::optimalPlacement>(), "Optimal placement",
     "Also try the quadric optimum near the edge.",
     kSwitch, false, {}, nullptr},
    {"boundaryWeight", memberField<&SimplifyParams::boundaryWeight>(), "Boundary/crease weight",
     "Weight of the constraint quadrics of boundaries, creases and borders.", kNonNegative, false, {}, nullptr},
    {"preserveTopology", memberField<&SimplifyParams::preserveTopology>(), "Preserve topology",
     "No change of genus, no non-manifold edges.", kSwitch, false, {}, nullptr},
    {"closeTunnels", memberField<&SimplifyParams::closeTunnels>(), "Close tunnels",
     "Tunnels may be cut and capped (logged).",
     kSwitch, false,
     {CliForm::FlagOff, "--keep-tunnels", "Never cut and cap a tunnel (a through-hole) whose rim has shrunk to three edges",
      7},
     "closeTunnels"},
    {"normalCheck", memberField<&SimplifyParams::normalCheck>(), "Normal check",
     "Refuse faces turned too far or flipped.",
     kSwitch, false, {}, nullptr},
    {"normalThreshold", memberField<&SimplifyParams::normalThreshold>(), "Normal threshold (degrees)",
     "Largest turn of a face normal in one collapse.", {0, 180, true}, false, {}, nullptr},
    {"minCompactness", memberField<&SimplifyParams::minCompactness>(), "Minimum compactness",
     "No new triangle less compact than this unless it was worse already (0: off).", kShare, false, {}, nullptr},
    {"qualityThreshold", memberField<&SimplifyParams::qualityThreshold>(), "Quality threshold",
     "Free collapses making triangles less compact than this wait longer.", kShare, false, {}, nullptr},
    {"largeFaceWeight", memberField<&SimplifyParams::largeFaceWeight>(), "Large-face weight",
     "Plane weight by face area: large faces (a plate's top) keep their place. 0: all alike.",
     kNonNegative, false, {}, nullptr},
    {"weightTrials", weightTrialsSwitch(), "Try plane weights",
     "Try several plane weights, keep the best.",
     kSwitch, false,
     {CliForm::FlagOff, "--no-weight-trials",
      "Simplify with the default plane weight only; by default a mesh under 200 000 faces is first simplified with a "
      "few plane weights, two at a time on two cores, and the result nearest the input is used",
      8},
     "weightTrials"},
    {"shadingWeight", memberField<&SimplifyParams::shadingWeight>(), "Shading weight",
     "Price of faces turned past the shading angle from their input faces. 0: geometry alone.",
     kNonNegative, false,
     {CliForm::Option, "--shading-weight",
      "Price of the faces a collapse turns further than the shading angle from their input faces, per squared bbox "
      "diagonal of turned area (0: geometry alone)",
      2},
     "shadingWeight"},
    {"shadingAngle", memberField<&SimplifyParams::shadingAngle>(), "Shading angle (degrees)",
     "Faces turned less than this from their input faces keep their shade: not priced.", kDegrees, false, {},
     nullptr},
    {"planarQuadric", memberField<&SimplifyParams::planarQuadric>(), "Planar quadrics",
     "Extra edge quadrics: steadier flat regions.", kSwitch, false, {}, nullptr},
    {"relaxToReachTarget", memberField<&SimplifyParams::relaxToReachTarget>(), "Reach the target",
     "Relax the guards when blocked (logged).",
     kSwitch, false,
     {CliForm::FlagOff, "--no-relax",
      "Stop early rather than cut non-manifold edges apart, relax the shape guards or remove components", 6},
     "relaxToReachTarget"},
    {"featureAngle", memberField<&SimplifyParams::featureAngle>(), "Feature angle (degrees)",
     "Sharper edges are creases: their vertices only move along them.", kDegrees, true,
     {CliForm::Option, "--feature-angle", "Creases sharper than this (degrees) are features", 0}, "featureAngle"},
    {"preserveBoundary", memberField<&SimplifyParams::preserveBoundary>(), "Preserve boundary",
     "Boundary edges are features.", kSwitch, true,
     {CliForm::FlagOff, "--no-boundary", "Open boundaries get no constraint quadrics", 5}, "preserveBoundary"},
    {"keepPartBorders", memberField<&SimplifyParams::keepPartBorders>(), "Keep part borders",
     "Part borders are features even where flat.",
     kSwitch, true,
     {CliForm::FlagOn, "--part-borders",
      "Edges between parts are features, also where the parts meet flat and in one colour", 3},
     "keepPartBorders"},
    {"keepColorBorders", memberField<&SimplifyParams::keepColorBorders>(), "Keep colour borders",
     "Borders between colours are features.", kSwitch, true,
     {CliForm::FlagOff, "--no-colour-borders,--no-color-borders", "Edges between colours (materials) are not features",
      4},
     "keepColourBorders"},
    {"featurePenalty", memberField<&SimplifyParams::featurePenalty>(), "Feature penalty",
     "A feature gives way only where that costs this many times less (0: never).", kNonNegative, true,
     {CliForm::Option, "--feature-penalty",
      "A collapse that breaks a feature costs this many times its quadric cost (0: hard lock)", 1},
     "featurePenalty"},
};

inline constexpr std::size_t kSimplifyParameterCount = std::size(kSimplifyParameters);

// The row's value in SimplifyParams{}: the one default of every front end.
inline double defaultOf(const SimplifyParameter& row)
{
    return row.field.get(SimplifyParams{});
}

}  // namespace cadlod
