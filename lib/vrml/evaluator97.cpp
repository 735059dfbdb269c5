// VRML97 scene evaluation: grouping nodes compose world transforms, Shapes emit their
// geometry into parts.
#include "vrml/evaluation.h"
#include "vrml/primitives.h"
#include "vrml/transform.h"
#include "vrml/traversal.h"

#include <set>

namespace cadlod::vrml {
namespace {

using Binding = AttributeSource::Binding;

const std::set<std::string>& ignoredNodeTypes()
{
    static const std::set<std::string> types{
        "Viewpoint", "NavigationInfo", "WorldInfo", "Background", "Fog", "DirectionalLight", "PointLight",
        "SpotLight", "Sound", "AudioClip", "Script", "TimeSensor", "TouchSensor", "PlaneSensor",
        "SphereSensor", "CylinderSensor", "ProximitySensor", "VisibilitySensor", "PositionInterpolator",
        "OrientationInterpolator", "ColorInterpolator", "ScalarInterpolator", "CoordinateInterpolator",
        "NormalInterpolator", "MovieTexture", "ImageTexture", "PixelTexture", "TextureTransform",
        "KeySensor", "StringSensor", "BooleanFilter", "BooleanSequencer", "BooleanToggle", "BooleanTrigger",
        "IntegerSequencer", "IntegerTrigger", "TimeTrigger", "OrthoViewpoint", "EnvironmentLight",
        "MetadataString", "MetadataFloat", "MetadataInteger", "MetadataSet", "MetadataDouble", "MetadataBoolean"};
    return types;
}

const FieldValue* nodesField(const Node& n, const char* name)
{
    const FieldValue* v = n.field(name);
    return v && v->kind == FieldValue::Kind::Nodes ? v : nullptr;
}

NodePtr nodeField(const Node& n, const char* name)
{
    const FieldValue* v = nodesField(n, name);
    return v && !v->nodes.empty() ? v->nodes.front() : nullptr;
}

std::vector<std::string> stringsField(const Node& n, const char* name)
{
    const FieldValue* v = n.field(name);
    return v && (v->kind == FieldValue::Kind::Strings || v->kind == FieldValue::Kind::Words) ? v->strings
                                                                                            : std::vector<std::string>{};
}

const std::vector<int32_t>* nonEmptyInts(const Node& n, const char* name)
{
    const std::vector<int32_t>* v = intsField(n, name);
    return v && !v->empty() ? v : nullptr;
}

const std::vector<float>* pointsOf(const NodePtr& n, const char* name)
{
    return n ? floatsField(*n, name) : nullptr;
}

class Evaluator97 {
public:
    explicit Evaluator97(EvalContext& ctx) : ctx_(ctx) {}

    void traverse(const NodePtr& node, const Mat4& world, const Owner& owner, const std::string& path, int depth)
    {
        if (!node || ctx_.stopped()) return;
        if (depth > ctx_.options.maxNesting) {
            ctx_.scene.diagnostics.warn("too deep", node->where, "scene nesting too deep; subtree skipped");
            return;
        }
        if (isInstance(*node)) {
            if (!ctx_.keepsInstances()) {
                ctx_.noteExpandedUse(sharedNodeKey(*node));
            } else {
                ctx_.placeInstance(sharedNodeKey(*node), node->defName, world, node->where,
                                   [&] { evaluate(node, ctx_.frame, Owner{}, node->defName, depth); });
                return;
            }
        }
        ctx_.enterNamed(*node);
        evaluate(node, world, owner, path, depth);
        ctx_.leaveNamed(*node);
    }

private:
    // A node that is USE'd and holds shapes: one geometry wherever it is used.
    static bool isInstance(const Node& n)
    {
        const std::string& t = n.type;
        return n.useCount > 0 && (t == "Transform" || t == "CADPart" || isGroupNode97(t) || t == "Switch" ||
                                  t == "LOD" || t == "Shape");
    }

    void evaluate(const NodePtr& node, const Mat4& world, const Owner& owner, const std::string& path, int depth)
    {
        const Owner here = node->defName.empty() ? owner : ctx_.newOwner(instanceName(*node, owner), true);
        const std::string& type = node->type;
        if (type == "Transform" || type == "CADPart") {
            const Mat4 local = transformMatrix(readTransformFields(*node, "scale"));
            follow(*node, world * local, here, path + "/" + type, depth);
        } else if (isGroupNode97(type) || type == "Switch" || type == "LOD") {
            follow(*node, world, here, path + "/" + type, depth);
        } else if (type == "Inline") {
            ctx_.loadInline(stringsField(*node, "url"), node->where, world, here);
        } else if (type == "Shape") {
            if (ctx_.admit(node, false)) shape(*node, world, ctx_.shapeOwner(here, path + "/Shape"));
        } else if (!ignoredNodeTypes().count(type)) {
            ctx_.scene.diagnostics.warn("unknown node", node->where, "node " + type + " ignored");
        }
    }

private:
    // The children vrml/traversal.h says a grouping node's evaluation follows; `path` names
    // the node, each child adds its index unless it is a Switch's or LOD's choice.
    void follow(const Node& node, const Mat4& world, const Owner& owner, const std::string& path, int depth)
    {
        const TraversedChildren t = traversedChildren(node, false);
        for (const ChildRef& c : t.children)
            traverse(*c.node, world, owner, t.chosen ? path : path + "[" + std::to_string(c.index) + "]", depth + 1);
    }

    std::array<float, 4> materialColor(const Node& shape)
    {
        std::array<float, 4> color{0.8f, 0.8f, 0.8f, 1.0f};
        const NodePtr appearance = nodeField(shape, "appearance");
        const NodePtr material = appearance ? nodeField(*appearance, "material") : nullptr;
        if (!material) return color;
        const Vec3 d = vec3Field(*material, "diffuseColor", {0.8, 0.8, 0.8});
        color = {float(d.x), float(d.y), float(d.z), 1.0f - floatField(*material, "transparency", 0.0f)};
        return color;
    }

    std::string texture(const Node& shape)
    {
        const NodePtr appearance = nodeField(shape, "appearance");
        const NodePtr texture = appearance ? nodeField(*appearance, "texture") : nullptr;
        if (!texture || texture->type != "ImageTexture") return {};
        return ctx_.resolveTexture(stringsField(*texture, "url"), texture->where);
    }

    void shape(const Node& node, const Mat4& world, const Owner& owner)
    {
        const NodePtr geometry = nodeField(node, "geometry");
        if (!geometry) return;
        ++ctx_.scene.stats.shapes;
        const std::string& type = geometry->type;
        if (type == "IndexedLineSet" || type == "LineSet") {
            ++ctx_.scene.stats.lineSets;
            return;
        }
        if (type == "PointSet") {
            ++ctx_.scene.stats.pointSets;
            return;
        }
        Part& part = ctx_.part(owner, materialColor(node), texture(node));
        const size_t before = part.triangleCount();
        emitGeometry(*geometry, world, part);
        countShapeTriangles(type, before, part, ctx_.scene.stats);
    }

    void emitGeometry(const Node& g, const Mat4& world, Part& part)
    {
        const std::string& type = g.type;
        if (type == "IndexedFaceSet") indexedFaceSet(g, world, part);
        else if (type == "Box") emitOwnedFaceSet(makeBox(vec3Field(g, "size", {2, 2, 2})), g.where, world, part, ctx_);
        else if (type == "Sphere") emitOwnedFaceSet(makeSphere(floatField(g, "radius", 1)), g.where, world, part, ctx_);
        else if (type == "Cylinder") cylinder(g, world, part);
        else if (type == "Cone") cone(g, world, part);
        else if (type == "ElevationGrid") elevationGrid(g, world, part);
        else if (type == "Extrusion") extrusion(g, world, part);
        else ctx_.scene.diagnostics.warn("unsupported geometry", g.where, "geometry " + type + " ignored");
    }

    void cylinder(const Node& g, const Mat4& world, Part& part)
    {
        emitOwnedFaceSet(makeCylinder(floatField(g, "radius", 1), floatField(g, "height", 2), boolField(g, "side", true),
                                      boolField(g, "top", true), boolField(g, "bottom", true)),
                         g.where, world, part, ctx_);
    }

    void cone(const Node& g, const Mat4& world, Part& part)
    {
        emitOwnedFaceSet(makeCone(floatField(g, "bottomRadius", 1), floatField(g, "height", 2), boolField(g, "side", true),
                                  boolField(g, "bottom", true)),
                         g.where, world, part, ctx_);
    }

    // colorPerVertex / normalPerVertex index rules (VRML97 6.23): an empty index array
    // falls back to coordIndex per vertex, to the face order per face.
    static AttributeSource binding(const std::vector<float>* values, int components, bool perVertex,
                                   const std::vector<int32_t>* index, const std::vector<int32_t>* coordIndex)
    {
        AttributeSource a;
        if (!values || values->empty()) return a;
        a.values = values;
        a.components = components;
        a.binding = perVertex ? Binding::PerCorner : Binding::PerFace;
        a.index = index ? index : (perVertex ? coordIndex : nullptr);
        return a;
    }

    void indexedFaceSet(const Node& g, const Mat4& world, Part& part)
    {
        FaceSetInput in;
        in.coords = pointsOf(nodeField(g, "coord"), "point");
        in.coordIndex = intsField(g, "coordIndex");
        in.where = g.where;
        if (!in.coords || !in.coordIndex) return;
        const NodePtr color = nodeField(g, "color");
        in.colors = binding(pointsOf(color, "color"), color && color->type == "ColorRGBA" ? 4 : 3,
                            boolField(g, "colorPerVertex", true), nonEmptyInts(g, "colorIndex"), in.coordIndex);
        in.normals = binding(pointsOf(nodeField(g, "normal"), "vector"), 3, boolField(g, "normalPerVertex", true),
                             nonEmptyInts(g, "normalIndex"), in.coordIndex);
        in.texCoords = binding(pointsOf(nodeField(g, "texCoord"), "point"), 2, true, nonEmptyInts(g, "texCoordIndex"),
                               in.coordIndex);
        in.ccw = boolField(g, "ccw", true);
        in.convex = boolField(g, "convex", true);
        in.creaseAngle = floatField(g, "creaseAngle", 0);
        emitFaceSet(in, world, ctx_.emit, part, ctx_.scene.diagnostics, ctx_.scene.stats);
    }

    void elevationGrid(const Node& g, const Mat4& world, Part& part)
    {
        const std::vector<float>* heights = floatsField(g, "height");
        const int32_t xDim = intField(g, "xDimension", 0), zDim = intField(g, "zDimension", 0);
        if (double(xDim) * double(zDim) > double(heights ? heights->size() : 0)) {  // also guards absurd sizes
            ctx_.scene.diagnostics.warn("bad ElevationGrid", g.where,
                                        "xDimension x zDimension exceeds the number of heights; grid skipped");
            return;
        }
        OwnedFaceSet f = makeElevationGrid(xDim, zDim,
                                           floatField(g, "xSpacing", 1), floatField(g, "zSpacing", 1),
                                           heights ? *heights : std::vector<float>{});
        FaceSetInput in;
        in.coords = &f.coords;
        in.coordIndex = &f.coordIndex;
        in.where = g.where;
        const NodePtr color = nodeField(g, "color");
        in.colors = binding(pointsOf(color, "color"), 3, boolField(g, "colorPerVertex", true), nullptr, &f.coordIndex);
        in.normals = binding(pointsOf(nodeField(g, "normal"), "vector"), 3, boolField(g, "normalPerVertex", true),
                             nullptr, &f.coordIndex);
        in.texCoords = binding(pointsOf(nodeField(g, "texCoord"), "point"), 2, true, nullptr, &f.coordIndex);
        in.ccw = boolField(g, "ccw", true);
        in.creaseAngle = floatField(g, "creaseAngle", 0);
        emitFaceSet(in, world, ctx_.emit, part, ctx_.scene.diagnostics, ctx_.scene.stats);
    }

    void extrusion(const Node& g, const Mat4& world, Part& part)
    {
        ExtrusionSpec spec;
        if (const auto* v = floatsField(g, "crossSection")) spec.crossSection = *v;
        if (const auto* v = floatsField(g, "spine")) spec.spine = *v;
        if (const auto* v = floatsField(g, "scale")) spec.scale = *v;
        if (const auto* v = floatsField(g, "orientation")) spec.orientation = *v;
        spec.beginCap = boolField(g, "beginCap", true);
        spec.endCap = boolField(g, "endCap", true);
        OwnedFaceSet f = makeExtrusion(spec);
        f.ccw = boolField(g, "ccw", true);
        f.convex = boolField(g, "convex", true);
        f.creaseAngle = floatField(g, "creaseAngle", 0);
        emitOwnedFaceSet(f, g.where, world, part, ctx_);
    }

    EvalContext& ctx_;
};

}  // namespace

void countShapeTriangles(const std::string& type, size_t before, const Part& part, SceneStats& stats)
{
    const size_t added = part.triangleCount() - before;
    if (type == "Sphere" || type == "Cylinder" || type == "Cone") stats.roundPrimitiveTriangles += added;
    else stats.meshTriangles += added;
}

void emitOwnedFaceSet(const OwnedFaceSet& f, const std::string& where, const Mat4& world, Part& part,
                      EvalContext& ctx)
{
    FaceSetInput in;
    in.coords = &f.coords;
    in.coordIndex = &f.coordIndex;
    in.ccw = f.ccw;
    in.convex = f.convex;
    in.creaseAngle = f.creaseAngle;
    in.where = where;
    emitFaceSet(in, world, ctx.emit, part, ctx.scene.diagnostics, ctx.scene.stats);
}

void evaluateVrml97(const std::vector<NodePtr>& roots, const Mat4& world, const Owner& owner, const std::string& path,
                    EvalContext& ctx)
{
    Evaluator97 e(ctx);
    for (size_t i = 0; i < roots.size(); ++i) e.traverse(roots[i], world, owner, path + "[" + std::to_string(i) + "]", 0);
}

}  // namespace cadlod::vrml
