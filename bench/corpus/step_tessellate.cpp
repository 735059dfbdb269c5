// step_tessellate IN.(step|stp|iges|igs|brep) OUT.ply [--deviation D] [--angular DEG]
// Tessellates a CAD model with OCCT's BRepMesh the way FreeCAD's mesh export (and so
// KiCad StepUp's VRML) does: linear deflection = (dx + dy + dz) / 300 * D of the model's
// bounding box (FreeCAD's "deviation", default 0.5), angular deflection DEG (default 28.5).
// Writes one binary little-endian PLY: float x y z per vertex, triangles with an int
// "part" face property (the solid index, in the order OCCT lists the solids; faces outside
// any solid get the next ids, one per shell or free face group). Vertices are welded
// within each solid only, at positions equal to 1e-7 of the bounding-box diagonal.
// Prints: triangles, vertices, parts, boundary edges.
#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Reader.hxx>
#include <Poly_Triangulation.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace {

std::string lower(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

bool readShape(const std::string& path, TopoDS_Shape& shape)
{
    const std::string ext = lower(path.substr(path.find_last_of('.') + 1));
    if (ext == "step" || ext == "stp") {
        STEPControl_Reader reader;
        if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
            return false;
        reader.TransferRoots();
        shape = reader.OneShape();
    } else if (ext == "iges" || ext == "igs") {
        IGESControl_Reader reader;
        if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
            return false;
        reader.TransferRoots();
        shape = reader.OneShape();
    } else if (ext == "brep") {
        BRep_Builder builder;
        if (!BRepTools::Read(shape, path.c_str(), builder))
            return false;
    } else {
        return false;
    }
    return !shape.IsNull();
}

struct Mesh {
    std::vector<std::array<float, 3>> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::int32_t> parts;
};

// Appends the triangulations of every face of `group` (welded among themselves).
void addGroup(const TopoDS_Shape& group, int part, double weldStep, Mesh& out)
{
    std::map<std::tuple<long long, long long, long long>, std::uint32_t> welded;
    for (TopExp_Explorer ex(group, TopAbs_FACE); ex.More(); ex.Next()) {
        const TopoDS_Face& face = TopoDS::Face(ex.Current());
        TopLoc_Location loc;
        const Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
        if (tri.IsNull())
            continue;
        const gp_Trsf trsf = loc.Transformation();
        std::vector<std::uint32_t> index(tri->NbNodes() + 1);
        for (int i = 1; i <= tri->NbNodes(); ++i) {
            const gp_Pnt p = tri->Node(i).Transformed(trsf);
            const auto key = std::make_tuple(std::llround(p.X() / weldStep), std::llround(p.Y() / weldStep),
                                             std::llround(p.Z() / weldStep));
            const auto found = welded.find(key);
            if (found != welded.end()) {
                index[i] = found->second;
            } else {
                index[i] = std::uint32_t(out.vertices.size());
                welded.emplace(key, index[i]);
                out.vertices.push_back({float(p.X()), float(p.Y()), float(p.Z())});
            }
        }
        const bool reversed = face.Orientation() == TopAbs_REVERSED;
        for (int t = 1; t <= tri->NbTriangles(); ++t) {
            int a, b, c;
            tri->Triangle(t).Get(a, b, c);
            if (reversed)
                std::swap(b, c);
            const std::array<std::uint32_t, 3> v{index[a], index[b], index[c]};
            if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
                continue;
            out.triangles.push_back(v);
            out.parts.push_back(part);
        }
    }
}

bool writePly(const std::string& path, const Mesh& m)
{
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (!f)
        return false;
    std::fprintf(f,
                 "ply\nformat binary_little_endian 1.0\ncomment made by cadlod bench/corpus/step_tessellate\n"
                 "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
                 "element face %zu\nproperty list uchar int vertex_indices\nproperty int part\nend_header\n",
                 m.vertices.size(), m.triangles.size());
    bool ok = true;
    for (const auto& v : m.vertices)
        ok = ok && std::fwrite(v.data(), sizeof(float), 3, f) == 3;
    for (std::size_t t = 0; t < m.triangles.size() && ok; ++t) {
        unsigned char rec[1 + 4 * 4];
        rec[0] = 3;
        std::int32_t ints[4] = {std::int32_t(m.triangles[t][0]), std::int32_t(m.triangles[t][1]),
                                std::int32_t(m.triangles[t][2]), m.parts[t]};
        std::memcpy(rec + 1, ints, sizeof ints);
        ok = std::fwrite(rec, 1, sizeof rec, f) == sizeof rec;
    }
    return std::fclose(f) == 0 && ok;
}

std::size_t boundaryEdges(const Mesh& m)
{
    std::vector<std::uint64_t> edges;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t a = t[k], b = t[(k + 1) % 3];
            edges.push_back(std::min(a, b) << 32 | std::max(a, b));
        }
    std::sort(edges.begin(), edges.end());
    std::size_t boundary = 0;
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j] == edges[i])
            ++j;
        boundary += (j - i) == 1;
        i = j;
    }
    return boundary;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: step_tessellate IN.(step|stp|iges|igs|brep) OUT.ply [--deviation D] [--angular DEG]\n");
        return 2;
    }
    const std::string in = argv[1], outPath = argv[2];
    double deviation = 0.5, angularDeg = 28.5;
    for (int i = 3; i + 1 < argc; i += 2) {
        const std::string key = argv[i];
        if (key == "--deviation")
            deviation = std::stod(argv[i + 1]);
        else if (key == "--angular")
            angularDeg = std::stod(argv[i + 1]);
        else {
            std::fprintf(stderr, "unknown option %s\n", key.c_str());
            return 2;
        }
    }
    TopoDS_Shape shape;
    if (!readShape(in, shape)) {
        std::fprintf(stderr, "%s: cannot read\n", in.c_str());
        return 1;
    }
    Bnd_Box box;
    BRepBndLib::Add(shape, box);
    if (box.IsVoid()) {
        std::fprintf(stderr, "%s: empty shape\n", in.c_str());
        return 1;
    }
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    const double linear = ((x1 - x0) + (y1 - y0) + (z1 - z0)) / 300.0 * deviation;
    BRepMesh_IncrementalMesh mesher(shape, linear, Standard_False, angularDeg * M_PI / 180.0, Standard_False);
    const double diagonal = std::sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0) + (z1 - z0) * (z1 - z0));
    const double weldStep = std::max(1e-12, 1e-7 * diagonal);

    Mesh mesh;
    int part = 0;
    for (TopExp_Explorer ex(shape, TopAbs_SOLID); ex.More(); ex.Next())
        addGroup(ex.Current(), part++, weldStep, mesh);
    for (TopExp_Explorer ex(shape, TopAbs_SHELL, TopAbs_SOLID); ex.More(); ex.Next())
        addGroup(ex.Current(), part++, weldStep, mesh);
    {
        // Free faces (in no shell): one more group.
        BRep_Builder builder;
        TopoDS_Compound loose;
        builder.MakeCompound(loose);
        bool any = false;
        for (TopExp_Explorer ex(shape, TopAbs_FACE, TopAbs_SHELL); ex.More(); ex.Next()) {
            builder.Add(loose, ex.Current());
            any = true;
        }
        if (any)
            addGroup(loose, part++, weldStep, mesh);
    }
    if (mesh.triangles.empty()) {
        std::fprintf(stderr, "%s: no triangles\n", in.c_str());
        return 1;
    }
    if (!writePly(outPath, mesh)) {
        std::fprintf(stderr, "%s: cannot write\n", outPath.c_str());
        return 1;
    }
    std::printf("%zu triangles, %zu vertices, %d parts, %zu boundary edges\n", mesh.triangles.size(),
                mesh.vertices.size(), part, boundaryEdges(mesh));
    return 0;
}
