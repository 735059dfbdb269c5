// Parser: DEF/USE sharing and re-DEF, values without brackets, odd layout, PROTO,
// ROUTE, truncated and malformed files.
#include "vrml/parser.h"
#include "vrml_test_util.h"

#include <gtest/gtest.h>

using namespace cadlod::vrml;
using namespace cadlod::vrml::test;

namespace {
ParsedFile parse(const std::string& text, Diagnostics& diag) { return parseVrml(text, "p.wrl", diag); }

NodePtr fieldNode(const Node& n, const char* name)
{
    const FieldValue* v = n.field(name);
    return v && !v->nodes.empty() ? v->nodes[0] : nullptr;
}
}  // namespace

TEST(VrmlParser, RejectsFilesWithoutAVrmlHeader)
{
    Diagnostics diag;
    EXPECT_NE(parse("solid x\n", diag).error.find("not a VRML file"), std::string::npos);
    EXPECT_EQ(parse("#VRML V1.0 ascii\n", diag).version, VrmlVersion::V1);
    EXPECT_EQ(parse("#VRML V2.0 utf8\n", diag).version, VrmlVersion::V2);
}

TEST(VrmlParser, UseSharesTheNodeAndTheMostRecentDefWins)
{
    Diagnostics diag;
    const ParsedFile f = parse(R"(#VRML V2.0 utf8
Shape { geometry IndexedFaceSet { coord DEF C Coordinate { point [ 0 0 0 ] } } }
Shape { geometry IndexedFaceSet { coord USE C } }
Shape { geometry IndexedFaceSet { coord DEF C Coordinate { point [ 1 1 1, 2 2 2 ] } } }
Shape { geometry IndexedFaceSet { coord USE C } }
)", diag);
    ASSERT_EQ(f.roots.size(), 4u);
    auto coordOf = [](const NodePtr& shape) { return fieldNode(*fieldNode(*shape, "geometry"), "coord"); };
    EXPECT_EQ(coordOf(f.roots[0]), coordOf(f.roots[1]));  // same object: the array is not copied
    EXPECT_EQ(coordOf(f.roots[0])->field("point")->floats, coordOf(f.roots[1])->field("point")->floats);
    EXPECT_EQ(coordOf(f.roots[3]), coordOf(f.roots[2]));
    EXPECT_EQ(coordOf(f.roots[3])->field("point")->floats->size(), 6u);
    EXPECT_EQ(diag.total(), 0);
}

TEST(VrmlParser, UndefinedUseIsAWarningNotAFailure)
{
    Diagnostics diag;
    const ParsedFile f = parse("#VRML V2.0 utf8\nShape { appearance USE NOPE }\nGroup {}\n", diag);
    EXPECT_EQ(f.roots.size(), 2u);
    EXPECT_EQ(diag.count("undefined USE"), 1);
}

TEST(VrmlParser, ValuesWithoutBracketsAndFieldsSplitOverLines)
{
    Diagnostics diag;
    const ParsedFile f = parse("#VRML V2.0 utf8\nTransform\n{\ntranslation\n1\n2\n3 children\nShape\n{\n}\n"
                               "scale 2 2 2 }\n", diag);
    ASSERT_EQ(f.roots.size(), 1u);
    const Node& t = *f.roots[0];
    EXPECT_EQ(*t.field("translation")->floats, (std::vector<float>{1, 2, 3}));
    EXPECT_EQ(t.field("children")->nodes.size(), 1u);  // a single MFNode value without []
    EXPECT_EQ(*t.field("scale")->floats, (std::vector<float>{2, 2, 2}));
}

TEST(VrmlParser, IndexFieldsAreIntegersOtherNumbersFloats)
{
    Diagnostics diag;
    const ParsedFile f = parse("#VRML V2.0 utf8\nIndexedFaceSet { coordIndex [ 0 1 2 -1 ] creaseAngle 0.5 }\n", diag);
    const Node& n = *f.roots[0];
    ASSERT_EQ(n.field("coordIndex")->kind, FieldValue::Kind::Ints);
    EXPECT_EQ(*n.field("coordIndex")->ints, (std::vector<int32_t>{0, 1, 2, -1}));
    EXPECT_EQ(n.field("creaseAngle")->kind, FieldValue::Kind::Floats);
}

TEST(VrmlParser, RoutesAndScriptsAreSkipped)
{
    Diagnostics diag;
    const ParsedFile f = parse(R"(#VRML V2.0 utf8
DEF T TimeSensor { loop TRUE }
DEF S Script { eventIn SFTime tick field SFNode target USE T eventOut SFBool done url "javascript: x" }
ROUTE T.time TO S.tick
Group {}
)", diag);
    EXPECT_EQ(f.roots.size(), 3u);
    EXPECT_EQ(diag.total(), 0);
}

TEST(VrmlParser, ProtoInstanceBecomesItsBodyWithIsFieldsSubstituted)
{
    Diagnostics diag;
    const ParsedFile f = parse(R"(#VRML V2.0 utf8
PROTO Bolt [ field SFVec3f at 0 0 0  field SFFloat size 1 ] {
  Transform { translation IS at children Shape { geometry Box { size IS size } } }
}
Bolt { at 1 2 3 }
Bolt { size 5 }
)", diag);
    ASSERT_EQ(f.roots.size(), 2u);
    EXPECT_EQ(f.roots[0]->type, "Transform");
    EXPECT_EQ(*f.roots[0]->field("translation")->floats, (std::vector<float>{1, 2, 3}));
    EXPECT_EQ(*f.roots[1]->field("translation")->floats, (std::vector<float>{0, 0, 0}));
    const NodePtr box = fieldNode(*fieldNode(*f.roots[1], "children"), "geometry");
    EXPECT_EQ(*box->field("size")->floats, (std::vector<float>{5}));
    EXPECT_NE(f.roots[0], f.roots[1]);
}

TEST(VrmlParser, ProtoBodyDefUseStaysSharedInsideEachInstance)
{
    Diagnostics diag;
    const ParsedFile f = parse(R"(#VRML V2.0 utf8
PROTO Pair [] { Group { children [ DEF A Shape {} USE A ] } }
Pair {}
Pair {}
)", diag);
    ASSERT_EQ(f.roots.size(), 2u);
    const auto& a = f.roots[0]->field("children")->nodes;
    const auto& b = f.roots[1]->field("children")->nodes;
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[0], a[1]);
    EXPECT_NE(a[0], b[0]);
}

TEST(VrmlParser, Vrml1ChildrenAndBitMasks)
{
    Diagnostics diag;
    const ParsedFile f = parse(R"(#VRML V1.0 ascii
DEF Root Separator {
  Cylinder { parts (SIDES | TOP) }
  ShapeHints { vertexOrdering COUNTERCLOCKWISE }
}
)", diag);
    ASSERT_EQ(f.roots.size(), 1u);
    EXPECT_EQ(f.roots[0]->defName, "Root");
    ASSERT_EQ(f.roots[0]->children.size(), 2u);
    EXPECT_EQ(f.roots[0]->children[0]->field("parts")->strings, (std::vector<std::string>{"SIDES", "TOP"}));
    EXPECT_EQ(diag.total(), 0);
}
