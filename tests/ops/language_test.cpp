// The edit language: parsing, naming steps, running them, and docs/cli.md's verb table.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/loop_steps.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/validate.h"
#include "meshedit/ops/ops.h"
#include "support/fixtures.h"
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
    EXPECT_EQ(steps[0].target, Target::Edge);
    EXPECT_EQ(steps[0].a, 0u);
    EXPECT_EQ(steps[0].b, 6u);
    EXPECT_EQ(steps[1].text, "split:12-3");
    EXPECT_EQ(steps[2].levels, 1);
    EXPECT_EQ(steps[3].levels, 3);
    EXPECT_EQ(steps[4].target, Target::None);
    EXPECT_EQ(steps[5].verb->name, "crease");
}

// Vertices as vI, faces as fI, two edges as A-B+C-D, amounts after a second colon; a list
// item that starts like a number is the step before it continued.
TEST(OpsLanguage, ParsesElementsAndAmounts) {
    const auto steps = parse(
        "dissolve:v12,extrude:f7:0.2, 0.9,weld:0-1+5-6,bevel:3-4:0.25,inset:f0:-0.5,"
        "extrude:f2:1e-3,collapse:f4,triangulate:f1");
    ASSERT_EQ(steps.size(), 8u);
    EXPECT_EQ(steps[0].target, Target::Vertex);
    EXPECT_EQ(steps[0].a, 12u);
    EXPECT_EQ(steps[1].target, Target::Face);
    EXPECT_EQ(steps[1].a, 7u);
    EXPECT_EQ(steps[1].amounts[0], 0.2);
    EXPECT_EQ(steps[1].amounts[1], 0.9);
    EXPECT_EQ(steps[1].text, "extrude:f7:0.2,0.9");
    EXPECT_EQ(steps[2].target, Target::EdgePair);
    EXPECT_EQ(steps[2].a, 0u);
    EXPECT_EQ(steps[2].b, 1u);
    EXPECT_EQ(steps[2].c, 5u);
    EXPECT_EQ(steps[2].d, 6u);
    EXPECT_EQ(steps[3].target, Target::Edge);
    EXPECT_EQ(steps[3].amounts[0], 0.25);
    EXPECT_EQ(steps[4].amounts[0], -0.5);
    EXPECT_EQ(steps[5].amounts[0], 1e-3);
    EXPECT_EQ(steps[5].amounts[1], 0.0);  // shrink defaults to 0
    EXPECT_EQ(steps[6].target, Target::Face);
    EXPECT_EQ(steps[7].verb->name, "triangulate");
    EXPECT_EQ(steps[7].target, Target::Face);
}

TEST(OpsLanguage, SyntaxErrorsNameTheItem) {
    EXPECT_EQ(
        syntax_error("twist:0-1"),
        "unknown op 'twist:0-1' (the verbs are flip, split, bisect, collapse, dissolve, "
        "make_boundary, fill, weld, poke, extrude, inset, bevel, extrude_region, inset_region, "
        "simplify_region, remesh_region, "
        "dissolve_region, subdivide_region, loop_region, catmull_clark_region, select, "
        "select_none, select_loop, select_ring, "
        "select_linked, select_more, select_less, select_invert, select_boundary, "
        "select_creases, select_valence, select_degree, crease, crease_by_angle, move, "
        "loop, loop_step, cc_step, catmull_clark, linear, simplify, remesh, smooth, smooth_cotan, "
        "taubin, smooth_implicit, smooth_region, fair, repair, merge_by_distance, "
        "stitch, remove_degenerate, orient, "
        "remove_small, fill_holes, fill_holes_fair, fill_fair, triangulate, flip_orientation or "
        "compact)");
    EXPECT_EQ(syntax_error("flip:0"),
              "bad op 'flip:0': expected flip:A-B with A-B (an edge by its two vertex indices)");
    EXPECT_EQ(syntax_error("flip:3-3"), "bad op 'flip:3-3': an edge needs two different vertices");
    EXPECT_EQ(syntax_error("flip:0-99999999999"),
              "bad op 'flip:0-99999999999': expected flip:A-B with A-B (an edge by its two "
              "vertex indices)");
    EXPECT_EQ(syntax_error("flip:v3"),
              "bad op 'flip:v3': expected flip:A-B with A-B (an edge by its two vertex indices)");
    EXPECT_EQ(syntax_error("dissolve:f3"),
              "bad op 'dissolve:f3': expected dissolve:vI, dissolve:A-B with vI (a vertex "
              "index) or A-B (an edge by its two vertex indices)");
    EXPECT_EQ(syntax_error("extrude:f3"),
              "bad op 'extrude:f3': expected extrude:fI:H, extrude:fI:H,S");
    EXPECT_EQ(syntax_error("extrude:f3:0.1,0.2,0.3"),
              "bad op 'extrude:f3:0.1,0.2,0.3': extrude takes at most 2 amounts "
              "(extrude:fI:H, extrude:fI:H,S)");
    EXPECT_EQ(syntax_error("bevel:v3:x"),
              "bad op 'bevel:v3:x': expected numbers after the element (bevel:vI:T, bevel:A-B:T)");
    EXPECT_EQ(syntax_error("flip:1-2:0.5"),
              "bad op 'flip:1-2:0.5': flip takes no amounts (flip:A-B)");
    EXPECT_EQ(syntax_error("weld:1-2+3-3"),
              "bad op 'weld:1-2+3-3': an edge needs two different vertices");
    EXPECT_EQ(syntax_error("loop:0"),
              "bad op 'loop:0': expected loop, loop:K, loop:K:uv=U with K from 1 to 12; U one of "
              "none, corners, corners+1, corners+2, boundaries, all");
    EXPECT_EQ(syntax_error("loop:13"),
              "bad op 'loop:13': expected loop, loop:K, loop:K:uv=U with K from 1 to 12; U one "
              "of none, corners, corners+1, corners+2, boundaries, all");
    EXPECT_EQ(syntax_error("flip_orientation:2"),
              "bad op 'flip_orientation:2': flip_orientation takes no argument");
    EXPECT_EQ(syntax_error("flip:0-6,,loop"), "empty op in --ops list 'flip:0-6,,loop'");
    EXPECT_EQ(syntax_error(""), "empty op in --ops list ''");
}

// simplify takes its attribute mode last, by name (after the amounts or alone); a wrong
// name is refused with the two, and no other verb takes one.
TEST(OpsLanguage, SimplifyTakesTheAttributeMode) {
    const auto steps =
        parse("simplify:attributes=blind, simplify:0.1,inf:attributes=aware, simplify:0.2");
    ASSERT_EQ(steps.size(), 3u);
    EXPECT_EQ(steps[0].attributes, SimplifyAttributes::Blind);
    EXPECT_EQ(steps[0].amounts[0], 0.5);
    EXPECT_EQ(steps[1].attributes, SimplifyAttributes::Aware);
    EXPECT_EQ(steps[1].amounts[0], 0.1);
    EXPECT_EQ(steps[2].attributes, std::nullopt);
    EXPECT_EQ(syntax_error("simplify:0.1:attributes=smart"),
              "bad op 'simplify:0.1:attributes=smart': unknown attribute mode 'smart' (aware: "
              "texture coordinates, colours and seams weigh; blind: positions only)");
    EXPECT_NE(syntax_error("remesh:attributes=blind"), "");
    EXPECT_NE(syntax_error("loop:attributes=blind"), "");
}

// The subdivisions take the texture coordinates' interpolation last, by name; a wrong name is
// refused with the names, and a verb that is no subdivision takes none.
TEST(OpsLanguage, SubdivisionsTakeTheUvInterpolation) {
    const auto steps = parse("loop:uv=none, catmull_clark:2:uv=corners+1, linear:uv=all, loop:2");
    ASSERT_EQ(steps.size(), 4u);
    EXPECT_EQ(steps[0].levels, 1);
    EXPECT_EQ(steps[0].uv, UvInterpolation::None);
    EXPECT_EQ(steps[1].levels, 2);
    EXPECT_EQ(steps[1].uv, UvInterpolation::CornersPlus1);
    EXPECT_EQ(steps[2].uv, UvInterpolation::All);
    EXPECT_EQ(steps[3].uv, std::nullopt);
    EXPECT_EQ(syntax_error("loop:uv=smooth"),
              "bad op 'loop:uv=smooth': unknown texture-coordinate interpolation 'smooth' (one of "
              "none, corners, corners+1, corners+2, boundaries, all)");
    EXPECT_EQ(syntax_error("flip:1-2:uv=none"),
              "bad op 'flip:1-2:uv=none': flip takes no amounts (flip:A-B)");
    EXPECT_EQ(syntax_error("loop_step:uv=none").rfind("bad op 'loop_step:uv=none': expected", 0),
              0u);

    // The step runs the core with that option: on a quad cube with a chart per face, `uv=all`
    // keeps the texture coordinates linear, `uv=none` smooths each chart's corners.
    Mesh cube = test::quad_cube();
    auto tex = cube.property<Halfedge, Vec2>(kTexCoordProperty, Vec2{});
    for (Face f : cube.faces()) {
        double k = 0;
        for (Halfedge h : cube.halfedges(f)) {
            tex[h] = {f.idx() + 0.25 * k, 0.5 * k * k};
            k += 1;
        }
    }
    Mesh linear = cube, by_step = cube, smooth = cube;
    QuadSubdivisionOptions all;
    all.uv = UvInterpolation::All;
    quad_subdivide(linear, all);
    apply_steps(by_step, parse("catmull_clark:uv=all"));
    apply_steps(smooth, parse("catmull_clark:uv=none"));
    const auto a = linear.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const auto b = by_step.get_property<Halfedge, Vec2>(kTexCoordProperty);
    const auto c = smooth.get_property<Halfedge, Vec2>(kTexCoordProperty);
    bool differs = false;
    for (Halfedge h : linear.halfedges()) {
        EXPECT_EQ(a[h], b[h]) << "halfedge " << h.idx();
        differs = differs || !(a[h] == c[h]);
    }
    EXPECT_TRUE(differs);
}

// The viewer names the selected edge as the language does, and the text parses back.
TEST(OpsLanguage, MakeStepNamesAnEdgeByItsEnds) {
    const Mesh cube = shapes::cube();
    const Edge e(5);
    const Step step = make_step("split", cube, ElementRef::edge(e));
    EXPECT_EQ(step.text, "split:" + std::to_string(cube.vertex(e, 0).idx()) + "-" +
                             std::to_string(cube.vertex(e, 1).idx()));
    const Step again = parse_step(step.text);
    EXPECT_EQ(again.verb, step.verb);
    EXPECT_EQ(named_edge(cube, again), e);
    EXPECT_EQ(make_step("loop", cube).text, "loop");
}

// Every element kind and amount the viewer can hand over is written so it reads back as the
// same step (amounts to the last bit).
TEST(OpsLanguage, MakeStepRoundTripsEveryKind) {
    const Mesh cube = shapes::cube();
    const double third = 1.0 / 3.0;
    const Step extrude =
        make_step("extrude", cube, ElementRef::face(Face(4)), std::vector<double>{third, 0.1});
    EXPECT_EQ(extrude.text, "extrude:f4:0.3333333333333333,0.1");
    const Step back = parse_step(extrude.text);
    EXPECT_EQ(back.amounts, extrude.amounts);
    EXPECT_EQ(back.a, 4u);
    EXPECT_EQ(make_step("extrude", cube, ElementRef::face(Face(4)), std::vector<double>{0.5}).text,
              "extrude:f4:0.5,0");
    EXPECT_EQ(make_step("dissolve", cube, ElementRef::vertex(Vertex(3))).text, "dissolve:v3");
    const Halfedge h(7);
    const Step from_halfedge =
        make_step("bevel", cube, ElementRef::halfedge(h), std::vector<double>{0.25});
    EXPECT_EQ(named_edge(cube, parse_step(from_halfedge.text)), Mesh::edge(h));
    const Step weld =
        make_step("weld", cube, ElementRef::edge(Edge(0)), {}, ElementRef::edge(Edge(9)));
    const Step weld_back = parse_step(weld.text);
    EXPECT_EQ(named_edge(cube, weld_back), Edge(0));
    EXPECT_EQ(named_second_edge(cube, weld_back), Edge(9));
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
    try {
        apply_steps(grid, parse("poke:f8"));
        FAIL() << "a missing face was found";
    } catch (const OpError& e) {
        EXPECT_FALSE(e.refused());
        EXPECT_STREQ(e.what(), "poke:f8: no face 8 (the mesh has 8 faces)");
    }
    // Absurd amounts are the operation's to refuse, by name, with the mesh untouched.
    const Mesh before = grid;
    for (const char* list : {"extrude:f0:nan", "extrude:f0:0.1,1", "inset:f0:1e300", "bevel:v4:1",
                             "bevel:v4:-0.1", "inset:f0:inf"}) {
        SCOPED_TRACE(list);
        try {
            apply_steps(grid, parse(list));
            FAIL() << "ran";
        } catch (const OpError& e) {
            EXPECT_TRUE(e.refused());
        } catch (const SyntaxError& e) {
            EXPECT_NE(std::string(e.what()).find("bad op"), std::string::npos);
        }
        EXPECT_TRUE(test::identical(grid, before));
    }
}

// A region is faces and ranges joined by '+', written back sorted and merged into ranges;
// a missing face is bad input, a refusal names the reason.
TEST(OpsLanguage, RegionsParseRoundTripAndRefuse) {
    const Step step = parse_step("extrude_region:f1..3+f7:0.5");
    ASSERT_EQ(step.target, Target::Region);
    EXPECT_EQ(step.region, (std::vector<std::array<std::uint32_t, 2>>{{1, 3}, {7, 7}}));
    EXPECT_EQ(step.amounts[0], 0.5);
    const double h = 0.5;
    EXPECT_EQ(make_region_step("extrude_region", {Face(7), Face(3), Face(1), Face(2)},
                               std::span<const double>(&h, 1))
                  .text,
              "extrude_region:f1..3+f7:0.5");
    EXPECT_EQ(make_region_step("subdivide_region", {Face(4)}).text, "subdivide_region:f4");
    EXPECT_EQ(syntax_error("extrude_region:f3..1:0.5"),
              "bad op 'extrude_region:f3..1:0.5': a range fI..J needs I <= J");
    EXPECT_EQ(syntax_error("subdivide_region:3-4"),
              "bad op 'subdivide_region:3-4': expected subdivide_region:R with R (faces: fI or "
              "fI..J, joined by +; sel: the selected faces)");
    EXPECT_EQ(syntax_error("extrude_region:f1"),
              "bad op 'extrude_region:f1': expected extrude_region:R:H");

    Mesh grid = shapes::quad_grid(3, 3);
    try {
        apply_steps(grid, parse("subdivide_region:f8..9"));
        FAIL() << "a missing face was found";
    } catch (const OpError& e) {
        EXPECT_FALSE(e.refused());
        EXPECT_STREQ(e.what(), "subdivide_region:f8..9: no face 9 (the mesh has 9 faces)");
    }
    Mesh cube = test::quad_cube();
    const Mesh before = cube;
    try {
        apply_steps(cube, parse("extrude_region:f0..5:1"));
        FAIL() << "a closed surface was extruded";
    } catch (const OpError& e) {
        EXPECT_TRUE(e.refused());
        EXPECT_STREQ(e.what(),
                     "extrude_region:f0..5:1 refused: cannot extrude the region: it is a whole "
                     "closed surface, with no border to extrude from");
    }
    EXPECT_TRUE(test::identical(cube, before));
    // The run selects the whole region.
    const StepsRun run = run_steps(grid, parse("extrude_region:f3..5:0.5"), OnRefusal::Stop);
    EXPECT_EQ(run.made.size(), 3u);
    EXPECT_VALID(grid);
}

// A list carries a selection: select_ verbs set it, `sel` names its faces in a region verb,
// and what a step makes is selected after it (a script's way to the viewer's keys).
TEST(OpsLanguage, SelectionVerbsFeedTheRegionVerbs) {
    Mesh grid = shapes::quad_grid(5, 5);
    Mesh direct = grid;
    // The centre face, grown twice: the middle 3 x 3, then the whole grid (5 x 5).
    StepsRun run = run_steps(grid, parse("select:f12,select_more"), OnRefusal::Stop);
    EXPECT_EQ(run.selection.indices, (std::vector<std::uint32_t>{6, 7, 8, 11, 12, 13, 16, 17, 18}));
    run = run_steps(grid, parse("select:f12,select_more,extrude_region:sel:0.5"), OnRefusal::Stop);
    apply_steps(direct, parse("extrude_region:f6..8+f11..13+f16..18:0.5"));
    EXPECT_TRUE(test::identical(grid, direct));
    EXPECT_EQ(run.selection.indices.size(), 9u);  // the top stays selected
    // Loops and rings are edges; linked, invert and the traits.
    Mesh flat = shapes::quad_grid(5, 4);
    run = run_steps(flat, parse("select_loop:14-15"), OnRefusal::Stop);
    EXPECT_EQ(run.selection.kind, ElementRef::Kind::Edge);
    EXPECT_EQ(run.selection.indices.size(), 5u);
    run = run_steps(flat, parse("select_ring:14-15"), OnRefusal::Stop);
    EXPECT_EQ(run.selection.indices.size(), 5u);
    EXPECT_EQ(
        run_steps(flat, parse("select:f0,select_linked"), OnRefusal::Stop).selection.indices.size(),
        20u);
    EXPECT_EQ(
        run_steps(flat, parse("select:f0,select_invert"), OnRefusal::Stop).selection.indices.size(),
        19u);
    EXPECT_EQ(run_steps(flat, parse("select_boundary"), OnRefusal::Stop).selection.indices.size(),
              14u);
    EXPECT_EQ(run_steps(flat, parse("select_valence:3"), OnRefusal::Stop).selection.indices.size(),
              14u);
    EXPECT_EQ(run_steps(flat, parse("select_degree:4"), OnRefusal::Stop).selection.indices.size(),
              20u);
    EXPECT_TRUE(
        run_steps(flat, parse("select_creases"), OnRefusal::Stop).selection.indices.empty());
    // `sel` with no faces selected is refused with the reason; the mesh is as it was.
    const Mesh before = flat;
    try {
        apply_steps(flat, parse("select_loop:14-15,dissolve_region:sel"));
        FAIL() << "a region of edges was dissolved";
    } catch (const OpError& e) {
        EXPECT_TRUE(e.refused());
        EXPECT_STREQ(e.what(),
                     "dissolve_region:sel refused: the selection holds no faces (select:R, or a "
                     "select_ verb, picks them first)");
    }
    EXPECT_TRUE(test::identical(flat, before));
}

// `select` lists vertices or edges too (what the viewer records for a region selection of
// that kind), one kind per step; select_step_text() writes what parses back to the same
// selection, and `select_none` empties it.
TEST(OpsLanguage, SelectListsVerticesAndEdgesAndWritesBack) {
    Mesh grid = shapes::quad_grid(5, 4);  // vertex (i, j) = 6j + i
    StepsRun run = run_steps(grid, parse("select:v0..2+v6"), OnRefusal::Stop);
    EXPECT_EQ(run.selection.kind, ElementRef::Kind::Vertex);
    EXPECT_EQ(run.selection.indices, (std::vector<std::uint32_t>{0, 1, 2, 6}));
    run = run_steps(grid, parse("select:v0,select_more"), OnRefusal::Stop);
    EXPECT_EQ(run.selection.indices.size(), 3u);  // the corner and its two neighbours
    run = run_steps(grid, parse("select:14-15+15-16"), OnRefusal::Stop);
    ASSERT_EQ(run.selection.kind, ElementRef::Kind::Edge);
    ASSERT_EQ(run.selection.indices.size(), 2u);
    EXPECT_EQ(Edge(run.selection.indices[0]), grid.find_edge(Vertex(14), Vertex(15)));
    EXPECT_TRUE(
        run_steps(grid, parse("select:f3,select_none"), OnRefusal::Stop).selection.indices.empty());
    EXPECT_EQ(syntax_error("select:f1+v2"),
              "bad op 'select:f1+v2': one kind of element per step (faces fI, vertices vI or "
              "edges A-B)");
    EXPECT_EQ(syntax_error("extrude_region:v1:0.5"),
              "bad op 'extrude_region:v1:0.5': expected extrude_region:R:H with R (faces: fI or "
              "fI..J, joined by +; sel: the selected faces)");
    try {
        apply_steps(grid, parse("select:3-10"));
        FAIL() << "an edge that is not there was selected";
    } catch (const OpError& e) {
        EXPECT_FALSE(e.refused());
    }

    // Written back: sorted ranges of the active element's kind (a halfedge as its edge).
    const Edge e1415 = grid.find_edge(Vertex(14), Vertex(15));
    const std::vector<ElementRef> edges = {ElementRef::edge(grid.find_edge(Vertex(15), Vertex(16))),
                                           ElementRef::halfedge(grid.halfedge(e1415, 1))};
    const std::string text = select_step_text(grid, edges);
    run = run_steps(grid, parse(text), OnRefusal::Stop);
    std::vector<std::uint32_t> want = {edges[0].index, e1415.idx()};
    std::sort(want.begin(), want.end());
    std::vector<std::uint32_t> got = run.selection.indices;
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, want) << text;
    EXPECT_EQ(select_step_text(grid, {ElementRef::face(Face(9)), ElementRef::face(Face(7)),
                                      ElementRef::face(Face(8)), ElementRef::face(Face(2))}),
              "select:f2+f7..9");
    EXPECT_EQ(
        select_step_text(grid, {ElementRef::vertex(Vertex(4)), ElementRef::vertex(Vertex(3))}),
        "select:v3..4");
    EXPECT_EQ(select_step_text(grid, {}), "select_none");
}

// Loop refuses polygons, counting them and naming the step that makes it possible.
TEST(OpsLanguage, LoopRefusesPolygonsAndSaysWhy) {
    Mesh mesh = shapes::quad_sphere(1);
    const Mesh before = mesh;
    try {
        apply_steps(mesh, parse("loop"));
        FAIL() << "Loop ran on quads";
    } catch (const OpError& e) {
        EXPECT_TRUE(e.refused());
        EXPECT_STREQ(e.what(),
                     "loop refused: cannot subdivide: Loop needs triangles and 6 of the 6 faces "
                     "are polygons (triangulate them first: the `triangulate` step, Ctrl+T in "
                     "the viewer)");
    }
    EXPECT_TRUE(test::identical(mesh, before));
    apply_steps(mesh, parse("triangulate,loop"));
    EXPECT_EQ(mesh.n_faces(), 48u);
    EXPECT_VALID(mesh);
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

// Found by fuzz_session (tests/fuzz/regressions/session/phased_loop_then_simplify.txt): in
// the middle of a phased Loop, simplify and remesh are refused as the subdivisions are (they
// would rebuild the mesh under the phases' marks, and the next phase threw), and a local edit
// that deletes elements leaves a mesh the next phase still splits.
TEST(OpsLanguage, APhasedLoopRefusesSimplifyAndRemeshAndSurvivesACollapse) {
    const char* const refused[][2] = {
        {"loop_step,simplify",
         "simplify refused: cannot simplify: a phased Loop is under way (phase 2 of 4 is next: "
         "`loop_step:3` finishes it, undo goes back)"},
        {"loop_step:2,remesh",
         "remesh refused: cannot remesh: a phased Loop is under way (phase 3 of 4 is next: "
         "`loop_step:2` finishes it, undo goes back)"},
    };
    for (const auto& [list, message] : refused) {
        SCOPED_TRACE(list);
        Mesh mesh = shapes::icosahedron();
        try {
            apply_steps(mesh, parse(list));
            FAIL() << "ran";
        } catch (const OpError& e) {
            EXPECT_TRUE(e.refused());
            EXPECT_STREQ(e.what(), message);
        }
        EXPECT_VALID(mesh);
    }
    Mesh mesh = shapes::icosahedron();
    apply_steps(mesh, parse("loop_step,collapse:0-1,dissolve:v2,loop_step:3"));
    EXPECT_EQ(next_loop_phase(mesh), 1);
    EXPECT_VALID(mesh);
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

namespace meshedit::ops {
namespace {

// The table, not the programs, knows which verbs change the connectivity and get a rewiring
// diagram: a crease mark and a move do neither; whole-mesh steps get no diagram, nor do the
// region verbs (their neighbourhood is the whole region).
TEST(VerbTraits, CreaseAndMoveKeepTheConnectivityAndDrawNoDiagram) {
    for (const Verb& verb : verbs()) {
        const bool keeps = verb.name == "crease" || verb.name == "crease_by_angle" ||
                           verb.name == "move" || verb.select != nullptr;
        const bool region = (verb.takes & kRegion) != 0;
        EXPECT_EQ((verb.traits & kChangesTopology) != 0, !keeps) << verb.name;
        EXPECT_EQ((verb.traits & kDrawsDiagram) != 0, !keeps && !region) << verb.name;
    }
    EXPECT_FALSE(draws_diagram(parse_step("extrude_region:f1..3+f7:0.5")));
    EXPECT_TRUE(draws_diagram(parse_step("flip:0-6")));
    EXPECT_TRUE(draws_diagram(parse_step("dissolve:v3")));
    EXPECT_FALSE(draws_diagram(parse_step("crease:0-6")));
    EXPECT_FALSE(draws_diagram(parse_step("move:v2:0,0,1")));
    EXPECT_FALSE(draws_diagram(parse_step("loop")));
    EXPECT_FALSE(draws_diagram(parse_step("triangulate")));
}

// The diagram's names and the tool amounts are facts of the table too.
TEST(VerbTraits, DiagramNamesAndToolAmountsComeFromTheTable) {
    for (const Verb& verb : verbs()) {
        const CodeNames expected = verb.name == "flip"       ? CodeNames::Flip
                                   : verb.name == "split"    ? CodeNames::Split
                                   : verb.name == "collapse" ? CodeNames::Collapse
                                                             : CodeNames::ByIndex;
        EXPECT_EQ(verb.names, expected) << verb.name;
        const bool tool = verb.name == "simplify" || verb.name == "remesh" ||
                          verb.name == "smooth" || verb.name == "smooth_cotan" ||
                          verb.name == "taubin" || verb.name == "smooth_implicit" ||
                          verb.name == "crease_by_angle";
        EXPECT_EQ((verb.traits & kToolAmounts) != 0, tool) << verb.name;
        // Tool amounts are for whole-mesh verbs; element verbs with amounts are drags.
        if (tool) {
            EXPECT_TRUE(verb.accepts(Target::None)) << verb.name;
        }
    }
}

// simplify:R,E: a share below 1 or a whole number of faces, and an error bound that is left
// out of the text when there is none; each form is one rounding in the verb.
TEST(OpsLanguage, SimplifyTakesAShareOrAFaceCountAndABound) {
    const Mesh ball = shapes::icosphere(3);  // 1,280 triangles
    const double none = std::numeric_limits<double>::infinity();
    EXPECT_EQ(make_step("simplify", ball, {}, std::array{0.5, none}).text, "simplify:0.5");
    EXPECT_EQ(make_step("simplify", ball).text, "simplify:0.5");
    EXPECT_EQ(make_step("simplify", ball, {}, std::array{300.0, 0.001}).text, "simplify:300,0.001");
    EXPECT_TRUE(std::isinf(parse_step("simplify:0.25").amounts[1]));

    Mesh share = ball;
    apply_steps(share, parse("simplify:0.25"));
    EXPECT_EQ(share.n_faces(), 320u);
    EXPECT_TRUE(!validate(share).has_value());
    Mesh count = ball;
    apply_steps(count, parse("simplify:300"));
    EXPECT_EQ(count.n_faces(), 300u);
    EXPECT_TRUE(!validate(count).has_value());
    // A tiny bound stops at once and says why.
    Mesh bounded = ball;
    std::vector<std::string> notices;
    ApplyOptions options;
    options.notice = [&](const std::string& n) { notices.push_back(n); };
    apply_steps(bounded, parse("simplify:10,1e-9"), options);
    ASSERT_EQ(notices.size(), 1u);
    EXPECT_EQ(notices[0].rfind("simplify:10,1e-9: stopped at 1280 faces: ", 0), 0u) << notices[0];
    EXPECT_NE(notices[0].find("the next collapse exceeds the error bound 1e-09"), std::string::npos)
        << notices[0];

    for (const auto& [text, reason] : std::vector<std::pair<std::string, std::string>>{
             {"simplify:1.5",
              "cannot simplify: keep a share of the faces above 0 and below 1, "
              "or a whole number of faces, not 1.5"},
             {"simplify:-0.5", "not -0.5"},
             {"simplify:1280", "the target must be from 1 to 1279 faces (the mesh has 1280)"},
             {"simplify:0", "the target must be from 1 to 1279 faces"},
             {"simplify:0.5,-1", "the error bound must be a number of 0 or more"}}) {
        Mesh untouched = ball;
        try {
            apply_steps(untouched, parse(text));
            ADD_FAILURE() << text << " ran";
        } catch (const OpError& e) {
            EXPECT_TRUE(e.refused());
            EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
        }
        EXPECT_TRUE(test::identical(untouched, ball)) << text;
    }
}

// OnRefusal::Skip runs what it can and names the first refusal; Stop throws at it; each
// step's check runs once either way (the list's steps that ran are pointers into it).
TEST(OpsLanguage, RunStepsStopsOrSkipsRefusals) {
    const Mesh quad = test::two_triangles();  // 0-2 is the only interior edge
    const std::vector<Step> steps = parse("flip:0-1,flip:0-2,split:0-1");
    Mesh skipped = quad;
    const StepsRun run = run_steps(skipped, steps, OnRefusal::Skip);
    EXPECT_EQ(run.ran, 2u);
    EXPECT_EQ(run.refused, 1u);
    EXPECT_EQ(run.first_refusal, "flip:0-1: cannot flip: boundary edge");
    ASSERT_EQ(run.done.size(), 2u);
    EXPECT_EQ(run.done[0], &steps[1]);
    EXPECT_EQ(run.done[1], &steps[2]);
    EXPECT_EQ(run.made.size(), 2u);
    EXPECT_TRUE(!validate(skipped).has_value());

    Mesh stopped = quad;
    try {
        run_steps(stopped, steps, OnRefusal::Stop);
        ADD_FAILURE() << "ran";
    } catch (const OpError& e) {
        EXPECT_EQ(std::string(e.what()), "flip:0-1 refused: cannot flip: boundary edge");
    }
    EXPECT_TRUE(test::identical(stopped, quad));
}

// One grammar names an element in --ops, --select and the session; --select's older
// spellings stay accepted.
TEST(OpsLanguage, ElementNamesHaveOneGrammar) {
    using K = ElementRef::Kind;
    const auto is = [](std::string_view text, K kind, std::uint32_t a, std::uint32_t b = 0) {
        const std::optional<ElementName> n = parse_element_name(text);
        ASSERT_TRUE(n.has_value()) << text;
        EXPECT_EQ(n->kind, kind) << text;
        EXPECT_EQ(n->a, a) << text;
        if (kind == K::Edge || kind == K::Halfedge) {
            EXPECT_EQ(n->b, b) << text;
        }
    };
    is("v12", K::Vertex, 12);
    is("v:12", K::Vertex, 12);
    is("f7", K::Face, 7);
    is("f:7", K::Face, 7);
    is("3-4", K::Edge, 3, 4);
    is("e:3-4", K::Edge, 3, 4);
    is("h3-4", K::Halfedge, 3, 4);
    is("h:3-4", K::Halfedge, 3, 4);
    for (const char* bad : {"", "v", "v:", "vx", "3-", "-4", "3", "e3-4", "x:3", "v-1", "f1.5",
                            "h3", "3-4-5", "v99999999999"}) {
        EXPECT_FALSE(parse_element_name(bad).has_value()) << bad;
    }
    // The steps read elements with it.
    EXPECT_EQ(parse_step("dissolve:v12").a, 12u);
    EXPECT_EQ(parse_step("flip:3-4").b, 4u);
    EXPECT_NE(syntax_error("flip:h3-4").find("expected flip:A-B"), std::string::npos);
}

}  // namespace
}  // namespace meshedit::ops
