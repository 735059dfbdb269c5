// Independent triangle counts from Coin3D (libcoin-dev), which reads VRML 1.0 and
// VRML97: prints "mesh N round M" for one file, where "mesh" counts triangles from
// IndexedFaceSet, ElevationGrid, Extrusion and Box/Cube (tessellated identically by any
// reader) and "round" those of Sphere/Cylinder/Cone (reader-specific tessellation).
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/VRMLnodes/SoVRMLBox.h>
#include <Inventor/VRMLnodes/SoVRMLElevationGrid.h>
#include <Inventor/VRMLnodes/SoVRMLExtrusion.h>
#include <Inventor/VRMLnodes/SoVRMLIndexedFaceSet.h>
#include <Inventor/VRMLnodes/SoVRMLInline.h>
#include <Inventor/VRMLnodes/SoVRMLCone.h>
#include <Inventor/VRMLnodes/SoVRMLCylinder.h>
#include <Inventor/VRMLnodes/SoVRMLSphere.h>
#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/nodes/SoCone.h>
#include <Inventor/nodes/SoCube.h>
#include <Inventor/nodes/SoCylinder.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoSeparator.h>
#include <Inventor/nodes/SoSphere.h>
#include <Inventor/nodes/SoWWWInline.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

struct Counts {
    long mesh = 0, round = 0, other = 0;
};

bool isRound(const SoNode* n)
{
    return n->isOfType(SoVRMLSphere::getClassTypeId()) || n->isOfType(SoVRMLCylinder::getClassTypeId()) ||
           n->isOfType(SoVRMLCone::getClassTypeId()) || n->isOfType(SoSphere::getClassTypeId()) ||
           n->isOfType(SoCylinder::getClassTypeId()) || n->isOfType(SoCone::getClassTypeId());
}

bool isMesh(const SoNode* n)
{
    return n->isOfType(SoVRMLIndexedFaceSet::getClassTypeId()) || n->isOfType(SoIndexedFaceSet::getClassTypeId()) ||
           n->isOfType(SoVRMLElevationGrid::getClassTypeId()) || n->isOfType(SoVRMLExtrusion::getClassTypeId()) ||
           n->isOfType(SoVRMLBox::getClassTypeId()) || n->isOfType(SoCube::getClassTypeId());
}

void onTriangle(void* data, SoCallbackAction* action, const SoPrimitiveVertex*, const SoPrimitiveVertex*,
                const SoPrimitiveVertex*)
{
    Counts& c = *static_cast<Counts*>(data);
    const SoNode* shape = action->getCurPathTail();
    if (isMesh(shape)) ++c.mesh;
    else if (isRound(shape)) ++c.round;
    else ++c.other;
}

// Inline files are read synchronously while the parent is read: a stack of directories
// resolves relative urls against the including file, and bounds recursion.
std::vector<std::string> directories;

std::string directoryOf(const std::string& path)
{
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

SoSeparator* readFile(const std::string& path)
{
    if (directories.size() > 16) return nullptr;
    SoInput in;
    if (!in.openFile(path.c_str(), TRUE)) return nullptr;
    directories.push_back(directoryOf(path));
    SoSeparator* root = SoDB::readAll(&in);
    directories.pop_back();
    return root;
}

std::string resolve(const SbString& url)
{
    const std::string u = url.getString();
    return u.empty() || u[0] == '/' || directories.empty() ? u : directories.back() + "/" + u;
}

void fetchVrmlInline(const SbString& url, void*, SoVRMLInline* node)
{
    if (SoSeparator* child = readFile(resolve(url))) node->setChildData(child);
}

void fetchWwwInline(const SbString& url, void*, SoWWWInline* node)
{
    if (SoSeparator* child = readFile(resolve(url))) node->setChildData(child);
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: %s FILE.wrl\n", argv[0]);
        return 2;
    }
    SoDB::init();
    SoVRMLInline::setFetchURLCallBack(fetchVrmlInline, nullptr);
    SoWWWInline::setFetchURLCallBack(fetchWwwInline, nullptr);
    SoSeparator* root = readFile(argv[1]);
    if (!root) {
        std::printf("%s\terror\tCoin cannot read it\n", argv[1]);
        return 1;
    }
    root->ref();
    Counts counts;
    SoCallbackAction action;
    action.addTriangleCallback(SoShape::getClassTypeId(), onTriangle, &counts);
    action.apply(root);
    root->unref();
    std::printf("%s\tmesh %ld\tround %ld\tother %ld\n", argv[1], counts.mesh, counts.round, counts.other);
    return 0;
}
