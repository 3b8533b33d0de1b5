// The edit language: parsing, naming steps, running them, and docs/cli.md's verb table.

#include <gtest/gtest.h>

#include <string>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/ops/ops.h"
#include "support/generated_text.h"
#include "support/mesh_compare.h"

namespace meshedit::ops {
namespace {

std::string syntax_error(std::string_view list) {
    try {
        parse(list);
    } catch (const SyntaxError& e) {
        return e.what();
    }
    ADD_FAILURE() << "'" << list << "' parsed";
    return {};
}

TEST(OpsLanguage, ParsesEveryShape) {
    const auto steps = parse("flip:0-6, split:12-3,loop,loop:3 ,triangulate,crease:1-2");
    ASSERT_EQ(steps.size(), 6u);
    EXPECT_EQ(steps[0].verb->name, "flip");
    EXPECT_EQ(steps[0].a, 0u);
    EXPECT_EQ(steps[0].b, 6u);
    EXPECT_EQ(steps[1].text, "split:12-3");
    EXPECT_EQ(steps[2].levels, 1);
    EXPECT_EQ(steps[3].levels, 3);
    EXPECT_EQ(steps[4].verb->shape, Shape::None);
    EXPECT_EQ(steps[5].verb->name, "crease");
}

TEST(OpsLanguage, SyntaxErrorsNameTheItem) {
    EXPECT_EQ(syntax_error("twist:0-1"),
              "unknown op 'twist:0-1' (expected flip:A-B, split:A-B, collapse:A-B, crease:A-B, "
              "loop, loop:K or triangulate)");
    EXPECT_EQ(syntax_error("flip:0"), "bad op 'flip:0': expected flip:A-B with two vertex indices");
    EXPECT_EQ(syntax_error("flip:3-3"), "bad op 'flip:3-3': an edge needs two different vertices");
    EXPECT_EQ(syntax_error("flip:0-99999999999"),
              "bad op 'flip:0-99999999999': expected flip:A-B with two vertex indices");
    EXPECT_EQ(syntax_error("loop:0"), "bad op 'loop:0': expected loop:K with K from 1 to 12");
    EXPECT_EQ(syntax_error("loop:13"), "bad op 'loop:13': expected loop:K with K from 1 to 12");
    EXPECT_EQ(syntax_error("triangulate:2"),
              "bad op 'triangulate:2': triangulate takes no argument");
    EXPECT_EQ(syntax_error("flip:0-6,,loop"), "empty op in --ops list 'flip:0-6,,loop'");
    EXPECT_EQ(syntax_error(""), "empty op in --ops list ''");
}

// The viewer names the selected edge as the language does, and the text parses back.
TEST(OpsLanguage, MakeStepNamesAnEdgeByItsEnds) {
    const Mesh cube = shapes::cube();
    const Edge e(5);
    const Step step = make_step("split", cube, e);
    EXPECT_EQ(step.text, "split:" + std::to_string(cube.vertex(e, 0).idx()) + "-" +
                             std::to_string(cube.vertex(e, 1).idx()));
    const Step again = parse_step(step.text);
    EXPECT_EQ(again.verb, step.verb);
    EXPECT_EQ(named_edge(cube, again), e);
    EXPECT_EQ(make_step("loop", cube).text, "loop");
}

TEST(OpsLanguage, StepsRunTheCoreOperations) {
    Mesh mesh = shapes::cube();
    Mesh expected = mesh;
    const Edge e = expected.find_edge(Vertex(0), Vertex(6));
    ASSERT_TRUE(e.is_valid());
    flip(expected, e);
    apply_steps(mesh, parse("flip:0-6"));
    EXPECT_TRUE(test::identical(mesh, expected));

    const StepResult split = run_step(mesh, parse_step("split:0-1"));
    EXPECT_EQ(split.selected, ElementRef::vertex(Vertex(8)));
    EXPECT_EQ(split.message.rfind("split edge ", 0), 0u);
    EXPECT_VALID(mesh);
}

TEST(OpsLanguage, RefusalsAndMissingElementsAreTold) {
    Mesh grid = shapes::grid(2, 2);
    try {
        apply_steps(grid, parse("flip:0-1"));
        FAIL() << "a boundary flip ran";
    } catch (const OpError& e) {
        EXPECT_TRUE(e.refused());
        EXPECT_STREQ(e.what(), "flip:0-1 refused: cannot flip: boundary edge");
    }
    try {
        apply_steps(grid, parse("collapse:0-99"));
        FAIL() << "a missing vertex was found";
    } catch (const OpError& e) {
        EXPECT_FALSE(e.refused());
        EXPECT_STREQ(e.what(), "collapse:0-99: no vertex 99 (the mesh has 9 vertices)");
    }
}

// A list whose Loop levels cannot fit is refused before any step runs.
TEST(OpsLanguage, LoopLevelsArePlannedBeforeAnyStep) {
    Mesh mesh = shapes::icosphere(3);
    const Mesh before = mesh;
    try {
        apply_steps(mesh, parse("split:0-1,loop:12"));
        FAIL() << "12 levels of a 1,280-face sphere ran";
    } catch (const OpError& e) {
        EXPECT_TRUE(e.refused());
        EXPECT_NE(std::string(e.what()).find("loop:12 refused: cannot subdivide: level"),
                  std::string::npos)
            << e.what();
    }
    EXPECT_TRUE(test::identical(mesh, before));
}

TEST(OpsLanguage, DocsTableIsGenerated) {
    EXPECT_TRUE(
        test::block_is_generated(MESHEDIT_SOURCE_DIR "/docs/cli.md", "ops", markdown_table()));
}

TEST(OpsLanguage, HelpListsEveryVerb) {
    const std::string help = help_lines();
    for (const Verb& verb : verbs()) {
        EXPECT_NE(help.find("  " + std::string(verb.syntax) + " "), std::string::npos) << verb.name;
        EXPECT_FALSE(verb.key_help.empty()) << verb.name;
        EXPECT_EQ(find_verb(verb.name), &verb);
    }
    EXPECT_EQ(help.find('`'), std::string::npos);
}

}  // namespace
}  // namespace meshedit::ops
