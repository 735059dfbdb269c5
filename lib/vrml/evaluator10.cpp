// VRML 1.0 scene evaluation: a traversal-state machine. Property nodes (Coordinate3,
// Normal, Material, bindings, ShapeHints, transforms) change the state in traversal
// order; Separator saves and restores it; shape nodes emit with the current state.
#include "vrml/evaluation.h"
#include "vrml/primitives.h"
#include "vrml/transform.h"
#include "vrml/traversal.h"

#include <cstdio>
#include <set>

namespace cadlod::vrml {
namespace {

using Binding = AttributeSource::Binding;

struct State {
    Mat4 world;
    const std::vector<float>* coords = nullptr;
    const std::vector<float>* normals = nullptr;
    const std::vector<float>* texCoords = nullptr;
    const std::vector<float>* diffuse = nullptr;
    const std::vector<float>* transparency = nullptr;
    std::string texture;
    std::string normalBinding = "DEFAULT";
    std::string materialBinding = "OVERALL";
    bool ccw = true;
    bool convex = true;
    float creaseAngle = 0.5f;
};

const std::set<std::string>& ignoredNodeTypes()
{
    static const std::set<std::string> types{"Info", "PerspectiveCamera", "OrthographicCamera", "DirectionalLight",
                                             "PointLight", "SpotLight", "Texture2Transform", "FontStyle",
                                             "AsciiText", "Label", "Complexity", "DrawStyle", "LightModel",
                                             "Environment", "Units"};
    return types;
}

const std::vector<int32_t>* indicesOrNull(const Node& n, const char* name)
{
    const std::vector<int32_t>* v = intsField(n, name);
    if (!v || v->empty() || (v->size() == 1 && (*v)[0] < 0)) return nullptr;  // default [-1]
    return v;
}

// NormalBinding / MaterialBinding values (VRML 1.0 spec, Coin's IndexedFaceSet rules).
AttributeSource bindingFor(const std::string& mode, const std::vector<float>* values, int components,
                           const std::vector<int32_t>* index, const std::vector<int32_t>* coordIndex)
{
    AttributeSource a;
    if (!values || values->empty()) return a;
    a.values = values;
    a.components = components;
    if (mode == "OVERALL") {
        a.binding = Binding::Overall;
    } else if (mode == "PER_PART" || mode == "PER_FACE") {
        a.binding = Binding::PerFace;
    } else if (mode == "PER_PART_INDEXED" || mode == "PER_FACE_INDEXED") {
        a.binding = Binding::PerFace;
        a.index = index;
    } else if (mode == "PER_VERTEX") {
        a.binding = Binding::PerCorner;
    } else {  // PER_VERTEX_INDEXED, DEFAULT
        a.binding = Binding::PerCorner;
        a.index = index ? index : coordIndex;
    }
    return a;
}

class Evaluator10 {
public:
    explicit Evaluator10(EvalContext& ctx) : ctx_(ctx) {}

    void traverse(const NodePtr& node, State& state, const Owner& owner, const std::string& path, int depth)
    {
        if (!node || ctx_.stopped()) return;
        if (depth > ctx_.options.maxNesting) {
            ctx_.scene.diagnostics.warn("too deep", node->where, "scene nesting too deep; subtree skipped");
            return;
        }
        if (node->useCount > 0 && node->type == "Separator") {
            if (ctx_.keepsInstances()) {
                place(node, state, depth);
                return;
            }
            ctx_.noteExpandedUse(instanceKey(*node, state));
        }
        ctx_.enterNamed(*node);
        evaluate(node, state, owner, path, depth);
        ctx_.leaveNamed(*node);
    }

private:
    // A USE'd Separator is one geometry per traversal state it is met in: what it draws depends
    // on the coordinates, materials and hints in force; its transform goes to the placement.
    static std::string instanceKey(const Node& node, const State& state)
    {
        char key[200];
        std::snprintf(key, sizeof key, " %p %p %p %p %p %s %s %d %d %g", static_cast<const void*>(state.coords), static_cast<const void*>(state.normals),
                      static_cast<const void*>(state.texCoords), static_cast<const void*>(state.diffuse),
                      static_cast<const void*>(state.transparency), state.normalBinding.c_str(),
                      state.materialBinding.c_str(), int(state.ccw), int(state.convex), double(state.creaseAngle));
        return sharedNodeKey(node) + key + " " + state.texture;
    }

    void place(const NodePtr& node, const State& state, int depth)
    {
        ctx_.placeInstance(instanceKey(*node, state), node->defName, state.world, node->where, [&] {
            State local = state;
            local.world = ctx_.frame;
            evaluate(node, local, Owner{}, node->defName, depth);
        });
    }

    void evaluate(const NodePtr& node, State& state, const Owner& owner, const std::string& path, int depth)
    {
        const Owner here = node->defName.empty() ? owner : ctx_.newOwner(instanceName(*node, owner), true);
        const std::string& t = node->type;
        const std::string at = path + "/" + t;
        if (t == "Separator") {
            State saved = state;
            follow(*node, saved, here, at, depth);
        } else if (t == "TransformSeparator") {
            const Mat4 world = state.world;
            follow(*node, state, here, at, depth);
            state.world = world;
        } else if (t == "Group" || t == "WWWAnchor" || t == "Switch" || t == "LOD") {
            follow(*node, state, here, at, depth);
        } else if (t == "WWWInline") {
            const FieldValue* name = node->field("name");
            ctx_.loadInline(name ? name->strings : std::vector<std::string>{}, node->where, state.world, here);
        } else if (!property(*node, state) && !shape(node, state, here, at)) {
            if (!ignoredNodeTypes().count(t))
                ctx_.scene.diagnostics.warn("unknown node", node->where, "node " + t + " ignored");
        }
    }

private:
    // The children vrml/traversal.h says a grouping node's evaluation follows, in the
    // current state; each adds its index to `path` unless it is a Switch's or LOD's choice.
    void follow(const Node& node, State& state, const Owner& owner, const std::string& path, int depth)
    {
        const TraversedChildren t = traversedChildren(node, true);
        for (const ChildRef& c : t.children)
            traverse(*c.node, state, owner, t.chosen ? path : path + "[" + std::to_string(c.index) + "]", depth + 1);
    }

    bool property(const Node& n, State& s)
    {
        const std::string& t = n.type;
        if (t == "Transform") s.world = s.world * transformMatrix(readTransformFields(n, "scaleFactor"));
        else if (t == "MatrixTransform") s.world = s.world * matrixFromRowVectors(exactNumbersField(n, "matrix"));
        else if (t == "Translation") s.world = s.world * Mat4::translation(exactVec3Field(n, "translation", {}));
        else if (t == "Scale") s.world = s.world * Mat4::scale(vec3Field(n, "scaleFactor", {1, 1, 1}));
        else if (t == "Rotation") {
            Vec3 axis{0, 0, 1};
            double angle = 0;
            rotationField(n, "rotation", axis, angle);
            s.world = s.world * Mat4::rotation(axis, angle);
        } else if (t == "Coordinate3") s.coords = floatsField(n, "point");
        else if (t == "Normal") s.normals = floatsField(n, "vector");
        else if (t == "TextureCoordinate2") s.texCoords = floatsField(n, "point");
        else if (t == "Texture2") {
            const FieldValue* file = n.field("filename");
            s.texture = file && !file->strings.empty() ? ctx_.resolveTexture(file->strings, n.where) : std::string();
        } else if (t == "NormalBinding") s.normalBinding = wordField(n, "value", "DEFAULT");
        else if (t == "MaterialBinding") s.materialBinding = wordField(n, "value", "OVERALL");
        else if (t == "Material") {
            s.diffuse = floatsField(n, "diffuseColor");
            s.transparency = floatsField(n, "transparency");
        } else if (t == "ShapeHints") {
            const std::string ordering = wordField(n, "vertexOrdering", "UNKNOWN_ORDERING");
            s.ccw = ordering != "CLOCKWISE";
            s.convex = wordField(n, "faceType", "CONVEX") != "UNKNOWN_FACE_TYPE";
            s.creaseAngle = floatField(n, "creaseAngle", 0.5f);
        } else {
            return false;
        }
        return true;
    }

    // Material list as RGBA (diffuse + 1 - transparency), one entry per diffuse color.
    std::vector<float> materialsRgba(const State& s) const
    {
        std::vector<float> rgba;
        if (!s.diffuse) return rgba;
        const size_t n = s.diffuse->size() / 3;
        for (size_t i = 0; i < n; ++i) {
            const float tr = s.transparency && !s.transparency->empty()
                                 ? (*s.transparency)[std::min(i, s.transparency->size() - 1)]
                                 : 0.0f;
            rgba.insert(rgba.end(), {(*s.diffuse)[3 * i], (*s.diffuse)[3 * i + 1], (*s.diffuse)[3 * i + 2], 1.0f - tr});
        }
        return rgba;
    }

    std::array<float, 4> firstMaterial(const std::vector<float>& rgba) const
    {
        if (rgba.size() < 4) return {0.8f, 0.8f, 0.8f, 1.0f};
        return {rgba[0], rgba[1], rgba[2], rgba[3]};
    }

    bool shape(const NodePtr& node, State& s, const Owner& owner, const std::string& path)
    {
        const Node& n = *node;
        const std::string& t = n.type;
        if (t == "IndexedLineSet") {
            ++ctx_.scene.stats.lineSets;
            return true;
        }
        if (t == "PointSet") {
            ++ctx_.scene.stats.pointSets;
            return true;
        }
        if (t != "IndexedFaceSet" && t != "Cube" && t != "Sphere" && t != "Cylinder" && t != "Cone") return false;
        if (!ctx_.admit(node, true)) return true;
        ++ctx_.scene.stats.shapes;
        const std::vector<float> materials = materialsRgba(s);
        Part& part = ctx_.part(ctx_.shapeOwner(owner, path), firstMaterial(materials), s.texture);
        const size_t before = part.triangleCount();
        emitShape(n, s, materials, part);
        countShapeTriangles(t, before, part, ctx_.scene.stats);
        return true;
    }

    void emitShape(const Node& n, const State& s, const std::vector<float>& materials, Part& part)
    {
        const std::string& t = n.type;
        if (t == "IndexedFaceSet") indexedFaceSet(n, s, materials, part);
        else if (t == "Cube")
            emitOwnedFaceSet(makeBox({floatField(n, "width", 2), floatField(n, "height", 2), floatField(n, "depth", 2)}),
                             n.where, s.world, part, ctx_);
        else if (t == "Sphere") emitOwnedFaceSet(makeSphere(floatField(n, "radius", 1)), n.where, s.world, part, ctx_);
        else if (t == "Cylinder")
            emitOwnedFaceSet(makeCylinder(floatField(n, "radius", 1), floatField(n, "height", 2), hasPart(n, "SIDES"),
                                          hasPart(n, "TOP"), hasPart(n, "BOTTOM")),
                             n.where, s.world, part, ctx_);
        else
            emitOwnedFaceSet(makeCone(floatField(n, "bottomRadius", 1), floatField(n, "height", 2), hasPart(n, "SIDES"),
                                      hasPart(n, "BOTTOM")),
                             n.where, s.world, part, ctx_);
    }

    static bool hasPart(const Node& n, const char* which)
    {
        const FieldValue* v = n.field("parts");
        if (!v || v->strings.empty()) return true;  // default ALL
        for (const std::string& p : v->strings)
            if (p == which || p == "ALL") return true;
        return false;
    }

    void indexedFaceSet(const Node& n, const State& s, const std::vector<float>& materials, Part& part)
    {
        FaceSetInput in;
        in.coords = s.coords;
        in.coordIndex = intsField(n, "coordIndex");
        in.where = n.where;
        if (!in.coords || !in.coordIndex) return;
        in.normals = bindingFor(s.normalBinding, s.normals, 3, indicesOrNull(n, "normalIndex"), in.coordIndex);
        if (materials.size() > 4 && s.materialBinding != "OVERALL" && s.materialBinding != "DEFAULT")
            in.colors = bindingFor(s.materialBinding, &materials, 4, indicesOrNull(n, "materialIndex"), in.coordIndex);
        in.texCoords = bindingFor("PER_VERTEX_INDEXED", s.texCoords, 2, indicesOrNull(n, "textureCoordIndex"),
                                  in.coordIndex);
        in.ccw = s.ccw;
        in.convex = s.convex;
        in.creaseAngle = s.creaseAngle;
        emitFaceSet(in, s.world, ctx_.emit, part, ctx_.scene.diagnostics, ctx_.scene.stats);
    }

    EvalContext& ctx_;
};

}  // namespace

void evaluateVrml10(const std::vector<NodePtr>& roots, const Mat4& world, const Owner& owner, const std::string& path,
                    EvalContext& ctx)
{
    Evaluator10 e(ctx);
    State state;
    state.world = world;
    for (size_t i = 0; i < roots.size(); ++i) e.traverse(roots[i], state, owner, path, 0);
}

}  // namespace cadlod::vrml
