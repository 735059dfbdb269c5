// Writes a CAD-like VRML97 file of about the requested size: an assembly of DEF'd part
// Transforms, each a finely tessellated revolved body (one IndexedFaceSet with a
// DEF'd Coordinate and per-vertex normals, KiCad/FreeCAD style) followed by a few
// CATIA-style face Shapes that USE the same Coordinate, materials DEF'd and USE'd.
// Numbers are written with 6 decimals like real exporters.
//   gen_cad_vrml OUT.wrl SIZE_MB
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

struct Writer {
    FILE* f;
    size_t bytes = 0;
    void put(const char* s)
    {
        bytes += std::fputs(s, f) >= 0 ? std::string(s).size() : 0;
    }
    void printf(const char* fmt, double a, double b, double c)
    {
        char buf[128];
        const int n = std::snprintf(buf, sizeof buf, fmt, a, b, c);
        std::fwrite(buf, 1, size_t(n), f);
        bytes += size_t(n);
    }
    void index(long a, long b, long c, long d)
    {
        char buf[96];
        const int n = std::snprintf(buf, sizeof buf, "%ld,%ld,%ld,%ld,-1,", a, b, c, d);
        std::fwrite(buf, 1, size_t(n), f);
        bytes += size_t(n);
    }
};

void writePart(Writer& w, int part, int rings, int segments)
{
    const double x0 = (part % 20) * 30.0, y0 = (part / 20 % 20) * 30.0, z0 = (part / 400) * 30.0;
    static const char* colors[] = {"0.7 0.7 0.75", "0.8 0.2 0.1", "0.2 0.3 0.8", "0.1 0.6 0.2"};
    char material[160];
    if (part < 4)  // the first parts DEF the materials, later ones USE them
        std::snprintf(material, sizeof material,
                      "DEF MAT_%d Material { diffuseColor %s specularColor 0.5 0.5 0.5 shininess 0.4 }", part,
                      colors[part]);
    else
        std::snprintf(material, sizeof material, "USE MAT_%d", part % 4);
    char head[512];
    std::snprintf(head, sizeof head,
                  "DEF Part_%d Transform {\n translation %g %g %g\n rotation 0 0 1 %g\n children [\n"
                  "  Shape {\n   appearance Appearance { material %s }\n"
                  "   geometry IndexedFaceSet {\n    creaseAngle 0.5\n    coord DEF COORD_%d Coordinate { point [",
                  part, x0, y0, z0, 0.01 * part, material, part);
    w.put(head);
    const double length = 20.0, radius = 5.0;
    for (int r = 0; r < rings; ++r) {
        const double t = double(r) / (rings - 1);
        const double rad = radius * (1.0 + 0.2 * std::sin(6.28318 * 3 * t));
        for (int s = 0; s < segments; ++s) {
            const double a = 6.283185307179586 * s / segments;
            w.printf("%.6f %.6f %.6f,", rad * std::cos(a), rad * std::sin(a), length * t);
        }
        w.put("\n");
    }
    w.put("] }\n    normal Normal { vector [");
    for (int r = 0; r < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            const double a = 6.283185307179586 * s / segments;
            w.printf("%.6f %.6f %.6f,", std::cos(a), std::sin(a), 0.0);
        }
        w.put("\n");
    }
    w.put("] }\n    coordIndex [");
    for (int r = 0; r + 1 < rings - 1; ++r) {
        for (int s = 0; s < segments; ++s) {
            const long a = long(r) * segments + s, b = long(r) * segments + (s + 1) % segments;
            w.index(a, b, b + segments, a + segments);
        }
        w.put("\n");
    }
    w.put("]\n   }\n  }\n");
    // The last ring band as CATIA-style face Shapes sharing the Coordinate, no normals.
    for (int s = 0; s < segments; s += segments / 4) {
        w.put("  Shape { appearance Appearance { material USE MAT_0 } geometry IndexedFaceSet { coord USE ");
        char ref[64];
        std::snprintf(ref, sizeof ref, "COORD_%d coordIndex [", part);
        w.put(ref);
        for (int k = s; k < s + segments / 4 && k < segments; ++k) {
            const long r = rings - 2;
            const long a = r * segments + k, b = r * segments + (k + 1) % segments;
            w.index(a, b, b + segments, a + segments);
        }
        w.put("] } }\n");
    }
    w.put(" ]\n}\n");
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s OUT.wrl SIZE_MB\n", argv[0]);
        return 2;
    }
    Writer w{std::fopen(argv[1], "wb")};
    if (!w.f) {
        std::perror(argv[1]);
        return 1;
    }
    const size_t target = size_t(std::atof(argv[2]) * 1e6);
    w.put("#VRML V2.0 utf8\n# cadlod benchmark: generated CAD-like assembly\n");
    w.put("WorldInfo { title \"generated assembly\" }\n");
    w.put("Group { children [\n");
    for (int part = 0; w.bytes < target; ++part) writePart(w, part, 120, 96);
    w.put("] }\n");
    std::fclose(w.f);
    std::printf("%s: %.1f MB\n", argv[1], w.bytes / 1e6);
    return 0;
}
