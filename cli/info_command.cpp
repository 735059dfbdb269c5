// cadlod info IN: format, parts, triangles, bounding box, a units guess and, for .flt, the
// LOD levels with their ranges.
#include "cli_options.h"
#include "commands.h"
#include "input_losses.h"
#include "mesh_files.h"
#include "progress_bar.h"

#include "measure/hausdorff.h"

#include <cmath>
#include <map>
#include <cstdio>
#include <memory>

namespace cadlod::cli {
namespace {

// CAD exports are usually in mm: an assembly a few hundred units across is likely mm.
const char* unitsGuess(double diagonal)
{
    if (diagonal > 20.0)
        return "mm likely (use --unit mm)";
    if (diagonal > 2.0)
        return "cm, in or m";
    return "m likely";
}

void printFltLevels(const std::string& path)
{
    const flt::LodModel model = readFlt(path);
    std::printf("units        %s (header)\nLOD levels   %zu\n", flt::unitsName(model.units), model.levels.size());
    for (std::size_t k = 0; k < model.levels.size(); ++k) {
        const flt::Level& l = model.levels[k];
        std::printf("  level %zu: %zu triangles, %zu parts, switch out %.6g, in %.6g\n", k, l.triangleCount(),
                    l.parts.size(), l.switchOut, l.switchIn);
    }
}

struct AssemblyCounts {
    std::size_t distinct = 0, shared = 0, placements = 0, mirrored = 0, placedTriangles = 0, distinctTriangles = 0;
    vcg::Box3d box;
};

AssemblyCounts countAssembly(const vrml::Scene& scene)
{
    AssemblyCounts c;
    const std::vector<vrml::Placement> placements = vrml::flattenPlacements(scene.assembly, "");
    std::map<std::size_t, std::size_t> uses;
    for (const vrml::Placement& p : placements) {
        const vrml::Geometry& g = scene.assembly.geometries[p.geometry];
        ++uses[p.geometry];
        c.mirrored += p.mirrored();
        c.placedTriangles += g.triangleCount();
        for (const vrml::Part& part : g.parts)
            for (const auto& v : part.positions) {
                const vrml::Vec3 w = p.matrix.transformPoint({v[0], v[1], v[2]});
                c.box.Add(vcg::Point3d(w.x, w.y, w.z));
            }
    }
    c.placements = placements.size();
    c.distinct = uses.size();
    for (const auto& [g, n] : uses) {
        c.shared += n > 1;
        c.distinctTriangles += scene.assembly.geometries[g].triangleCount();
    }
    return c;
}

// An assembly that shares parts: what is distinct, what is placed.
void printAssembly(const std::string& path, const vrml::Scene& scene)
{
    const AssemblyCounts c = countAssembly(scene);
    std::printf("file         %s\nformat       VRML, an assembly that shares parts\n", path.c_str());
    std::printf("parts        %zu distinct, %zu of them placed more than once\n", c.distinct, c.shared);
    std::printf("placements   %zu (%zu mirrored)\n", c.placements, c.mirrored);
    std::printf("instances    %zu placements of shared parts\n", c.placements - (c.distinct - c.shared));
    std::printf("triangles    %zu placed, %zu distinct\n", c.placedTriangles, c.distinctTriangles);
    std::printf("bbox         (%.6g %.6g %.6g) .. (%.6g %.6g %.6g), diagonal %.6g\n", c.box.min[0], c.box.min[1],
                c.box.min[2], c.box.max[0], c.box.max[1], c.box.max[2], c.box.Diag());
    std::printf("units guess  %s\n", unitsGuess(c.box.Diag()));
}

void runInfo(const std::string& path)
{
    progress::enable(false);
    CoreMesh m;
    ImportSettings settings;
    settings.allowPartial = true;  // shows what can be read; the losses are listed as warnings
    settings.keepInstances = true;
    vrml::Scene assembly;
    const LoadedMesh loaded = loadMesh(path, m, settings, &assembly);
    if (loaded.placements > 0) {
        printAssembly(path, assembly);
        return;
    }
    const vcg::Box3d box = liveVertexBox(m);
    std::printf("file         %s\nformat       %s\nparts        %zu\ntriangles    %d\nvertices     %d\n", path.c_str(),
                formatName(loaded.format), loaded.parts, m.fn, m.vn);
    std::printf("bbox         (%.6g %.6g %.6g) .. (%.6g %.6g %.6g), diagonal %.6g\n", box.min[0], box.min[1],
                box.min[2], box.max[0], box.max[1], box.max[2], box.Diag());
    if (loaded.format == InputFormat::OpenFlight)
        printFltLevels(path);
    else if (loaded.kicadUnitApplied)
        std::printf("units        %s, scaled to metres\n", loaded.unit.describe().c_str());
    else
        std::printf("units guess  %s\n", unitsGuess(box.Diag()));
    if (!geometryLosses(loaded.findings).empty())
        std::printf("incomplete   %zu finding(s) lost geometry (see the warnings)\n",
                    geometryLosses(loaded.findings).size());
}

}  // namespace

void addInfoCommand(CLI::App& app)
{
    auto path = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("info", "What a file holds");
    cmd->add_option("input", *path, "Input file")->required();
    cmd->callback([path] { runInfo(*path); });
}

}  // namespace cadlod::cli
