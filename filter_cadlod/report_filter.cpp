#include "report_filter.h"

#include "compactness_colors.h"
#include "mesh/layer_metadata.h"
#include "measure/simplification_report.h"

#include <vcg/complex/algorithms/update/bounding.h>

#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

namespace cadlod {
namespace {

// The original of a LOD level is level 0 of its set; otherwise the first other layer.
MeshModel* defaultOriginal(MeshDocument& md)
{
    MeshModel* current = md.mm();
    if (current && hasLodLevel(current->cm)) {
        const int set = lodLevelHandle(current->cm)().setId;
        for (MeshModel* m : md.meshList)
            if (m != current && hasLodLevel(m->cm) && lodLevelHandle(m->cm)().setId == set &&
                lodLevelHandle(m->cm)().level == 0)
                return m;
    }
    for (MeshModel* m : md.meshList)
        if (m != current)
            return m;
    return current;
}

double percentOf(double value, double diagonal) { return diagonal > 0 ? 100.0 * value / diagonal : 0.0; }

// True when both layers are levels of one LOD set: cadlod knows one comes from the other.
bool sameLodSet(MeshModel& a, MeshModel& b)
{
    return hasLodLevel(a.cm) && hasLodLevel(b.cm) && lodLevelHandle(a.cm)().setId == lodLevelHandle(b.cm)().setId;
}

// Two meshes that cannot be a simplification of one another (the measure core's rule, as
// `cadlod report` applies it). Empty when they may be.
std::string unrelatedBecause(CMeshO& current, CMeshO& original)
{
    vcg::tri::UpdateBounding<CMeshO>::Box(current);
    vcg::tri::UpdateBounding<CMeshO>::Box(original);
    return whyNotASimplification(original.bbox, current.bbox);
}

// MeshLab's log panel is HTML in a proportional font: runs of spaces collapse (figure
// spaces too), and a '#' is not as wide as a space, so no column after a bar lines up.
// Each line starts with text of one width (digits are all as wide), then the bar, then
// its value: "0.3-0.4 |## 10.0 %".
std::vector<std::string> histogramForLog(const CompactnessHistogram& h, std::size_t faces)
{
    std::vector<std::string> lines;
    for (std::size_t bin = 0; bin < h.size(); ++bin) {
        const double share = faces ? 100.0 * double(h[bin]) / double(faces) : 0.0;
        char line[96];
        std::snprintf(line, sizeof line, "%.1f-%.1f |%s %.1f %%", bin / 10.0, (bin + 1) / 10.0,
                      std::string(std::size_t(share / 5.0 + 0.5), '#').c_str(), share);
        lines.push_back(line);
    }
    return lines;
}

void logReport(MeshFilterInterface& plugin, const MeshModel& current, const MeshModel& original,
               const SimplificationReport& r)
{
    const SymmetricHausdorff& d = r.distance;
    plugin.Log("Simplification report: %s against %s", qUtf8Printable(current.label()),
               qUtf8Printable(original.label()));
    plugin.Log("  faces %d -> %d (%+.1f%%), vertices %d -> %d", r.facesBefore, r.facesAfter,
               r.facesBefore ? 100.0 * (r.facesAfter - r.facesBefore) / r.facesBefore : 0.0, r.verticesBefore,
               r.verticesAfter);
    plugin.Log("  Hausdorff (symmetric, %zu samples): max %.6g (%.4f%% of diagonal), mean %.6g (%.4f%%), "
               "RMS %.6g (%.4f%%); original->current max %.6g, current->original max %.6g",
               d.forward.samples + d.backward.samples, d.max(), percentOf(d.max(), d.diagonal), d.mean(),
               percentOf(d.mean(), d.diagonal), d.rms(), percentOf(d.rms(), d.diagonal), d.forward.max,
               d.backward.max);
    for (const auto& [name, s] : {std::pair{"before", r.before}, std::pair{"after", r.after}})
        plugin.Log("  compactness %s: mean %.4f, min %.4f, p5 %.4f, below 0.1: %.2f%%, below 0.3: %.2f%%", name,
                   s.mean, s.min, s.p5, 100.0 * s.shareBelow01, 100.0 * s.shareBelow03);
    for (const auto& [name, h, faces] : {std::tuple{"before", r.histogramBefore, r.before.faces},
                                         std::tuple{"after", r.histogramAfter, r.after.faces}}) {
        plugin.Log("  compactness %s, share of the faces per tenth (# = 5 %%):", name);
        for (const std::string& line : histogramForLog(h, faces))
            plugin.Log("%s", line.c_str());
    }
}

}  // namespace

void reportParameters(MeshDocument& md, RichParameterList& par)
{
    par.addParam(RichMesh("original", defaultOriginal(md), &md, "Original",
                          "The layer the current one was simplified from (level 0 of its LOD set "
                          "by default)."));
    par.addParam(RichInt("samples", 0, "Samples per direction",
                         "Surface samples for the Hausdorff distance in each direction, besides "
                         "the vertices; 0 = as many as the larger face count."));
    par.addParam(RichBool("storeDistance", true, "Distance as vertex quality",
                          "Store each vertex's distance to the original as vertex quality, for "
                          "the quality color mapper."));
    par.addParam(RichBool("storeCompactness", true, "Compactness as face quality and colour",
                          "Store each triangle's compactness as face quality and paint the faces by it "
                          "(red 0, yellow 0.5, green 1; replaces the face colours)."));
}

bool simplificationReport(MeshFilterInterface& plugin, MeshDocument& md, const RichParameterList& par,
                          QString& error)
{
    MeshModel* current = md.mm();
    MeshModel* original = par.getMesh("original");
    if (!current || !original || current == original) {
        error = "choose as Original a layer other than the current one";
        return false;
    }
    if (current->cm.fn == 0 || original->cm.fn == 0) {
        error = "both layers need faces";
        return false;
    }
    // A layer is only compared with a mesh it may come from, and the log says when cadlod
    // has no record of that (two layers opened from files, not levels of one LOD set).
    const std::string unrelated = unrelatedBecause(current->cm, original->cm);
    if (!unrelated.empty()) {
        error = QString("\"%1\" cannot have been simplified from \"%2\": %3. Choose as Original the layer "
                        "it was simplified from (level 0 of its LOD set, or a copy made before simplifying).")
                    .arg(current->label(), original->label(), QString::fromStdString(unrelated));
        return false;
    }
    if (!sameLodSet(*current, *original))
        plugin.Log(GLLogStream::WARNING,
                   "Simplification report: \"%s\" and \"%s\" are not levels of one LOD set; cadlod has no "
                   "record that the first was simplified from the second, the report assumes it. If it was not, "
                   "choose the right Original.",
                   qUtf8Printable(current->label()), qUtf8Printable(original->label()));
    if (current->cm.fn > original->cm.fn)
        plugin.Log(GLLogStream::WARNING,
                   "Simplification report: \"%s\" has more faces (%d) than its Original \"%s\" (%d): was "
                   "it really simplified from it?",
                   qUtf8Printable(current->label()), current->cm.fn, qUtf8Printable(original->label()),
                   original->cm.fn);
    std::vector<double> distance;
    const SimplificationReport r = compareWithOriginal(original->cm, current->cm,
                                                       std::size_t(std::max(0, par.getInt("samples"))),
                                                       &distance);
    if (par.getBool("storeDistance")) {
        current->updateDataMask(MeshModel::MM_VERTQUALITY);
        for (std::size_t i = 0; i < current->cm.vert.size(); ++i)
            current->cm.vert[i].Q() = CVertexO::QualityType(distance[i]);
    }
    if (par.getBool("storeCompactness")) {
        current->updateDataMask(MeshModel::MM_FACEQUALITY);
        for (CFaceO& f : current->cm.face)
            if (!f.IsD())
                f.Q() = CFaceO::QualityType(compactness(f.cP(0), f.cP(1), f.cP(2)));
        current->updateDataMask(MeshModel::MM_FACECOLOR);
        paintFacesByCompactness(current->cm);
    }
    logReport(plugin, *current, *original, r);
    if (par.getBool("storeCompactness"))
        plugin.Log(kCompactnessPaintNote, qUtf8Printable(current->label()));
    return true;
}

}  // namespace cadlod
