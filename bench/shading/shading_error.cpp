// Shading error: see shading_error.h for what is rendered and counted.
#include "shading_error.h"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>

namespace cadlod::shading {

namespace {

using Vec3 = std::array<double, 3>;

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 scale(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 cross(const Vec3& a, const Vec3& b)
{
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 normalized(const Vec3& a)
{
    const double l = std::sqrt(dot(a, a));
    return l > 0 ? scale(a, 1.0 / l) : Vec3{0, 0, 0};
}

Vec3 vertex(const MeshRef& m, std::uint32_t i) { return {m.xyz[3 * i], m.xyz[3 * i + 1], m.xyz[3 * i + 2]}; }

bool validTriangle(const MeshRef& m, std::size_t f)
{
    const std::uint32_t* t = m.tri + 3 * f;
    return t[0] < m.vertexCount && t[1] < m.vertexCount && t[2] < m.vertexCount;
}

// Union-find over corners.
std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x)
{
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

void unite(std::vector<std::uint32_t>& parent, std::uint32_t a, std::uint32_t b)
{
    a = findRoot(parent, a);
    b = findRoot(parent, b);
    if (a != b)  // the smaller index becomes the root: deterministic
        parent[std::max(a, b)] = std::min(a, b);
}

}  // namespace

// Unit normal per corner (3 per triangle, as float xyz): area-weighted face normals summed
// over the corner's smooth fan, fans split at edges whose dihedral exceeds the crease angle.
std::vector<float> cornerNormals(MeshRef m, double creaseDegrees)
{
    const std::size_t nf = m.triangleCount;
    // Weld vertices at identical positions.
    std::vector<std::uint32_t> order(m.vertexCount);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        const double* pa = m.xyz + 3 * a;
        const double* pb = m.xyz + 3 * b;
        if (pa[0] != pb[0]) return pa[0] < pb[0];
        if (pa[1] != pb[1]) return pa[1] < pb[1];
        if (pa[2] != pb[2]) return pa[2] < pb[2];
        return a < b;
    });
    std::vector<std::uint32_t> weld(m.vertexCount);
    for (std::size_t i = 0; i < order.size(); ++i) {
        const bool same = i > 0 && std::equal(m.xyz + 3 * order[i], m.xyz + 3 * order[i] + 3, m.xyz + 3 * order[i - 1]);
        weld[order[i]] = same ? weld[order[i - 1]] : order[i];
    }

    std::vector<Vec3> faceArea(nf);  // cross product: normal times twice the area
    std::vector<Vec3> faceUnit(nf);
    for (std::size_t f = 0; f < nf; ++f) {
        if (!validTriangle(m, f))
            continue;
        const std::uint32_t* t = m.tri + 3 * f;
        const Vec3 a = vertex(m, t[0]);
        faceArea[f] = cross(sub(vertex(m, t[1]), a), sub(vertex(m, t[2]), a));
        faceUnit[f] = normalized(faceArea[f]);
    }

    struct EdgeUse {
        std::uint64_t key;
        std::uint32_t face;
        std::uint8_t corner;  // the edge runs from this corner to the next
    };
    std::vector<EdgeUse> edges;
    edges.reserve(3 * nf);
    for (std::size_t f = 0; f < nf; ++f) {
        if (!validTriangle(m, f))
            continue;
        for (int k = 0; k < 3; ++k) {
            const std::uint64_t a = weld[m.tri[3 * f + k]], b = weld[m.tri[3 * f + (k + 1) % 3]];
            if (a == b)
                continue;
            edges.push_back({std::min(a, b) << 32 | std::max(a, b), std::uint32_t(f), std::uint8_t(k)});
        }
    }
    std::sort(edges.begin(), edges.end(), [](const EdgeUse& x, const EdgeUse& y) {
        return x.key != y.key ? x.key < y.key : x.face != y.face ? x.face < y.face : x.corner < y.corner;
    });

    std::vector<std::uint32_t> parent(3 * nf);
    std::iota(parent.begin(), parent.end(), 0u);
    const double cosCrease = std::cos(creaseDegrees * M_PI / 180.0);
    auto cornerAt = [&](std::uint32_t f, std::uint32_t weldedVertex) {
        for (std::uint32_t k = 0; k < 3; ++k)
            if (weld[m.tri[3 * f + k]] == weldedVertex)
                return 3 * f + k;
        return 3 * f;  // not reached
    };
    for (std::size_t i = 0; i < edges.size();) {
        std::size_t j = i;
        while (j < edges.size() && edges[j].key == edges[i].key)
            ++j;
        if (j - i == 2) {  // manifold edge: one fan across it when the dihedral is small
            const EdgeUse& e0 = edges[i];
            const EdgeUse& e1 = edges[i + 1];
            if (dot(faceUnit[e0.face], faceUnit[e1.face]) >= cosCrease) {
                const std::uint32_t a = std::uint32_t(e0.key >> 32), b = std::uint32_t(e0.key & 0xffffffffu);
                unite(parent, cornerAt(e0.face, a), cornerAt(e1.face, a));
                unite(parent, cornerAt(e0.face, b), cornerAt(e1.face, b));
            }
        }
        i = j;
    }

    std::vector<Vec3> sum(3 * nf, Vec3{0, 0, 0});
    for (std::uint32_t c = 0; c < 3 * nf; ++c) {
        const std::uint32_t r = findRoot(parent, c);
        sum[r] = add(sum[r], faceArea[c / 3]);
    }
    std::vector<float> normals(9 * nf);
    for (std::uint32_t c = 0; c < 3 * nf; ++c) {
        Vec3 n = normalized(sum[findRoot(parent, c)]);
        if (dot(n, n) == 0)
            n = faceUnit[c / 3];
        for (int k = 0; k < 3; ++k)
            normals[3 * c + k] = float(n[k]);
    }
    return normals;
}

namespace {

struct Camera {
    Vec3 forward, right, up;  // forward: from the camera into the scene
    Vec3 key, fill;           // unit directions towards the lights
};

struct Frame {
    Vec3 center{0, 0, 0};
    double radius = 1;
};

// One view's image: intensity (0..255) per pixel, -1 where nothing is drawn.
using Image = std::vector<std::int16_t>;

constexpr std::int64_t kSub = 256;  // sub-pixel steps of the fixed-point rasterizer

// Renders mesh `m` (with its corner normals) from `cam`. Rows bottom-up.
Image render(const MeshRef& m, const std::vector<float>& normals, const Camera& cam, const Frame& frame, int n)
{
    const std::size_t nv = m.vertexCount;
    std::vector<std::int64_t> sx(nv), sy(nv);
    std::vector<double> sz(nv);
    std::vector<std::uint8_t> far(nv, 0);
    const double toPixels = n / (2.0 * frame.radius);
    const double limit = 64.0 * n;  // farther out than 64 viewports: not rasterized
    for (std::size_t v = 0; v < nv; ++v) {
        const Vec3 d = sub(vertex(m, std::uint32_t(v)), frame.center);
        const double x = (dot(d, cam.right) * toPixels + n / 2.0);
        const double y = (dot(d, cam.up) * toPixels + n / 2.0);
        if (!(std::abs(x) < limit && std::abs(y) < limit)) {
            far[v] = 1;
            continue;
        }
        sx[v] = std::llround(x * kSub);
        sy[v] = std::llround(y * kSub);
        sz[v] = dot(d, cam.forward);
    }

    const std::size_t pixels = std::size_t(n) * n;
    std::vector<double> depth(pixels, std::numeric_limits<double>::infinity());
    std::vector<std::int32_t> id(pixels, -1);
    const std::int64_t maxCoord = std::int64_t(n) * kSub;
    for (std::size_t f = 0; f < m.triangleCount; ++f) {
        if (!validTriangle(m, f))
            continue;
        const std::uint32_t* t = m.tri + 3 * f;
        if (far[t[0]] || far[t[1]] || far[t[2]])
            continue;
        const std::int64_t x0 = sx[t[0]], y0 = sy[t[0]], x1 = sx[t[1]], y1 = sy[t[1]], x2 = sx[t[2]], y2 = sy[t[2]];
        const std::int64_t area = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);
        if (area <= 0)  // back face (or degenerate on screen): culled
            continue;
        std::int64_t minX = std::min({x0, x1, x2}), maxX = std::max({x0, x1, x2});
        std::int64_t minY = std::min({y0, y1, y2}), maxY = std::max({y0, y1, y2});
        if (maxX < 0 || maxY < 0 || minX >= maxCoord || minY >= maxCoord)
            continue;
        // Pixel centres at (i + 1/2) * kSub inside the box.
        const int i0 = int(std::max<std::int64_t>(0, (minX - kSub / 2 + kSub - 1) / kSub));
        const int i1 = int(std::min<std::int64_t>(n - 1, (maxX - kSub / 2) >= 0 ? (maxX - kSub / 2) / kSub : -1));
        const int j0 = int(std::max<std::int64_t>(0, (minY - kSub / 2 + kSub - 1) / kSub));
        const int j1 = int(std::min<std::int64_t>(n - 1, (maxY - kSub / 2) >= 0 ? (maxY - kSub / 2) / kSub : -1));
        if (i0 > i1 || j0 > j1)
            continue;
        // Edge functions, >= 0 inside; an edge owns the pixels exactly on it only when it is
        // a "top-left" edge, so that two faces sharing it never both draw them.
        auto owns = [](std::int64_t dx, std::int64_t dy) { return dy < 0 || (dy == 0 && dx > 0); };
        const std::int64_t bias0 = owns(x2 - x1, y2 - y1) ? 0 : -1;
        const std::int64_t bias1 = owns(x0 - x2, y0 - y2) ? 0 : -1;
        const std::int64_t bias2 = owns(x1 - x0, y1 - y0) ? 0 : -1;
        const double z0 = sz[t[0]], z1 = sz[t[1]], z2 = sz[t[2]];
        const double invArea = 1.0 / double(area);
        for (int j = j0; j <= j1; ++j) {
            const std::int64_t py = std::int64_t(j) * kSub + kSub / 2;
            for (int i = i0; i <= i1; ++i) {
                const std::int64_t px = std::int64_t(i) * kSub + kSub / 2;
                const std::int64_t w0 = (x2 - x1) * (py - y1) - (y2 - y1) * (px - x1);
                const std::int64_t w1 = (x0 - x2) * (py - y2) - (y0 - y2) * (px - x2);
                const std::int64_t w2 = (x1 - x0) * (py - y0) - (y1 - y0) * (px - x0);
                if (w0 + bias0 < 0 || w1 + bias1 < 0 || w2 + bias2 < 0)
                    continue;
                const double z = (double(w0) * z0 + double(w1) * z1 + double(w2) * z2) * invArea;
                const std::size_t p = std::size_t(j) * n + i;
                if (z < depth[p]) {
                    depth[p] = z;
                    id[p] = std::int32_t(f);
                }
            }
        }
    }

    // Deferred shading: one interpolated normal per covered pixel.
    Image image(pixels, -1);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const std::size_t p = std::size_t(j) * n + i;
            if (id[p] < 0)
                continue;
            const std::uint32_t f = std::uint32_t(id[p]);
            const std::uint32_t* t = m.tri + 3 * f;
            const double x0 = double(sx[t[0]]), y0 = double(sy[t[0]]), x1 = double(sx[t[1]]), y1 = double(sy[t[1]]),
                         x2 = double(sx[t[2]]), y2 = double(sy[t[2]]);
            const double px = double(i) * kSub + kSub / 2, py = double(j) * kSub + kSub / 2;
            const double area = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);
            const double b0 = ((x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)) / area;
            const double b1 = ((x0 - x2) * (py - y2) - (y0 - y2) * (px - x2)) / area;
            const double b2 = 1.0 - b0 - b1;
            const float* c = normals.data() + 9 * std::size_t(f);
            const Vec3 nrm = normalized({b0 * c[0] + b1 * c[3] + b2 * c[6], b0 * c[1] + b1 * c[4] + b2 * c[7],
                                         b0 * c[2] + b1 * c[5] + b2 * c[8]});
            const double intensity = 0.10 + 0.75 * std::max(0.0, dot(nrm, cam.key)) +
                                     0.25 * std::max(0.0, dot(nrm, cam.fill));
            image[p] = std::int16_t(std::lround(255.0 * std::min(1.0, intensity)));
        }
    return image;
}

std::vector<Camera> cameras()
{
    std::vector<Camera> out;
    for (const Vec3& f : viewDirections()) {
        Camera c;
        c.forward = f;
        const Vec3 hint = std::abs(f[2]) < 0.99 ? Vec3{0, 0, 1} : Vec3{0, 1, 0};
        c.right = normalized(cross(f, hint));
        c.up = cross(c.right, f);
        const Vec3 toViewer = scale(f, -1.0);
        c.key = normalized(add(add(toViewer, scale(c.up, 0.4)), scale(c.right, -0.3)));
        c.fill = normalized(add(add(scale(toViewer, 0.5), scale(c.right, 0.9)), scale(c.up, -0.1)));
        out.push_back(c);
    }
    return out;
}

Frame frameOf(const MeshRef& m)
{
    Frame fr;
    Vec3 lo{0, 0, 0}, hi{0, 0, 0};
    bool any = false;
    for (std::size_t f = 0; f < m.triangleCount; ++f) {
        if (!validTriangle(m, f))
            continue;
        for (int k = 0; k < 3; ++k) {
            const Vec3 p = vertex(m, m.tri[3 * f + k]);
            for (int a = 0; a < 3; ++a) {
                lo[a] = any ? std::min(lo[a], p[a]) : p[a];
                hi[a] = any ? std::max(hi[a], p[a]) : p[a];
            }
            any = true;
        }
    }
    fr.center = scale(add(lo, hi), 0.5);
    fr.radius = 0.5 * std::sqrt(dot(sub(hi, lo), sub(hi, lo)));
    if (!(fr.radius > 0))
        fr.radius = 1;
    return fr;
}

void writeTriptych(const std::string& path, const Image& a, const Image& b, int n, int threshold)
{
    std::vector<std::uint8_t> rgb(std::size_t(3) * n * 3 * n);
    for (int row = 0; row < n; ++row) {
        const int j = n - 1 - row;  // images are bottom-up
        for (int i = 0; i < n; ++i) {
            const std::size_t p = std::size_t(j) * n + i;
            auto put = [&](int panel, std::uint8_t r, std::uint8_t g, std::uint8_t bl) {
                std::uint8_t* o = rgb.data() + 3 * (std::size_t(row) * 3 * n + std::size_t(panel) * n + i);
                o[0] = r;
                o[1] = g;
                o[2] = bl;
            };
            const std::uint8_t ia = std::uint8_t(std::max<int>(0, a[p])), ib = std::uint8_t(std::max<int>(0, b[p]));
            put(0, ia, ia, ia);
            put(1, ib, ib, ib);
            if ((a[p] < 0) != (b[p] < 0))
                put(2, 255, 0, 0);
            else if (a[p] < 0)
                put(2, 0, 0, 0);
            else {
                const int d = std::abs(a[p] - b[p]);
                if (d > threshold)
                    put(2, 255, 230, 0);
                else {
                    const std::uint8_t g = std::uint8_t(40 + 16 * d);
                    put(2, g, g, g);
                }
            }
        }
    }
    writePng(path, 3 * n, n, rgb);
}

}  // namespace

std::vector<std::array<double, 3>> viewDirections()
{
    // Icosahedron vertices (0, ±1, ±φ) and cyclic permutations, turned about the fixed
    // axis (1, 2, 3) by 0.5 rad so that none lies in a coordinate plane.
    const double phi = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<Vec3> ico;
    for (int s1 : {-1, 1})
        for (int s2 : {-1, 1}) {
            ico.push_back({0, double(s1), s2 * phi});
            ico.push_back({double(s1), s2 * phi, 0});
            ico.push_back({s2 * phi, 0, double(s1)});
        }
    const Vec3 axis = normalized({1, 2, 3});
    const double angle = 0.5, c = std::cos(angle), s = std::sin(angle);
    std::vector<std::array<double, 3>> out;
    for (const Vec3& v0 : ico) {
        const Vec3 v = normalized(v0);
        // Rodrigues' rotation.
        const Vec3 r = add(add(scale(v, c), scale(cross(axis, v), s)), scale(axis, dot(axis, v) * (1 - c)));
        out.push_back(normalized(r));
    }
    return out;
}

struct Reference::Impl {
    Options options;
    Frame frame;
    std::vector<Camera> cams;
    std::vector<Image> images;
};

Reference::Reference(MeshRef input, Options options) : impl_(new Impl)
{
    impl_->options = options;
    impl_->options.resolution = std::max(8, options.resolution);
    impl_->frame = frameOf(input);
    impl_->cams = cameras();
    const std::vector<float> normals = cornerNormals(input, options.creaseDegrees);
    for (const Camera& cam : impl_->cams)
        impl_->images.push_back(render(input, normals, cam, impl_->frame, impl_->options.resolution));
}

Reference::~Reference() { delete impl_; }
Reference::Reference(Reference&& o) noexcept : impl_(o.impl_) { o.impl_ = nullptr; }
Reference& Reference::operator=(Reference&& o) noexcept
{
    std::swap(impl_, o.impl_);
    return *this;
}

const Options& Reference::options() const { return impl_->options; }

Result Reference::compare(MeshRef result, const std::string& imagePrefix) const
{
    const int n = impl_->options.resolution;
    const int threshold = impl_->options.threshold;
    const std::vector<float> normals = cornerNormals(result, impl_->options.creaseDegrees);
    Result out;
    double sumDelta = 0;
    for (std::size_t v = 0; v < impl_->cams.size(); ++v) {
        const Image img = render(result, normals, impl_->cams[v], impl_->frame, n);
        const Image& ref = impl_->images[v];
        ViewFigures fig;
        for (std::size_t p = 0; p < img.size(); ++p) {
            const bool a = ref[p] >= 0, b = img[p] >= 0;
            if (!a && !b)
                continue;
            ++fig.either;
            const int d = std::abs(std::max<int>(0, ref[p]) - std::max<int>(0, img[p]));
            fig.sumAbsDelta += d;
            if (a != b)
                ++fig.silhouette;
            else if (d > threshold)
                ++fig.shading;
        }
        if (!imagePrefix.empty()) {
            char name[32];
            std::snprintf(name, sizeof name, "view%02d.png", int(v));
            writeTriptych(imagePrefix + name, ref, img, n, threshold);
        }
        out.either += fig.either;
        out.silhouette += fig.silhouette;
        out.shading += fig.shading;
        sumDelta += fig.sumAbsDelta;
        out.views.push_back(fig);
    }
    if (out.either > 0) {
        out.visiblePercent = 100.0 * double(out.silhouette + out.shading) / double(out.either);
        out.silhouettePercent = 100.0 * double(out.silhouette) / double(out.either);
        out.meanAbsDelta = sumDelta / double(out.either);
    }
    return out;
}

Result compare(MeshRef input, MeshRef result, const Options& options, const std::string& imagePrefix)
{
    return Reference(input, options).compare(result, imagePrefix);
}

bool writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgb)
{
    if (width <= 0 || height <= 0 || rgb.size() != std::size_t(width) * height * 3)
        return false;
    std::vector<std::uint8_t> raw;
    raw.reserve((std::size_t(width) * 3 + 1) * height);
    for (int y = 0; y < height; ++y) {
        raw.push_back(0);  // filter: none
        raw.insert(raw.end(), rgb.begin() + std::size_t(y) * width * 3, rgb.begin() + std::size_t(y + 1) * width * 3);
    }
    uLongf packedSize = compressBound(uLong(raw.size()));
    std::vector<std::uint8_t> packed(packedSize);
    if (compress2(packed.data(), &packedSize, raw.data(), uLong(raw.size()), 9) != Z_OK)
        return false;
    packed.resize(packedSize);

    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file)
        return false;
    auto be32 = [](std::uint32_t v, std::uint8_t* o) {
        o[0] = std::uint8_t(v >> 24);
        o[1] = std::uint8_t(v >> 16);
        o[2] = std::uint8_t(v >> 8);
        o[3] = std::uint8_t(v);
    };
    bool ok = true;
    auto chunk = [&](const char* type, const std::uint8_t* data, std::size_t size) {
        std::uint8_t head[8];
        be32(std::uint32_t(size), head);
        std::copy(type, type + 4, head + 4);
        uLong crc = crc32(0L, head + 4, 4);
        if (size)
            crc = crc32(crc, data, uInt(size));
        std::uint8_t tail[4];
        be32(std::uint32_t(crc), tail);
        ok = ok && std::fwrite(head, 1, 8, file) == 8 && (size == 0 || std::fwrite(data, 1, size, file) == size) &&
             std::fwrite(tail, 1, 4, file) == 4;
    };
    static const std::uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    ok = std::fwrite(signature, 1, 8, file) == 8;
    std::uint8_t ihdr[13];
    be32(std::uint32_t(width), ihdr);
    be32(std::uint32_t(height), ihdr + 4);
    ihdr[8] = 8;   // bit depth
    ihdr[9] = 2;   // RGB
    ihdr[10] = 0;  // deflate
    ihdr[11] = 0;  // adaptive filtering
    ihdr[12] = 0;  // no interlace
    chunk("IHDR", ihdr, sizeof ihdr);
    chunk("IDAT", packed.data(), packed.size());
    chunk("IEND", nullptr, 0);
    return std::fclose(file) == 0 && ok;
}

}  // namespace cadlod::shading
