// What simplification did to a mesh, for before/after inspection: face and vertex counts,
// symmetric Hausdorff distance to the original (max, mean, RMS) and triangle compactness
// before and after, with a histogram in tenths.
#pragma once

#include "measure/compactness.h"
#include "measure/hausdorff.h"
#include "support/run_together.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace cadlod {

using CompactnessHistogram = std::array<std::size_t, 10>;  // [0,0.1) ... [0.9,1]

inline CompactnessHistogram histogramOf(const std::vector<double>& values)
{
    CompactnessHistogram h{};
    for (double c : values)
        ++h[std::min<std::size_t>(9, std::size_t(std::max(0.0, c) * 10.0))];
    return h;
}

struct SimplificationReport {
    int facesBefore = 0, facesAfter = 0;
    int verticesBefore = 0, verticesAfter = 0;
    SymmetricHausdorff distance;  // A = the original, B = the simplified mesh
    CompactnessStats before, after;
    CompactnessHistogram histogramBefore{}, histogramAfter{};
};

// `faceSamples` per direction (0: as many as the larger face count). `vertexDistance`, when
// given, receives each vertex of `simplified`'s distance to `original`. `together` runs the
// four independent measures (both Hausdorff directions, both compactness lists) two by
// two; a caller with a thread pool passes e.g. oneTBB's parallel_invoke.
template <class MeshType>
SimplificationReport compareWithOriginal(MeshType& original, MeshType& simplified, std::size_t faceSamples,
                                         std::vector<double>* vertexDistance = nullptr,
                                         const RunTogether& together = runInSequence)
{
    SimplificationReport r;
    r.facesBefore = original.fn;
    r.facesAfter = simplified.fn;
    r.verticesBefore = original.vn;
    r.verticesAfter = simplified.vn;
    const std::size_t samples = faceSamples ? faceSamples : std::size_t(std::max(original.fn, simplified.fn));
    std::vector<double> before, after;
    together(
        [&] {
            together([&] { r.distance.forward = oneSidedHausdorff(original, simplified, samples, 1); },
                     [&] { r.distance.backward = oneSidedHausdorff(simplified, original, samples, 2, vertexDistance); });
        },
        [&] { together([&] { before = faceCompactness(original); }, [&] { after = faceCompactness(simplified); }); });
    r.distance.diagonal = liveDiagonal(original);
    r.histogramBefore = histogramOf(before);
    r.histogramAfter = histogramOf(after);
    r.before = summarizeCompactness(before);
    r.after = summarizeCompactness(after);
    return r;
}

// Why `result` cannot be a simplification of `original` (empty when it may be): bounding-box
// diagonals more than 1.5x apart (a ratio near a unit conversion is named), boxes that do
// not overlap, or whose common part is less than half the smaller one across. Boxes are
// closed: a flat part and its flat simplification overlap.
template <class S>
std::string whyNotASimplification(const vcg::Box3<S>& original, const vcg::Box3<S>& result)
{
    constexpr double kSizeRatio = 1.5, kLeastOverlap = 0.5;
    const double da = double(original.Diag()), db = double(result.Diag());
    char why[320];
    const double ratio = std::max(da, db) / std::max(std::min(da, db), 1e-300);
    if (ratio > kSizeRatio) {
        static const std::pair<double, const char*> kUnits[] = {
            {1000, "mm and m"}, {100, "cm and m"}, {10, "mm and cm"}, {25.4, "mm and in"},
            {2.54, "cm and in, or 0.1 in and mm"}, {39.37, "in and m"}, {304.8, "mm and ft"}};
        std::string unit = "another model, or a different unit?";
        for (const auto& [factor, names] : kUnits)
            if (std::abs(ratio / factor - 1.0) < 0.1)
                unit = std::string("a different unit (") + names + ")?";
        std::snprintf(why, sizeof why, "the result is %.*fx %s (bounding-box diagonals %.4g and %.4g): %s",
                      ratio < 10 ? 1 : 0, ratio, db < da ? "smaller" : "larger", da, db, unit.c_str());
        return why;
    }
    double common2 = 0;
    for (int i = 0; i < 3; ++i) {
        const double overlap = double(std::min(original.max[i], result.max[i])) -
                               double(std::max(original.min[i], result.min[i]));
        if (overlap < 0 || original.IsNull() || result.IsNull()) {
            std::snprintf(why, sizeof why,
                          "their bounding boxes do not overlap (centers %.4g apart, diagonals %.4g and %.4g): "
                          "moved, or a different unit?",
                          double((original.Center() - result.Center()).Norm()), da, db);
            return why;
        }
        common2 += overlap * overlap;
    }
    if (std::sqrt(common2) < kLeastOverlap * std::min(da, db)) {
        std::snprintf(why, sizeof why,
                      "their bounding boxes barely overlap (the common part is %.0f%% of the smaller one across): "
                      "moved, or a different unit?",
                      100.0 * std::sqrt(common2) / std::max(std::min(da, db), 1e-300));
        return why;
    }
    return {};
}

// One line per tenth: "0.3-0.4 | before  12.5% ######     | after  30.1% ###############".
inline std::vector<std::string> histogramLines(const SimplificationReport& r)
{
    std::vector<std::string> lines;
    auto share = [](const CompactnessHistogram& h, std::size_t bin, std::size_t total) {
        return total ? 100.0 * double(h[bin]) / double(total) : 0.0;
    };
    for (std::size_t bin = 0; bin < 10; ++bin) {
        const double b = share(r.histogramBefore, bin, r.before.faces);
        const double a = share(r.histogramAfter, bin, r.after.faces);
        char line[160];
        std::snprintf(line, sizeof line, "%.1f-%.1f | before %5.1f%% %-20s | after %5.1f%% %s", bin / 10.0,
                      (bin + 1) / 10.0, b, std::string(std::size_t(b / 5.0 + 0.5), '#').c_str(), a,
                      std::string(std::size_t(a / 5.0 + 0.5), '#').c_str());
        lines.push_back(line);
    }
    return lines;
}

}  // namespace cadlod
