// osg_render: what a VR engine user of a model sees (paper §5, Table 1), measured with
// OpenSceneGraph on the current X display: load time (wall clock), peak memory,
// triangles per LOD level, and the frame rate along a fixed camera path that orbits the
// model while backing away from it, log-spaced, across every OpenFlight LOD switch
// distance (bench/lod_path), with the triangles the LOD nodes select in each frame.
// `--path inside` moves the eye through the model instead, over the 4x4x2 grid of
// bench/view_error's inside path, so both tools see the same viewer.
// `--level K` shows only level K of every LOD (or use a plain mesh file) to measure one
// level alone; `--shot FILE` writes one shaded (optionally wireframe) picture instead.
// Output: one "key value" line per figure, for scripts.
#include "lod_path.h"

#include <osg/ComputeBoundsVisitor>
#include <osg/Geometry>
#include <osg/LOD>
#include <osg/Material>
#include <osgDB/ReadFile>
#include <osgDB/Registry>
#include <osgDB/WriteFile>
#include <osgFX/Scribe>
#include <osgUtil/SmoothingVisitor>
#include <osgViewer/Viewer>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace {

using cadlod::lodpath::Level;
using cadlod::lodpath::LodChildRef;

constexpr double kFovY = 45.0;  // degrees, like the LOD-set filter's default

enum class PathKind { Orbit, Inside };

struct Options {
    std::string model;
    int frames = 240;
    int width = 640;
    int height = 480;
    int level = -1;             // -1: LOD ranges active; K: only level K shown
    double nearDistance = 0;    // camera path, model units; 0: automatic
    double farDistance = 0;
    double elevation = 20;      // degrees above the XY plane (Z up)
    double azimuth = 35;        // degrees, for --shot
    double shotDistance = 2.4;  // bounding radii, for --shot
    double creaseAngle = -1;    // >= 0: recompute normals, split above this angle (degrees)
    int upAxis = 2;             // model axis pointing up on screen (0 x, 1 y, 2 z)
    osg::Vec3d focus{0.5, 0.5, 0.5};  // looked-at point for --shot, as fractions of the bbox
    std::string shot;
    bool wire = false;
    bool render = true;         // false: load and count only
    PathKind path = PathKind::Orbit;
    osg::BoundingBox box;       // valid: replaces the model's own box (--box)
};

[[noreturn]] void usage(const char* why)
{
    std::fprintf(stderr,
                 "osg_render: %s\n"
                 "usage: osg_render MODEL [--frames N] [--size WxH] [--level K] [--near D --far D]\n"
                 "                  [--elevation DEG] [--crease DEG] [--path orbit|inside]\n"
                 "                  [--box X0,Y0,Z0,X1,Y1,Z1] [--no-render]\n"
                 "       osg_render MODEL --shot OUT.png [--wire] [--azimuth DEG] [--distance RADII]\n"
                 "                  [--focus FX,FY,FZ] ...\n"
                 "       (--up x|y|z: the model axis shown upwards, default z)\n",
                 why);
    std::exit(2);
}

double number(int& i, int argc, char** argv)
{
    if (i + 1 >= argc)
        usage("missing value after an option");
    char* end = nullptr;
    const double v = std::strtod(argv[++i], &end);
    if (end == argv[i] || *end)
        usage("not a number");
    return v;
}

int axisIndex(const std::string& name)
{
    if (name == "x" || name == "y" || name == "z")
        return name[0] - 'x';
    usage("--up wants x, y or z");
}

PathKind pathKind(const std::string& name)
{
    if (name == "orbit")
        return PathKind::Orbit;
    if (name == "inside")
        return PathKind::Inside;
    usage("--path wants orbit or inside");
}

Options parseOptions(int argc, char** argv)
{
    Options o;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames") o.frames = int(number(i, argc, argv));
        else if (a == "--level") o.level = int(number(i, argc, argv));
        else if (a == "--near") o.nearDistance = number(i, argc, argv);
        else if (a == "--far") o.farDistance = number(i, argc, argv);
        else if (a == "--elevation") o.elevation = number(i, argc, argv);
        else if (a == "--azimuth") o.azimuth = number(i, argc, argv);
        else if (a == "--distance") o.shotDistance = number(i, argc, argv);
        else if (a == "--crease") o.creaseAngle = number(i, argc, argv);
        else if (a == "--wire") o.wire = true;
        else if (a == "--up" && i + 1 < argc) o.upAxis = axisIndex(argv[++i]);
        else if (a == "--path" && i + 1 < argc) o.path = pathKind(argv[++i]);
        else if (a == "--focus" && i + 1 < argc) {
            if (std::sscanf(argv[++i], "%lf,%lf,%lf", &o.focus.x(), &o.focus.y(), &o.focus.z()) != 3)
                usage("--focus wants FX,FY,FZ (fractions of the bounding box)");
        }
        else if (a == "--box" && i + 1 < argc) {
            osg::Vec3d lo, hi;
            if (std::sscanf(argv[++i], "%lf,%lf,%lf,%lf,%lf,%lf", &lo.x(), &lo.y(), &lo.z(), &hi.x(), &hi.y(),
                            &hi.z()) != 6)
                usage("--box wants X0,Y0,Z0,X1,Y1,Z1");
            o.box.set(lo, hi);
        }
        else if (a == "--no-render") o.render = false;
        else if (a == "--shot" && i + 1 < argc) o.shot = argv[++i];
        else if (a == "--size" && i + 1 < argc) {
            if (std::sscanf(argv[++i], "%dx%d", &o.width, &o.height) != 2)
                usage("--size wants WxH");
        } else if (!a.empty() && a[0] != '-' && o.model.empty()) o.model = a;
        else usage(("unknown argument " + a).c_str());
    }
    if (o.model.empty())
        usage("no model file");
    if (o.frames < 2 || o.width < 16 || o.height < 16)
        usage("need at least 2 frames and a 16x16 window");
    return o;
}

double peakRssKb()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss);
}

// CPU time of the whole process (Mesa's software renderer draws in threads of this
// process), steadier than wall time on a busy machine.
double cpuSeconds()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Loads the reader plugin first so that the timed part is reading the file only.
osg::ref_ptr<osg::Node> loadTimed(const std::string& file, double& seconds)
{
    osgDB::Registry* registry = osgDB::Registry::instance();
    registry->loadLibrary(registry->createLibraryNameForFile(file));
    const auto start = std::chrono::steady_clock::now();
    osg::ref_ptr<osg::Node> node = osgDB::readRefNodeFile(file);
    seconds = secondsSince(start);
    return node;
}

// Shows level `k` at every distance and hides the others.
void pinLevel(std::vector<Level>& levels, int k)
{
    if (k < 0 || k >= int(levels.size())) {
        std::fprintf(stderr, "osg_render: the model has %zu LOD levels, no level %d\n", levels.size(), k);
        std::exit(1);
    }
    for (int i = 0; i < int(levels.size()); ++i)
        for (const LodChildRef& lc : levels[std::size_t(i)].children)
            lc.lod->setRange(lc.child, 0.0f, i == k ? std::numeric_limits<float>::max() : 0.0f);
}

void recomputeNormals(osg::Node& root, double creaseDegrees)
{
    class Smooth : public osg::NodeVisitor
    {
    public:
        explicit Smooth(double crease) : osg::NodeVisitor(TRAVERSE_ALL_CHILDREN), crease_(crease) {}
        void apply(osg::Geometry& g) override { osgUtil::SmoothingVisitor::smooth(g, crease_); }

    private:
        double crease_;
    };
    Smooth s(osg::DegreesToRadians(creaseDegrees));
    root.accept(s);
}

// A uniform matte material for pictures, so that only the mesh changes between them.
void applyPictureMaterial(osg::Node& root)
{
    osg::ref_ptr<osg::Material> m = new osg::Material;
    m->setColorMode(osg::Material::OFF);
    m->setAmbient(osg::Material::FRONT_AND_BACK, osg::Vec4(0.25f, 0.27f, 0.30f, 1));
    m->setDiffuse(osg::Material::FRONT_AND_BACK, osg::Vec4(0.70f, 0.74f, 0.80f, 1));
    m->setSpecular(osg::Material::FRONT_AND_BACK, osg::Vec4(0.35f, 0.35f, 0.35f, 1));
    m->setShininess(osg::Material::FRONT_AND_BACK, 40);
    root.getOrCreateStateSet()->setAttributeAndModes(m, osg::StateAttribute::ON | osg::StateAttribute::OVERRIDE);
}

osg::ref_ptr<osgViewer::Viewer> makeViewer(const Options& o, osg::Node* scene)
{
    osg::ref_ptr<osg::GraphicsContext::Traits> t = new osg::GraphicsContext::Traits;
    t->readDISPLAY();  // a bare Traits means display :0.0, whatever DISPLAY says
    t->x = 0;
    t->y = 0;
    t->width = o.width;
    t->height = o.height;
    t->windowDecoration = false;
    t->doubleBuffer = true;
    t->vsync = false;
    osg::ref_ptr<osg::GraphicsContext> gc = osg::GraphicsContext::createGraphicsContext(t);
    if (!gc) {
        std::fprintf(stderr, "osg_render: cannot open a %dx%d OpenGL window (DISPLAY=%s)\n", o.width, o.height,
                     std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "unset");
        std::exit(1);
    }
    osg::ref_ptr<osgViewer::Viewer> viewer = new osgViewer::Viewer;
    viewer->setThreadingModel(osgViewer::Viewer::SingleThreaded);
    osg::Camera* camera = viewer->getCamera();
    camera->setGraphicsContext(gc);
    camera->setViewport(0, 0, o.width, o.height);
    camera->setProjectionMatrixAsPerspective(kFovY, double(o.width) / o.height, 1.0, 10.0);
    camera->setClearColor(osg::Vec4(1, 1, 1, 1));
    camera->setDrawBuffer(GL_BACK);
    camera->setReadBuffer(GL_BACK);
    viewer->setSceneData(scene);
    viewer->realize();
    if (gc->makeCurrent()) {
        const GLubyte* renderer = glGetString(GL_RENDERER);
        std::printf("gl_renderer %s\n", renderer ? reinterpret_cast<const char*>(renderer) : "unknown");
        gc->releaseContext();
    }
    return viewer;
}

osg::Vec3d unitAxis(int i)
{
    osg::Vec3d v(0, 0, 0);
    v[i % 3] = 1;
    return v;
}

// Azimuth turns about the up axis; elevation lifts the eye towards it.
osg::Vec3d eyePosition(const osg::Vec3d& target, int upAxis, double distance, double azimuthDeg, double elevationDeg)
{
    const double az = osg::DegreesToRadians(azimuthDeg), el = osg::DegreesToRadians(elevationDeg);
    const osg::Vec3d up = unitAxis(upAxis), a = unitAxis(upAxis + 1), b = unitAxis(upAxis + 2);
    const osg::Vec3d dir = (a * std::cos(az) + b * std::sin(az)) * std::cos(el) + up * std::sin(el);
    return target + dir * distance;
}

void lookAt(osgViewer::Viewer& viewer, const osg::Vec3d& target, int upAxis, double distance, double azimuthDeg,
            double elevationDeg)
{
    viewer.getCamera()->setViewMatrixAsLookAt(eyePosition(target, upAxis, distance, azimuthDeg, elevationDeg), target,
                                              unitAxis(upAxis));
}

struct Capture : osg::Camera::DrawCallback {
    osg::ref_ptr<osg::Image> image = new osg::Image;
    void operator()(osg::RenderInfo& info) const override
    {
        const osg::Viewport* vp = info.getCurrentCamera()->getViewport();
        image->readPixels(int(vp->x()), int(vp->y()), int(vp->width()), int(vp->height()), GL_RGB, GL_UNSIGNED_BYTE);
    }
};

int writeShot(const Options& o, osg::Node* model, const osg::BoundingBox& box)
{
    applyPictureMaterial(*model);
    osg::ref_ptr<osg::Node> scene = model;
    if (o.wire) {
        osg::ref_ptr<osgFX::Scribe> scribe = new osgFX::Scribe;
        scribe->setWireframeColor(osg::Vec4(0.1f, 0.1f, 0.15f, 1));
        scribe->addChild(model);
        scene = scribe;
    }
    osg::ref_ptr<osgViewer::Viewer> viewer = makeViewer(o, scene.get());
    osg::ref_ptr<Capture> capture = new Capture;
    const osg::Vec3d target(box.xMin() + o.focus.x() * (box.xMax() - box.xMin()),
                            box.yMin() + o.focus.y() * (box.yMax() - box.yMin()),
                            box.zMin() + o.focus.z() * (box.zMax() - box.zMin()));
    lookAt(*viewer, target, o.upAxis, o.shotDistance * box.radius(), o.azimuth, o.elevation);
    viewer->frame();
    viewer->getCamera()->setFinalDrawCallback(capture);
    viewer->frame();
    viewer->getCamera()->setFinalDrawCallback(nullptr);
    if (!osgDB::writeImageFile(*capture->image, o.shot)) {
        std::fprintf(stderr, "osg_render: cannot write %s\n", o.shot.c_str());
        return 1;
    }
    std::printf("shot %s\n", o.shot.c_str());
    return 0;
}

// The default path sweeps every level (see cadlod::lodpath::pathOverEveryLevel); --near and
// --far override either end.
void chooseOrbitEnds(Options& o, const std::vector<Level>& levels, double radius)
{
    const cadlod::lodpath::PathEnds ends = cadlod::lodpath::pathOverEveryLevel(levels, radius, kFovY, o.height);
    if (o.nearDistance <= 0)
        o.nearDistance = ends.nearDistance;
    if (o.farDistance <= 0)
        o.farDistance = ends.farDistance;
    if (o.farDistance <= o.nearDistance)
        o.farDistance = 2 * o.nearDistance;
}

// Frame i of n: one full orbit while the distance grows log-spaced from near to far.
double pathDistance(const Options& o, int i)
{
    const double t = double(i) / (o.frames - 1);
    return o.nearDistance * std::pow(o.farDistance / o.nearDistance, t);
}

double pathAzimuth(const Options& o, int i) { return 360.0 * i / o.frames; }

// Where the eye is in one frame and the point it looks at.
struct Pose {
    osg::Vec3d eye;
    osg::Vec3d target;
};

std::vector<Pose> orbitPath(const Options& o, const osg::Vec3d& center)
{
    std::vector<Pose> poses;
    for (int i = 0; i < o.frames; ++i)
        poses.push_back({eyePosition(center, o.upAxis, pathDistance(o, i), pathAzimuth(o, i), o.elevation), center});
    return poses;
}

// bench/view_error's inside points, (i + 0.5) / 4, (j + 0.5) / 4, (k + 0.5) / 2 of the box,
// in an order where each is next to the one before (rows back and forth, the upper layer
// walked back over the lower), so that the eye glides between them rather than jumps.
std::vector<osg::Vec3d> insideGridInOrder(const osg::BoundingBox& box)
{
    const osg::Vec3d size = box._max - box._min;
    std::vector<osg::Vec3d> points;
    int row = 0;
    for (int k = 0; k < 2; ++k)
        for (int jj = 0; jj < 4; ++jj, ++row) {
            const int j = k == 0 ? jj : 3 - jj;
            for (int ii = 0; ii < 4; ++ii) {
                const int i = row % 2 == 0 ? ii : 3 - ii;
                points.push_back(osg::Vec3d(box._min) + osg::Vec3d(size.x() * (i + 0.5) / 4, size.y() * (j + 0.5) / 4,
                                                                   size.z() * (k + 0.5) / 2));
            }
        }
    return points;
}

// The point at arc length `s` along the polyline through `points`.
osg::Vec3d alongPolyline(const std::vector<osg::Vec3d>& points, double s)
{
    for (std::size_t p = 1; p < points.size(); ++p) {
        const double step = (points[p] - points[p - 1]).length();
        if (s <= step || p + 1 == points.size())
            return points[p - 1] + (points[p] - points[p - 1]) * (step > 0 ? std::min(1.0, s / step) : 0.0);
        s -= step;
    }
    return points.front();
}

double polylineLength(const std::vector<osg::Vec3d>& points)
{
    double length = 0;
    for (std::size_t p = 1; p < points.size(); ++p)
        length += (points[p] - points[p - 1]).length();
    return length;
}

// The frames spread evenly along the grid's polyline, the eye looking at the box's centre:
// the grid keeps off the centre's height, so the view direction never runs along the up axis.
std::vector<Pose> insidePath(const Options& o, const osg::BoundingBox& box)
{
    const std::vector<osg::Vec3d> grid = insideGridInOrder(box);
    const double length = polylineLength(grid);
    std::vector<Pose> poses;
    for (int i = 0; i < o.frames; ++i)
        poses.push_back({alongPolyline(grid, length * i / (o.frames - 1)), osg::Vec3d(box.center())});
    return poses;
}

// What the LOD nodes select in every frame of the path: the mean triangles per frame (all
// frames, and those with the eye outside the bounding sphere), and for each level the frames
// that drew it (first and last, with the eye's distances to the centre). Counted apart from
// the timed frames, which it would slow down.
void printTrianglesAlongPath(const std::vector<Pose>& poses, cadlod::lodpath::LodPathCounter& counter,
                             const osg::BoundingSphere& bs)
{
    std::vector<osg::Vec3d> eyes;
    for (const Pose& pose : poses)
        eyes.push_back(pose.eye);
    const cadlod::lodpath::PathTally tally = counter.walk(eyes);
    const auto [fewest, most] = std::minmax_element(tally.trianglesPerFrame.begin(), tally.trianglesPerFrame.end());
    std::printf("path_mean_triangles %.1f\npath_min_triangles %zu\npath_max_triangles %zu\n"
                "path_frames_drawing_nothing %d\n",
                tally.meanTriangles(), *fewest, *most, tally.framesDrawingNothing);
    const auto distance = [&](int frame) { return (eyes[std::size_t(frame)] - osg::Vec3d(bs.center())).length(); };
    // Levels switched in closer than the bounding radius are only drawn with the eye inside
    // the model; the mean over the other frames is what a viewer outside it gets.
    double outsideSum = 0;
    int outsideFrames = 0;
    for (int i = 0; i < int(eyes.size()); ++i)
        if (distance(i) >= bs.radius()) {
            outsideSum += double(tally.trianglesPerFrame[std::size_t(i)]);
            ++outsideFrames;
        }
    std::printf("path_outside_frames %d\npath_outside_mean_triangles %.1f\n", outsideFrames,
                outsideFrames ? outsideSum / outsideFrames : 0.0);
    for (std::size_t k = 0; k < tally.levels.size(); ++k) {
        const cadlod::lodpath::LevelOnPath& on = tally.levels[k];
        std::printf("path_level %zu frames %d first %d last %d", k, on.frames, on.firstFrame, on.lastFrame);
        if (on.frames > 0)
            std::printf(" from %.6g to %.6g", distance(on.firstFrame), distance(on.lastFrame));
        std::printf("\n");
    }
}

void printPath(const Options& o)
{
    if (o.path == PathKind::Orbit)
        std::printf("path_kind orbit\npath_near %.6g\npath_far %.6g\n", o.nearDistance, o.farDistance);
    else
        std::printf("path_kind inside\n");
    std::printf("frames %d\n", o.frames);
}

void look(osgViewer::Viewer& viewer, const Pose& pose, int upAxis)
{
    viewer.getCamera()->setViewMatrixAsLookAt(pose.eye, pose.target, unitAxis(upAxis));
}

int measureFrameRate(const Options& o, osg::Node* model, const std::vector<Pose>& poses)
{
    osg::ref_ptr<osgViewer::Viewer> viewer = makeViewer(o, model);
    for (int i = 0; i < 5; ++i) {  // first frames compile display lists and shaders
        look(*viewer, poses[std::size_t(i * (o.frames - 1) / 4)], o.upAxis);
        viewer->frame();
    }
    const double cpuStart = cpuSeconds();
    const auto start = std::chrono::steady_clock::now();
    for (const Pose& pose : poses) {
        look(*viewer, pose, o.upAxis);
        viewer->frame();
    }
    const double seconds = secondsSince(start);
    const double cpu = cpuSeconds() - cpuStart;
    std::printf("render_seconds %.4f\nfps %.2f\n", seconds, o.frames / seconds);
    std::printf("cpu_seconds %.4f\nfps_cpu %.2f\n", cpu, cpu > 0 ? o.frames / cpu : 0.0);
    std::printf("peak_rss_kb %.0f\n", peakRssKb());
    return 0;
}

std::vector<Pose> cameraPath(Options& o, const std::vector<Level>& levels, const osg::BoundingBox& box)
{
    if (o.path == PathKind::Inside)
        return insidePath(o, box);
    chooseOrbitEnds(o, levels, box.radius());
    return orbitPath(o, box.center());
}

}  // namespace

int main(int argc, char** argv)
{
    Options o = parseOptions(argc, argv);
    double loadSeconds = 0;
    osg::ref_ptr<osg::Node> model = loadTimed(o.model, loadSeconds);
    if (!model) {
        std::fprintf(stderr, "osg_render: OpenSceneGraph cannot read %s\n", o.model.c_str());
        return 1;
    }
    std::printf("model %s\nload_seconds %.4f\npeak_rss_after_load_kb %.0f\n", o.model.c_str(), loadSeconds,
                peakRssKb());

    cadlod::lodpath::LodPathCounter counter(*model);
    std::vector<Level> levels = counter.levels();
    std::printf("triangles %zu\nlod_levels %zu\n", cadlod::lodpath::trianglesBelow(*model), levels.size());
    for (std::size_t k = 0; k < levels.size(); ++k)
        std::printf("level %zu triangles %zu range %.6g %.6g\n", k, levels[k].triangles, levels[k].nearRange,
                    levels[k].farRange);
    if (o.level >= 0)
        pinLevel(levels, o.level);
    if (o.creaseAngle >= 0)
        recomputeNormals(*model, o.creaseAngle);

    osg::ComputeBoundsVisitor bounds;
    model->accept(bounds);
    // OSG bounds a transformed subgraph by its transformed box corners, which overshoots
    // for rotated parts: --box lets two files of the same model share one camera path.
    const osg::BoundingBox box = o.box.valid() ? o.box : bounds.getBoundingBox();
    const osg::BoundingSphere bs(box.center(), box.radius());
    std::printf("radius %.6g\nbox %.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", bs.radius(), box.xMin(), box.yMin(), box.zMin(),
                box.xMax(), box.yMax(), box.zMax());
    std::fflush(stdout);
    if (!box.valid()) {
        std::fprintf(stderr, "osg_render: %s has no geometry\n", o.model.c_str());
        return 1;
    }
    if (!o.shot.empty())
        return o.render ? writeShot(o, model.get(), box) : 0;
    const std::vector<Pose> poses = cameraPath(o, levels, box);
    printPath(o);
    printTrianglesAlongPath(poses, counter, bs);
    std::fflush(stdout);
    return o.render ? measureFrameRate(o, model.get(), poses) : 0;
}
