// OpenFlight benchmark tool (bench/openflight/run.sh drives it and prints the table).
//   flt_bench ply N out.ply                 the N-triangle test mesh as binary PLY (for osgconv)
//   flt_bench ours N out.flt meshes|faces   write it with cadlod's writer; prints time and size
//   flt_bench ours-lodset N out.flt         an LOD set (N, N/2, N/4, N/8 triangles) with cadlod's writer
//   flt_bench osg-lodset N out.flt          the same LOD set with OpenSceneGraph's FLT writer
//   flt_bench load file.flt                 load with OpenSceneGraph; prints time, LOD nodes, triangles
// The test mesh is a wavy sheet split into 4 parts, with analytic normals: the same
// geometry for every writer.
#include "openflight/flt_writer.h"

#include <osg/Geode>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/NodeVisitor>
#include <osg/TriangleFunctor>
#include <osgDB/ReadFile>
#include <osgDB/WriteFile>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

using namespace cadlod::flt;

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// One part: the (nx x ny)-quad patch of a wavy sheet starting at column x0.
Part sheetPart(int x0, int nx, int ny, double step, const std::string& name, Rgba color)
{
    Part p;
    p.name = name;
    p.color = color;
    for (int j = 0; j <= ny; ++j)
        for (int i = x0; i <= x0 + nx; ++i) {
            const double x = step * i, y = step * j;
            p.positions.push_back({x, y, 0.3 * std::sin(x) * std::cos(y)});
            const double dx = 0.3 * std::cos(x) * std::cos(y), dy = -0.3 * std::sin(x) * std::sin(y);
            const double len = std::sqrt(dx * dx + dy * dy + 1.0);
            p.normals.push_back({float(-dx / len), float(-dy / len), float(1.0 / len)});
        }
    auto at = [nx](int i, int j) { return std::uint32_t(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            p.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            p.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return p;
}

// About `triangles` triangles over a 20 x 20 sheet, in 4 parts.
Level sheetLevel(long triangles)
{
    const int n = std::max(4, int(std::lround(std::sqrt(double(triangles) / 2.0))) / 4 * 4);
    const double step = 20.0 / n;
    const Rgba colors[4] = {{0.8f, 0.2f, 0.2f, 1}, {0.2f, 0.8f, 0.2f, 1}, {0.2f, 0.2f, 0.8f, 1}, {0.8f, 0.8f, 0.2f, 1}};
    Level level;
    for (int k = 0; k < 4; ++k)
        level.parts.push_back(sheetPart(k * n / 4, n / 4, n, step, "sheet_part_" + std::to_string(k), colors[k]));
    return level;
}

LodModel singleModel(long triangles)
{
    LodModel m;
    m.levels.push_back(sheetLevel(triangles));
    return m;
}

LodModel lodSetModel(long triangles)
{
    LodModel m;
    double out = 0;
    for (int l = 0; l < 4; ++l) {
        Level level = sheetLevel(triangles >> l);
        level.name = "lod" + std::to_string(l);
        level.switchOut = out;
        level.switchIn = out = 50.0 * (1 << l);
        level.center = {10, 10, 0};
        m.levels.push_back(std::move(level));
    }
    return m;
}

int writePly(long triangles, const std::string& path)
{
    const Level level = sheetLevel(triangles);
    std::size_t nv = 0, nf = 0;
    for (const Part& p : level.parts) {
        nv += p.positions.size();
        nf += p.triangles.size();
    }
    std::ofstream out(path, std::ios::binary);
    out << "ply\nformat binary_little_endian 1.0\nelement vertex " << nv
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\n"
           "property float nz\nelement face "
        << nf << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const Part& p : level.parts)
        for (std::size_t i = 0; i < p.positions.size(); ++i) {
            const float v[6] = {float(p.positions[i][0]), float(p.positions[i][1]), float(p.positions[i][2]),
                                p.normals[i][0], p.normals[i][1], p.normals[i][2]};
            out.write(reinterpret_cast<const char*>(v), sizeof v);
        }
    std::uint32_t base = 0;
    for (const Part& p : level.parts) {
        for (const Triangle& t : p.triangles) {
            const unsigned char three = 3;
            out.write(reinterpret_cast<const char*>(&three), 1);
            const std::int32_t idx[3] = {std::int32_t(base + t[0]), std::int32_t(base + t[1]), std::int32_t(base + t[2])};
            out.write(reinterpret_cast<const char*>(idx), sizeof idx);
        }
        base += std::uint32_t(p.positions.size());
    }
    std::printf("ply %s triangles %zu vertices %zu\n", path.c_str(), nf, nv);
    return out ? 0 : 1;
}

int writeOurs(const LodModel& model, const std::string& path, GeometryRecords records)
{
    WriteOptions o;
    o.geometry = records;
    std::string error;
    WriteStats stats;
    const auto t0 = std::chrono::steady_clock::now();
    if (!writeOpenFlightFile(path, model, o, error, &stats)) {
        std::fprintf(stderr, "%s\n", error.c_str());
        return 1;
    }
    std::printf("write_seconds %.3f bytes %zu triangles %zu bytes_per_triangle %.1f\n", secondsSince(t0),
                stats.bytes, stats.triangles, double(stats.bytes) / double(stats.triangles));
    return 0;
}

osg::ref_ptr<osg::Geode> osgGeode(const Level& level)
{
    osg::ref_ptr<osg::Geode> geode = new osg::Geode;
    for (const Part& p : level.parts) {
        osg::ref_ptr<osg::Geometry> g = new osg::Geometry;
        osg::ref_ptr<osg::Vec3Array> v = new osg::Vec3Array;
        osg::ref_ptr<osg::Vec3Array> n = new osg::Vec3Array;
        for (std::size_t i = 0; i < p.positions.size(); ++i) {
            v->push_back(osg::Vec3(float(p.positions[i][0]), float(p.positions[i][1]), float(p.positions[i][2])));
            n->push_back(osg::Vec3(p.normals[i][0], p.normals[i][1], p.normals[i][2]));
        }
        osg::ref_ptr<osg::DrawElementsUInt> tris = new osg::DrawElementsUInt(GL_TRIANGLES);
        for (const Triangle& t : p.triangles)
            tris->insert(tris->end(), t.begin(), t.end());
        g->setVertexArray(v.get());
        g->setNormalArray(n.get(), osg::Array::BIND_PER_VERTEX);
        osg::ref_ptr<osg::Vec4Array> c = new osg::Vec4Array;
        c->push_back(osg::Vec4(p.color[0], p.color[1], p.color[2], p.color[3]));
        g->setColorArray(c.get(), osg::Array::BIND_OVERALL);
        g->addPrimitiveSet(tris.get());
        geode->addDrawable(g.get());
    }
    return geode;
}

int writeOsgLodSet(const LodModel& model, const std::string& path)
{
    osg::ref_ptr<osg::Group> root = new osg::Group;
    for (const Level& level : model.levels) {
        osg::ref_ptr<osg::LOD> lod = new osg::LOD;
        lod->setCenter(osg::Vec3(float(level.center[0]), float(level.center[1]), float(level.center[2])));
        lod->addChild(osgGeode(level).get(), float(level.switchOut), float(level.switchIn));
        root->addChild(lod.get());
    }
    const auto t0 = std::chrono::steady_clock::now();
    if (!osgDB::writeNodeFile(*root, path)) {
        std::fprintf(stderr, "OpenSceneGraph could not write %s\n", path.c_str());
        return 1;
    }
    std::ifstream f(path, std::ios::binary | std::ios::ate);
    const double bytes = double(f.tellg());
    std::printf("write_seconds %.3f bytes %.0f triangles %zu bytes_per_triangle %.1f\n", secondsSince(t0), bytes,
                model.triangleCount(), bytes / double(model.triangleCount()));
    return 0;
}

struct TriangleCounter {
    std::size_t count = 0;
    void operator()(const osg::Vec3& a, const osg::Vec3& b, const osg::Vec3& c)
    {
        count += !(a == b || b == c || a == c);  // strip joints are degenerate
    }
};

class LoadStats : public osg::NodeVisitor {
public:
    LoadStats() : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN) {}
    void apply(osg::LOD& lod) override
    {
        lods += 1;
        traverse(lod);
    }
    void apply(osg::Geode& geode) override
    {
        for (unsigned i = 0; i < geode.getNumDrawables(); ++i) {
            osg::TriangleFunctor<TriangleCounter> f;
            geode.getDrawable(i)->accept(f);
            triangles += f.count;
        }
    }
    std::size_t lods = 0, triangles = 0;
};

int load(const std::string& path)
{
    const auto t0 = std::chrono::steady_clock::now();
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(path);
    const double seconds = secondsSince(t0);
    if (!node) {
        std::fprintf(stderr, "OpenSceneGraph could not read %s\n", path.c_str());
        return 1;
    }
    LoadStats s;
    node->accept(s);
    std::printf("load_seconds %.3f lod_nodes %zu triangles %zu\n", seconds, s.lods, s.triangles);
    return 0;
}

}  // namespace

int main(int argc, char** argv)
{
    const std::string cmd = argc > 1 ? argv[1] : "";
    if (cmd == "load" && argc == 3)
        return load(argv[2]);
    if (argc >= 4) {
        const long n = std::atol(argv[2]);
        const std::string out = argv[3];
        if (cmd == "ply")
            return writePly(n, out);
        if (cmd == "ours" && argc == 5)
            return writeOurs(singleModel(n), out,
                             std::strcmp(argv[4], "faces") == 0 ? GeometryRecords::Faces : GeometryRecords::Meshes);
        if (cmd == "ours-lodset")
            return writeOurs(lodSetModel(n), out, GeometryRecords::Meshes);
        if (cmd == "osg-lodset")
            return writeOsgLodSet(lodSetModel(n), out);
    }
    std::fprintf(stderr, "usage: see the comment at the top of flt_bench.cpp\n");
    return 2;
}
