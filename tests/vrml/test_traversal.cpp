// One set of traversal rules (vrml/traversal.h): the instancing budget counts exactly the
// children the evaluators follow. For each grouping node, the budget's triangle count of
// a subtree must equal what evaluating it emits. The node model allows NULL entries in a
// node list (the evaluators skip them); the budget used to keep its own copy of the rules
// and dropped NULLs before picking a Switch choice or an LOD level, so it counted another
// child than the one evaluated.
#include "vrml/evaluation.h"
#include "vrml/parser.h"

#include <gtest/gtest.h>

using namespace cadlod::vrml;

namespace {

struct Counted {
    uint64_t budget = 0;   // InstancingBudget's count, before anything is expanded
    size_t emitted = 0;    // triangles the evaluator emitted
};

Counted count(const std::vector<NodePtr>& roots, bool vrml1)
{
    Scene scene;
    ImportOptions options;
    EvalContext ctx(scene, options);
    ctx.loadInline = [](const std::vector<std::string>&, const std::string&, const Mat4&, const Owner&) {};
    Counted c;
    for (const NodePtr& r : roots)
        if (r) c.budget += ctx.budget.triangles(*r, vrml1);
    if (vrml1)
        evaluateVrml10(roots, Mat4::identity(), Owner{}, "", ctx);
    else
        evaluateVrml97(roots, Mat4::identity(), Owner{}, "", ctx);
    EXPECT_EQ(ctx.error, "");
    c.emitted = scene.triangleCount();
    return c;
}

std::vector<NodePtr> parse(const std::string& text)
{
    Diagnostics diag;
    ParsedFile f = parseVrml(text, "t.wrl", diag);
    EXPECT_EQ(f.error, "");
    return f.roots;
}

// Puts a NULL entry first in the root's node list `field` ("" = VRML 1.0 children).
void prependNull(const NodePtr& root, const char* field)
{
    if (!*field) {
        root->children.insert(root->children.begin(), nullptr);
        return;
    }
    for (Field& f : root->fields)
        if (f.name == field) f.value.nodes.insert(f.value.nodes.begin(), nullptr);
}

const char* kBox97 = "Shape { geometry Box {} }";

// `text` with a NULL put first in its root's node list `field`: evaluation emits `emitted`
// triangles and the budget counts as many.
void expectNullFirstCounted(const std::string& text, const char* field, bool vrml1, size_t emitted)
{
    const std::vector<NodePtr> roots = parse(text);
    ASSERT_FALSE(roots.empty()) << text;
    prependNull(roots.front(), field);
    const Counted c = count(roots, vrml1);
    EXPECT_EQ(c.emitted, emitted) << text;
    EXPECT_EQ(c.budget, c.emitted) << text;
}

}  // namespace

TEST(TraversalRules, Vrml97GroupsSwitchesAndLodsCountWhatIsEvaluated)
{
    const std::string b = kBox97;
    for (const std::string& body :
         {"Group { children [ " + b + " " + b + " ] }", "Transform { children [ " + b + " ] }",
          "CADPart { children [ " + b + " ] }", "Switch { whichChoice 1 choice [ " + b + " Group { children [ " + b +
                                                    " " + b + " ] } ] }",
          "Switch { whichChoice -1 choice [ " + b + " ] }", "Switch { whichChoice 5 choice [ " + b + " ] }",
          "LOD { level [ Group { children [ " + b + " " + b + " ] } " + b + " ] }"}) {
        const Counted c = count(parse("#VRML V2.0 utf8\n" + body), false);
        EXPECT_EQ(c.budget, c.emitted) << body;
    }
}

TEST(TraversalRules, Vrml1SeparatorsSwitchesAndLodsCountWhatIsEvaluated)
{
    for (const char* body :
         {"Separator { Cube {} Cube {} }", "Group { Cube {} }", "Switch { whichChild 1 Cube {} Separator { Cube {} Cube {} } }",
          "Switch { whichChild -3 Cube {} Cube {} }", "Switch { whichChild -1 Cube {} }",
          "LOD { Separator { Cube {} Cube {} } Cube {} }"}) {
        const Counted c = count(parse(std::string("#VRML V1.0 ascii\n") + body), true);
        EXPECT_EQ(c.budget, c.emitted) << body;
    }
}

TEST(TraversalRules, NullEntryBeforeTheChosenSwitchChoiceIsCountedAsEvaluated)
{
    // choice [ NULL, box ] with whichChoice 1: the box is evaluated, and counted.
    expectNullFirstCounted(std::string("#VRML V2.0 utf8\nSwitch { whichChoice 1 choice [ ") + kBox97 + " ] }",
                           "choice", false, 12);
    expectNullFirstCounted("#VRML V1.0 ascii\nSwitch { whichChild 1 Cube {} }", "", true, 12);
}

TEST(TraversalRules, LodWhoseFirstLevelIsNullCountsNothing)
{
    // level [ NULL, box ]: nothing is shown up close, nothing is evaluated or counted.
    expectNullFirstCounted(std::string("#VRML V2.0 utf8\nLOD { level [ ") + kBox97 + " ] }", "level", false, 0);
    expectNullFirstCounted("#VRML V1.0 ascii\nLOD { Cube {} }", "", true, 0);
}
