// view_error FILE.flt...: the error on screen of an OpenFlight LOD model wherever the viewer
// stands (design.md §8), as OpenSceneGraph reads and draws it. On four paths, inside (a 4x4x2
// grid of points in the bounding box), walk (50 points along the longest horizontal side, 5 %
// of the diagonal outside it), approach (1x to 1000x the diagonal, log-spaced) and far (the
// approach's points from 10x the diagonal on), every LOD node picks its children by the
// distance from the eye to its centre in its own frame, as OSG's cull does. A drawn level
// switched in at s shows its error as s / n pixels, n being the distance from the eye to the
// nearest vertex of that level's own geometry (by the chain's contract the error is 1 px at s).
// Prints per path the worst and mean worst error, the triangles drawn as a share of level 0
// (with --estimate, REF's level 0) and the drawables (mean, most, and of them the cluster
// proxies); with --estimate REF, also the share the per-cluster estimate of REF's chain draws
// (cluster_estimate.h) and the ratio of the two, and the same for the estimate's cells as LOD
// nodes and for the estimate with long triangles held (with --estimate-triangles FILE, level
// 0's triangles are FILE's, the shares REF's); with --walk-csv, every walk point's figures;
// with --box, the paths are laid in that box rather than the model's own; with --breakdown N,
// the N LOD records drawing the most triangles per path; with --gaps, the gaps on screen
// (osg_view_probe.h) at points of the finest geometry, per path: the widest, the mean of each
// eye point's widest, and the share wider than the error bound (1.2 px, 5 % slack): within it
// where every drawn level keeps its error, wider where a chunk or part is missing beside its
// coarsened neighbours.
#include <osg/ComputeBoundsVisitor>
#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/MatrixTransform>
#include <osg/NodeVisitor>
#include <osg/TriangleIndexFunctor>
#include <osgDB/ReadFile>

#include <CLI/CLI.hpp>

#include "cluster_estimate.h"
#include "osg_view_probe.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace {

struct Path {
    const char* name;
    std::vector<osg::Vec3d> eyes;
};

std::vector<Path> paths(const osg::BoundingBox& box)
{
    const osg::Vec3d lo(box.xMin(), box.yMin(), box.zMin()), hi(box.xMax(), box.yMax(), box.zMax());
    const osg::Vec3d size = hi - lo, centre = (lo + hi) * 0.5;
    const double diagonal = size.length();
    Path inside{"inside", {}}, walk{"walk", {}}, approach{"approach", {}}, far{"far", {}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 2; ++k)
                inside.eyes.push_back(lo + osg::Vec3d(size.x() * (i + 0.5) / 4, size.y() * (j + 0.5) / 4,
                                                      size.z() * (k + 0.5) / 2));
    const bool alongX = size.x() >= size.y();
    for (int i = 0; i < 50; ++i) {
        const double t = (i + 0.5) / 50;
        walk.eyes.push_back(alongX ? osg::Vec3d(lo.x() + t * size.x(), lo.y() - 0.05 * diagonal, centre.z())
                                   : osg::Vec3d(lo.x() - 0.05 * diagonal, lo.y() + t * size.y(), centre.z()));
    }
    osg::Vec3d direction(-0.3, -1, 0.4);
    direction.normalize();
    for (int i = 0; i < 30; ++i) {
        const double distance = diagonal * std::pow(1000.0, i / 29.0);
        approach.eyes.push_back(centre + direction * distance);
        if (distance >= 10 * diagonal)
            far.eyes.push_back(approach.eyes.back());
    }
    return {inside, walk, approach, far};
}

// Where the walk's rows go: one per eye point and measured file.
class WalkCsv {
public:
    bool open(const std::string& path)
    {
        file_ = std::fopen(path.c_str(), "w");
        if (file_)
            std::fputs("file,index,x,y,z,triangles_share,worst_px,drawables,estimate_share,held_estimate_share\n",
                       file_);
        return file_ != nullptr;
    }
    ~WalkCsv()
    {
        if (file_)
            std::fclose(file_);
    }
    bool isOpen() const { return file_ != nullptr; }

    // `estimate`: the estimate's share and the held estimate's, or null without --estimate.
    void row(const std::string& model, std::size_t index, const osg::Vec3d& eye, double share,
             const cadlod::test::OsgView& frame, const std::pair<double, double>* estimate)
    {
        std::fprintf(file_, "%s,%zu,%.9g,%.9g,%.9g,%.6f,%.4f,%zu,", quoted(model).c_str(), index, eye.x(),
                     eye.y(), eye.z(), share, frame.worstApparentPx, frame.drawables);
        if (estimate)
            std::fprintf(file_, "%.6f,%.6f", estimate->first, estimate->second);
        else
            std::fputc(',', file_);
        std::fputc('\n', file_);
    }

private:
    static std::string quoted(const std::string& field)
    {
        if (field.find_first_of(",\"\n") == std::string::npos)
            return field;
        std::string out = "\"";
        for (char c : field)
            out += c == '"' ? std::string("\"\"") : std::string(1, c);
        return out + "\"";
    }

    std::FILE* file_ = nullptr;
};

struct PathTotals {
    double worst = 0, meanWorst = 0, share = 0, drawables = 0, mostDrawables = 0, proxyDrawables = 0, estimate = 0,
           nodeEstimate = 0, heldEstimate = 0, widestGap = 0, meanGap = 0, widerGaps = 0;
    std::map<std::string, double> trianglesByLevel;  // summed over the path's eye points
};

// How many points of the finest geometry the gaps are measured at, and the gap counted as
// too wide: the error bound (the one lib/lod/nearest_point.h keeps) with the 5 % sampling slack.
constexpr std::size_t kGapSamples = 20000;
constexpr double kWideGapPx = kErrorBoundPx * 1.05;

struct Model {
    std::string file;
    std::unique_ptr<cadlod::test::OsgViewProbe> osg;
    double levelZero = 1;
    std::unique_ptr<ClusterGrid> clusters;  // only with --estimate
    std::vector<cadlod::test::Point3> gapSamples;  // only with --gaps
    cadlod::test::OsgGapQuery gaps;
};

PathTotals measurePath(const Model& model, const Path& path, WalkCsv* walkCsv)
{
    PathTotals totals;
    for (std::size_t i = 0; i < path.eyes.size(); ++i) {
        const osg::Vec3d& eye = path.eyes[i];
        const cadlod::test::OsgView f =
            model.osg->drawFrom({eye.x(), eye.y(), eye.z()}, model.gapSamples.empty() ? nullptr : &model.gaps);
        const double share = double(f.triangles) / model.levelZero;
        const double estimate = model.clusters ? model.clusters->share(eye) : 0;
        const double heldEstimate = model.clusters ? model.clusters->heldShare(eye) : 0;
        totals.worst = std::max(totals.worst, f.worstApparentPx);
        totals.meanWorst += f.worstApparentPx;
        totals.share += share;
        totals.drawables += double(f.drawables);
        totals.mostDrawables = std::max(totals.mostDrawables, double(f.drawables));
        totals.proxyDrawables += double(f.proxyDrawables);
        totals.estimate += estimate;
        totals.nodeEstimate += model.clusters ? model.clusters->nodeShare(eye) : 0;
        totals.heldEstimate += heldEstimate;
        if (!model.gapSamples.empty()) {
            const cadlod::test::OsgGaps& gaps = f.gaps;
            totals.widestGap = std::max(totals.widestGap, gaps.widestPx);
            totals.meanGap += gaps.widestPx;
            totals.widerGaps += double(gaps.wider) / double(model.gapSamples.size());
        }
        for (const auto& [level, triangles] : f.trianglesByLevel)
            totals.trianglesByLevel[level] += double(triangles);
        if (walkCsv) {
            const std::pair<double, double> estimates{estimate, heldEstimate};
            walkCsv->row(model.file, i, eye, share, f, model.clusters ? &estimates : nullptr);
        }
    }
    return totals;
}

void printPath(const Model& model, const Path& path, const PathTotals& totals)
{
    const double n = double(path.eyes.size());
    std::printf("%s %s worst_px %.2f mean_worst_px %.2f triangles_share %.4f drawables_mean %.0f drawables_max %.0f "
                "proxies_mean %.0f",
                model.file.c_str(), path.name, totals.worst, totals.meanWorst / n, totals.share / n,
                totals.drawables / n, totals.mostDrawables, totals.proxyDrawables / n);
    if (model.clusters)
        std::printf(" estimate_share %.4f ratio_to_estimate %.4f node_estimate_share %.4f ratio_to_node_estimate %.4f",
                    totals.estimate / n, totals.estimate > 0 ? totals.share / totals.estimate : 0.0,
                    totals.nodeEstimate / n, totals.nodeEstimate > 0 ? totals.share / totals.nodeEstimate : 0.0);
    if (model.clusters)
        std::printf(" held_estimate_share %.4f ratio_to_held_estimate %.4f", totals.heldEstimate / n,
                    totals.heldEstimate > 0 ? totals.share / totals.heldEstimate : 0.0);
    if (!model.gapSamples.empty())
        std::printf(" widest_gap_px %.2f mean_widest_gap_px %.2f wide_gap_share %.6f", totals.widestGap,
                    totals.meanGap / n, totals.widerGaps / n);
    std::printf("\n");
}

// The LOD records that draw the most triangles on the path, by their mean per eye point.
void printBreakdown(const Model& model, const Path& path, const PathTotals& totals, std::size_t most)
{
    std::vector<std::pair<double, std::string>> levels;
    for (const auto& [level, triangles] : totals.trianglesByLevel)
        levels.emplace_back(triangles / double(path.eyes.size()), level);
    std::sort(levels.rbegin(), levels.rend());
    levels.resize(std::min(levels.size(), most));
    for (const auto& [triangles, level] : levels)
        std::printf("  %s %s %.0f triangles (%.4f of level 0) in \"%s\"\n", model.file.c_str(), path.name, triangles,
                    triangles / model.levelZero, level.c_str());
}

// The model's box as OSG bounds it, unless --box gave one: OSG bounds a transformed subgraph
// by its transformed box corners, which overshoots for rotated parts, so two files of the
// same model (one node, HLOD) share their paths only through a box given to both.
osg::BoundingBox boxOf(const cadlod::test::OsgViewProbe& probe, const std::vector<double>& given)
{
    if (given.size() == 6)
        return osg::BoundingBox(given[0], given[1], given[2], given[3], given[4], given[5]);
    const auto box = probe.bounds();
    return osg::BoundingBox(box[0][0], box[0][1], box[0][2], box[1][0], box[1][1], box[1][2]);
}

int measure(const std::string& file, const ReferenceChain* reference, const std::vector<double>& givenBox,
            double gapPixelRadians, std::size_t breakdown, WalkCsv& walkCsv)
{
    Model model;
    model.file = file;
    model.osg = std::make_unique<cadlod::test::OsgViewProbe>(file, "");
    if (!model.osg->loaded()) {
        std::fprintf(stderr, "view_error: OpenSceneGraph could not read %s\n", file.c_str());
        return 1;
    }
    model.levelZero = double(std::max<std::size_t>(1, model.osg->finestTriangles()));
    const osg::BoundingBox bounds = boxOf(*model.osg, givenBox);
    if (reference) {
        // The same model's level 0 for both: a file that cut its finest triangles into pieces
        // draws a share of the triangles the model has, not of its pieces.
        model.clusters = std::make_unique<ClusterGrid>(*reference, bounds);
        model.levelZero = double(std::max<std::size_t>(1, model.clusters->levelZero()));
    }
    if (gapPixelRadians > 0) {
        model.gapSamples = model.osg->finestSamples(kGapSamples);
        model.gaps = {&model.gapSamples, gapPixelRadians, kWideGapPx};
    }
    for (const Path& path : paths(bounds)) {
        const bool isWalk = std::string(path.name) == "walk";
        const PathTotals totals = measurePath(model, path, isWalk && walkCsv.isOpen() ? &walkCsv : nullptr);
        printPath(model, path, totals);
        printBreakdown(model, path, totals, breakdown);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    CLI::App app{"The error on screen of OpenFlight LOD models wherever the viewer stands"};
    std::vector<std::string> files;
    std::string estimateFile, walkCsvFile;
    std::string boxText;
    app.add_option("files", files, "OpenFlight files to measure")->required();
    app.add_option("--estimate", estimateFile,
                   "a one-LOD-node chain of the same model: compare with its per-cluster estimate");
    std::string estimateTrianglesFile;
    app.add_option("--estimate-triangles", estimateTrianglesFile,
                   "with --estimate: where level 0's triangles lie, from this file's finest levels, the shares "
                   "still from --estimate's chain (a model whose own one-node chain is too large to build, "
                   "against the chain of a part of it)");
    app.add_option("--walk-csv", walkCsvFile, "write one row per walk eye point and file");
    app.add_option("--box", boxText, "X0,Y0,Z0,X1,Y1,Z1: the box the paths are laid in, instead of the model's");
    bool gaps = false;
    double fovY = 45.0, viewport = 1080.0;
    app.add_flag("--gaps", gaps, "also the widest gap on screen per path");
    std::size_t breakdown = 0;
    app.add_option("--breakdown", breakdown, "also the N LOD records drawing the most triangles per path");
    app.add_option("--fov-y", fovY, "with --gaps: the vertical field of view the model was built for, degrees")
        ->capture_default_str();
    app.add_option("--viewport", viewport, "with --gaps: the viewport height it was built for, pixels")
        ->capture_default_str();
    CLI11_PARSE(app, argc, argv);

    ReferenceChain reference;
    std::string error;
    if (!estimateFile.empty() && !readReferenceChain(estimateFile, reference, error)) {
        std::fprintf(stderr, "view_error: %s\n", error.c_str());
        return 1;
    }
    if (!estimateTrianglesFile.empty()) {
        ReferenceChain triangles;
        if (estimateFile.empty() || !readReferenceChain(estimateTrianglesFile, triangles, error)) {
            std::fprintf(stderr, "view_error: %s\n",
                         estimateFile.empty() ? "--estimate-triangles needs --estimate" : error.c_str());
            return 1;
        }
        reference.finestCentroids = std::move(triangles.finestCentroids);
        reference.finestRadii = std::move(triangles.finestRadii);
        reference.finestSideMidpoints = std::move(triangles.finestSideMidpoints);
    }
    std::vector<double> box(6);
    if (!boxText.empty() && std::sscanf(boxText.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &box[0], &box[1], &box[2],
                                        &box[3], &box[4], &box[5]) != 6) {
        std::fprintf(stderr, "view_error: --box wants X0,Y0,Z0,X1,Y1,Z1\n");
        return 2;
    }
    if (boxText.empty())
        box.clear();
    WalkCsv walkCsv;
    if (!walkCsvFile.empty() && !walkCsv.open(walkCsvFile)) {
        std::fprintf(stderr, "view_error: cannot write %s\n", walkCsvFile.c_str());
        return 1;
    }
    const double pixelRadians = gaps ? 2 * std::tan(fovY * M_PI / 360) / viewport : 0.0;
    int rc = 0;
    for (const std::string& file : files)
        rc |= measure(file, estimateFile.empty() ? nullptr : &reference, box, pixelRadians, breakdown, walkCsv);
    return rc;
}
