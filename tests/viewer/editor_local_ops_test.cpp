// The editor's polygon operations: several selected elements (Shift+click, Ctrl+A, a hole),
// Delete, weld, and the interactive edits (extrude, bevel, move) confirmed, typed or
// cancelled. Each edit equals the core operations run directly; a cancel leaves the document
// bit for bit as it was, with no undo step.

#include <gtest/gtest.h>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/mesh_change.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/validate.h"
#include "meshedit/ops/ops.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"
#include "viewer/editor_test_util.h"

namespace meshedit::viewer {
namespace {

void type(Editor& ed, const std::string& text) {
    for (char c : text) {
        ed.modal_type(c);
    }
}

// Shift+click adds, a second Shift+click on the same element removes it again.
TEST(EditorPolygons, ShiftClickTogglesElements) {
    Editor ed = editor_with(test::quad_cube());
    ed.select(ElementRef::face(Face(0)));
    ed.toggle_select(ElementRef::face(Face(2)));
    ed.toggle_select(ElementRef::edge(Edge(3)));
    EXPECT_EQ(ed.selected().size(), 3u);
    EXPECT_EQ(ed.selection(), ElementRef::edge(Edge(3)));
    ed.toggle_select(ElementRef::face(Face(2)));
    EXPECT_EQ(ed.selected(),
              (std::vector<ElementRef>{ElementRef::face(Face(0)), ElementRef::edge(Edge(3))}));
    ed.toggle_select(ElementRef::edge(Edge(3)));  // the active one: the one before it takes over
    EXPECT_EQ(ed.selected(), std::vector<ElementRef>{ElementRef::face(Face(0))});
    EXPECT_EQ(ed.press(key_of('A'), kCtrl).message, "selected all 6 faces");
    EXPECT_EQ(ed.selected().size(), 6u);
    EXPECT_EQ(ed.press(key_of('A'), kAlt).message, "selection cleared");
    EXPECT_TRUE(ed.selected().empty());
}

// Delete on two faces of the cube makes both holes in one undo step, as make_boundary twice.
TEST(EditorPolygons, DeleteActsOnEverySelectedElementInOneStep) {
    const Mesh cube = test::quad_cube();
    Editor ed = editor_with(cube);
    ed.select(ElementRef::face(Face(0)));
    ed.toggle_select(ElementRef::face(Face(1)));
    ed.toggle_select(ElementRef::vertex(Vertex(2)));  // on face 0: dissolved first
    const Outcome out = ed.press(Key::Delete, 0);
    ASSERT_FALSE(out.refused) << out.message;
    Mesh expected = cube;
    ASSERT_TRUE(dissolve_vertex(expected, Vertex(2)));
    // Face 0 merged into the face dissolve_vertex returns; the steps name faces by index.
    if (!expected.is_deleted(Face(0))) {
        ASSERT_TRUE(make_boundary(expected, Face(0)));
    }
    ASSERT_TRUE(make_boundary(expected, Face(1)));
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    EXPECT_VALID(ed.mesh());
    EXPECT_EQ(ed.history().undo_steps(), 1u);
    ed.run({Command::Undo});
    EXPECT_TRUE(test::identical(ed.mesh(), cube));
}

// J welds the two selected boundary edges: the active one onto the one selected before it.
// The ends of a strip of three quads meet: a ring.
TEST(EditorPolygons, WeldTheTwoSelectedEdges) {
    const Mesh strip = test::quad_strip(3);
    Editor ed = editor_with(strip);
    const Edge left = edge_of(strip, 0, 4);
    const Edge right = edge_of(strip, 3, 7);
    ed.press(key_of('J'), 0);
    EXPECT_EQ(ed.press(key_of('J'), 0).message,
              "select two boundary edges first (click one, Shift+click the other)");
    ed.select(ElementRef::edge(left));
    ed.toggle_select(ElementRef::edge(right));
    const Outcome out = ed.press(key_of('J'), 0);
    ASSERT_FALSE(out.refused) << out.message;
    Mesh expected = strip;
    ASSERT_TRUE(weld(expected, right, left));
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    EXPECT_VALID(ed.mesh());
    // The status line names the edges as they were clicked; the result is the selection.
    EXPECT_EQ(out.message, "welded edges " + std::to_string(left.idx()) + " and " +
                               std::to_string(right.idx()) + " into one edge (selected)");
    EXPECT_EQ(ed.selection(), ElementRef::edge(right));
}

// Shift+L on a boundary edge selects its hole.
TEST(EditorPolygons, ShiftLSelectsTheHole) {
    Editor ed = editor_with(test::quad_strip(3));
    EXPECT_TRUE(ed.press(key_of('L'), kShift).refused);
    ed.select(ElementRef::edge(edge_of(ed.mesh(), 0, 1)));
    EXPECT_EQ(ed.press(key_of('L'), kShift).message, "selected the 8 edges of a hole");
    EXPECT_EQ(ed.selected().size(), 8u);
}

// Extrude with a drag and then a typed amount: the typed numbers win; Enter keeps it as one
// undo step equal to extrude_face; Esc after a drag restores the document bit for bit.
TEST(EditorPolygons, ExtrudeTypedConfirmedOrCancelled) {
    const Mesh cube = test::quad_cube();
    Editor ed = editor_with(cube);
    ed.select(ElementRef::face(Face(1)));
    ASSERT_FALSE(ed.press(key_of('X'), 0).refused);
    EXPECT_EQ(ed.modal(), Modal::Extrude);
    ModalInput in;
    in.dy = 40;
    in.pixel = 0.01;
    ed.modal_input(in);
    EXPECT_EQ(ed.mesh().n_faces(), 10u);  // live: the ring is there during the drag
    ed.press(Key::Escape, 0);
    EXPECT_EQ(ed.modal(), Modal::None);
    EXPECT_TRUE(test::identical(ed.mesh(), cube));
    EXPECT_EQ(ed.history().undo_steps(), 0u);
    EXPECT_FALSE(ed.dirty());

    ed.press(key_of('X'), 0);
    ed.modal_input(in);
    type(ed, "0.5,0.25");
    EXPECT_NE(ed.modal_status().find("height 0.5, shrink 0.25"), std::string::npos)
        << ed.modal_status();
    ASSERT_FALSE(ed.press(Key::Enter, 0).refused);
    Mesh expected = cube;
    ASSERT_TRUE(extrude_face(expected, Face(1), 0.5, 0.25));
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    EXPECT_EQ(ed.selection(), ElementRef::face(Face(1)));
    EXPECT_EQ(ed.history().undo_steps(), 1u);
    ed.run({Command::Undo});
    EXPECT_TRUE(test::identical(ed.mesh(), cube));
}

// An extrude drag builds its topology once: the first move runs the verb, every other move
// only places the corners it made (and re-blends what they carry) as a position amendment of
// the same recorded change. Two faces, 100 moves, a user attribute that blends: Enter gives,
// bit for bit, extrude_face() on each face at the last amounts, one undo step, and the
// session's steps at those amounts.
TEST(EditorPolygons, ExtrudeDragBuildsTheTopologyOnce) {
    Mesh cube = test::quad_cube();
    auto u = cube.add_property<Vertex, double>("v:u");
    for (Vertex v : cube.vertices()) {
        u[v] = 2.0 * cube.position(v).x - cube.position(v).z;
    }
    Editor ed = editor_with(cube);
    ed.select(ElementRef::face(Face(1)));
    ed.toggle_select(ElementRef::face(Face(2)));
    ASSERT_FALSE(ed.press(key_of('X'), 0).refused);
    ModalInput in;
    in.pixel = 0.01;
    for (int k = 1; k <= 100; ++k) {
        in.dy = 0.5 * k;
        in.dx = -0.3 * k;
        ed.modal_input(in);
    }
    EXPECT_EQ(ed.modal_counts().topology_changes, 1u);
    EXPECT_EQ(ed.modal_counts().position_amendments, 100u);
    const std::string status = ed.modal_status();
    ASSERT_FALSE(ed.press(Key::Enter, 0).refused) << status;
    EXPECT_EQ(ed.history().undo_steps(), 1u);

    // What the drag ended at, as the verbs run it from the session.
    const std::vector<std::string>& session = ed.document().session;
    ASSERT_GE(session.size(), 2u);
    Mesh expected = cube;
    std::vector<std::string> replayed;
    for (const std::string& text : std::vector<std::string>(session.end() - 2, session.end())) {
        const ops::Step step = ops::parse_step(text);
        EXPECT_EQ(step.verb->name, "extrude");
        ASSERT_TRUE(extrude_face(expected, Face(step.a), step.amounts[0], step.amounts[1]));
        replayed.push_back(text);
    }
    EXPECT_EQ(replayed[0].rfind("extrude:f1:", 0), 0u) << replayed[0];
    EXPECT_EQ(replayed[1].rfind("extrude:f2:", 0), 0u) << replayed[1];
    expect_as_replayed(ed, cube, expected);
}

// A bevel drag builds its faces once and then only places the corners (and derives what they
// carry again); bevels that touch one another run again at every move instead. Either way
// the result is bit for bit what the session's steps make.
void bevel_drag(const std::vector<Vertex>& vertices, std::size_t topology_changes) {
    Mesh cube = test::quad_cube();
    auto u = cube.add_property<Vertex, double>("v:u");
    auto corner = cube.add_property<Halfedge, double>("h:corner");
    for (Vertex v : cube.vertices()) {
        u[v] = 2.0 * cube.position(v).x - cube.position(v).z;
    }
    for (Halfedge h : cube.halfedges()) {
        corner[h] = 0.25 * h.idx();
    }
    Editor ed = editor_with(cube);
    ed.select(ElementRef::vertex(vertices[0]));
    for (std::size_t i = 1; i < vertices.size(); ++i) {
        ed.toggle_select(ElementRef::vertex(vertices[i]));
    }
    ASSERT_FALSE(ed.press(key_of('B'), kCtrl).refused);
    ModalInput in;
    for (int k = 1; k <= 100; ++k) {
        in.dx = 0.9 * k;
        ed.modal_input(in);
    }
    EXPECT_EQ(ed.modal_counts().topology_changes, topology_changes);
    EXPECT_EQ(ed.modal_counts().position_amendments + ed.modal_counts().topology_changes, 101u);
    const std::string status = ed.modal_status();
    ASSERT_FALSE(ed.press(Key::Enter, 0).refused) << status;
    EXPECT_EQ(ed.history().undo_steps(), 1u);

    const std::vector<std::string>& session = ed.document().session;
    ASSERT_GE(session.size(), vertices.size());
    Mesh expected = cube;
    for (auto text = session.end() - static_cast<std::ptrdiff_t>(vertices.size());
         text != session.end(); ++text) {
        const ops::Step step = ops::parse_step(*text);
        EXPECT_EQ(step.verb->name, "bevel");
        EXPECT_EQ(step.amounts[0], 0.3) << *text;  // 90 pixels at 300 a unit
        ASSERT_TRUE(bevel_vertex(expected, Vertex(step.a), step.amounts[0]));
    }
    expect_as_replayed(ed, cube, expected);
}

TEST(EditorPolygons, BevelDragBuildsTheTopologyOnce) {
    bevel_drag({Vertex(0), Vertex(6)}, 1);  // opposite corners of the cube: apart
}

TEST(EditorPolygons, BevelDragOfNeighboursRunsAgain) {
    bevel_drag({Vertex(0), Vertex(1)}, 101);  // one edge apart: the second reads the first
}

// A refused amount (shrink 1) applies nothing and says why.
TEST(EditorPolygons, RefusedAmountIsNotApplied) {
    const Mesh cube = test::quad_cube();
    Editor ed = editor_with(cube);
    ed.select(ElementRef::vertex(Vertex(0)));
    ed.press(key_of('B'), kCtrl);
    const Mesh shown = ed.mesh();  // the bevel's faces at amount 0
    type(ed, "1");
    EXPECT_NE(ed.modal_status().find("refused: cannot bevel"), std::string::npos);
    EXPECT_TRUE(test::identical(ed.mesh(), shown));  // the last amount that fits stays
    const Outcome out = ed.press(Key::Enter, 0);
    EXPECT_TRUE(out.refused);
    EXPECT_TRUE(test::identical(ed.mesh(), cube));
    EXPECT_EQ(ed.history().undo_steps(), 0u);
}

// M, Y, 2: the selected face's corners move 2 along +Y; R and Alt+S turn and scale about the
// centre; Esc puts them back.
TEST(EditorPolygons, MoveRotateScaleTheSelection) {
    const Mesh cube = test::quad_cube();
    Editor ed = editor_with(cube);
    ed.select(ElementRef::face(Face(1)));  // (4,5,6,7) at z = 1
    ed.press(key_of('M'), 0);
    ed.press(key_of('Y'), 0);
    ed.press(key_of('2'), 0);
    ASSERT_FALSE(ed.press(Key::Enter, 0).refused);
    for (std::uint32_t v = 0; v < 8; ++v) {
        const Vec3 want = cube.position(Vertex(v)) + Vec3{0.0, v >= 4 ? 2.0 : 0.0, 0.0};
        EXPECT_EQ(ed.mesh().position(Vertex(v)), want) << v;
    }
    ed.run({Command::Undo});
    ed.select(ElementRef::face(Face(1)));
    ed.press(key_of('S'), kAlt);
    ed.press(key_of('0'), 0);
    ed.press(Key::Period, 0);
    ed.press(key_of('5'), 0);
    ed.press(Key::Enter, 0);
    EXPECT_EQ(ed.mesh().position(Vertex(4)), (Vec3{-0.5, -0.5, 1.0}));
    ed.run({Command::Undo});
    ed.select(ElementRef::face(Face(1)));
    ed.press(key_of('R'), 0);
    ed.press(key_of('Z'), 0);
    ed.press(key_of('9'), 0);
    ed.press(key_of('0'), 0);
    ed.press(Key::Enter, 0);
    const Vec3 p = ed.mesh().position(Vertex(4));  // (−1, −1, 1) a quarter turn about z
    EXPECT_NEAR(p.x, 1.0, 1e-12);
    EXPECT_NEAR(p.y, -1.0, 1e-12);
    EXPECT_EQ(p.z, 1.0);
    ed.run({Command::Undo});
    ed.select(ElementRef::face(Face(1)));
    ed.press(key_of('M'), 0);
    ed.press(key_of('3'), 0);
    ed.press(Key::Escape, 0);
    EXPECT_TRUE(test::identical(ed.mesh(), cube));
    // A scale of 1e300 would overflow every normal: refused, nothing applied.
    ed.select(ElementRef::face(Face(1)));
    ed.press(key_of('S'), kAlt);
    type(ed, "1" + std::string(300, '0'));  // typed digits only: 10^300
    EXPECT_NE(ed.modal_status().find("refused: the amount puts corners beyond the range"),
              std::string::npos)
        << ed.modal_status();
    EXPECT_TRUE(ed.press(Key::Enter, 0).refused);
    EXPECT_TRUE(test::identical(ed.mesh(), cube));
}

// Loop on polygons is refused with the reason; Ctrl+T triangulates, then Loop runs.
TEST(EditorPolygons, LoopNeedsTriangulateFirst) {
    Editor ed = editor_with(test::quad_cube());
    const Outcome refused = ed.press(key_of('L'), 0);
    EXPECT_TRUE(refused.refused);
    EXPECT_NE(refused.message.find("6 of the 6 faces are polygons"), std::string::npos);
    EXPECT_NE(refused.message.find("Ctrl+T"), std::string::npos);
    EXPECT_EQ(ed.press(key_of('T'), kCtrl).message, "triangulated 6 faces");
    EXPECT_FALSE(ed.press(key_of('L'), 0).refused);
    EXPECT_EQ(ed.mesh().n_faces(), 48u);
}

}  // namespace
}  // namespace meshedit::viewer

namespace meshedit::viewer {
namespace {

TEST(EditorRewiring, AFlipShowsItsDiagramUntilUndoAndWholeMeshEditsShowNone) {
    Editor ed = editor_with(shapes::icosahedron());
    EXPECT_FALSE(ed.last_diagram().has_value());
    const Edge e(7);
    const std::string described = describe(ed.mesh(), ElementRef::edge(e));
    ed.select(ElementRef::edge(e));
    ASSERT_FALSE(ed.press(key_of('F'), 0).refused);
    ASSERT_TRUE(ed.last_diagram().has_value());
    EXPECT_EQ(ed.last_diagram()->title, "flip of " + described);
    EXPECT_EQ(ed.last_diagram()->changes.size(), 8u);  // six halfedges, two faces
    EXPECT_TRUE(ed.view().show_diagram);
    ed.press(key_of('R'), kAlt);
    EXPECT_FALSE(ed.view().show_diagram);
    ed.press(key_of('R'), kAlt);
    ed.press(key_of('Z'), kCtrl);
    EXPECT_FALSE(ed.last_diagram().has_value());
    // A collapse's diagram names the elements before the renumbering that follows it.
    ed.select(ElementRef::edge(e));
    ASSERT_FALSE(ed.press(key_of('C'), 0).refused);
    ASSERT_TRUE(ed.last_diagram().has_value());
    EXPECT_EQ(ed.last_diagram()->title, "collapse of " + described);
    ed.press(key_of('L'), 0);
    EXPECT_FALSE(ed.last_diagram().has_value());
}

// The diagram is built only while its panel is shown, and at a size where the copy of the
// mesh it once needed was refused (above 200,000 faces).
TEST(EditorRewiring, BuiltOnlyWhenShownAndAtAnySize) {
    Editor ed = editor_with(shapes::torus(300, 400));  // 240,000 triangles
    ed.press(key_of('R'), kAlt);
    ASSERT_FALSE(ed.view().show_diagram);
    ed.select(ElementRef::edge(Edge(5)));
    ASSERT_FALSE(ed.press(key_of('F'), 0).refused);
    EXPECT_FALSE(ed.last_diagram().has_value());
    ed.press(key_of('R'), kAlt);
    const std::string described = describe(ed.mesh(), ElementRef::edge(Edge(9)));
    ed.select(ElementRef::edge(Edge(9)));
    ASSERT_FALSE(ed.press(key_of('F'), 0).refused);
    ASSERT_TRUE(ed.last_diagram().has_value());
    EXPECT_EQ(ed.last_diagram()->title, "flip of " + described);
    EXPECT_EQ(ed.last_diagram()->changes.size(), 8u);
    // Reading the diagram undid and redid the flip: the undo step still restores the torus.
    ed.press(key_of('Z'), kCtrl);
    ed.press(key_of('Z'), kCtrl);
    EXPECT_TRUE(test::identical(ed.mesh(), shapes::torus(300, 400)));
}

}  // namespace
}  // namespace meshedit::viewer
