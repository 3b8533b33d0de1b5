// The editor's selection: moving it through the connectivity (N T H V E G), its
// description and info rows, and drags (one undo step each).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/core/validate.h"
#include "meshedit/io/io.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"
#include "viewer/editor_test_util.h"

namespace meshedit::viewer {
namespace {

// ------------------------------------------------------------------------------ navigation

TEST(Editor, NavigationFollowsTheMeshApi) {
    const Mesh cube = shapes::cube();
    Editor ed = editor_with(cube);
    const Halfedge h = cube.find_halfedge(Vertex(0), Vertex(6));
    ASSERT_TRUE(h.is_valid());
    const auto selected = [&](Kind kind, std::uint32_t index) {
        EXPECT_EQ(ed.selection().kind, kind);
        EXPECT_EQ(ed.selection().index, index);
    };

    ed.select(ElementRef::halfedge(h));
    Outcome out = ed.press(key_of('N'), 0);
    EXPECT_EQ(out.changes, unsigned{kSelection});
    selected(Kind::Halfedge, cube.next(h).idx());
    ed.press(key_of('T'), 0);
    selected(Kind::Halfedge, Mesh::twin(cube.next(h)).idx());

    ed.select(ElementRef::halfedge(h));
    out = ed.press(key_of('V'), 0);
    selected(Kind::Vertex, 0);  // the source, as CS184's halfedge->vertex()
    EXPECT_EQ(out.message, "vertex 0 (the halfedge's source)");
    ed.press(key_of('H'), 0);
    selected(Kind::Halfedge, cube.halfedge(Vertex(0)).idx());

    ed.select(ElementRef::halfedge(h));
    ed.press(key_of('E'), 0);
    selected(Kind::Edge, Mesh::edge(h).idx());
    ed.press(key_of('H'), 0);
    selected(Kind::Halfedge, Mesh::halfedge(Mesh::edge(h), 0).idx());
    ed.select(ElementRef::edge(Mesh::edge(h)));
    ed.press(key_of('V'), 0);
    selected(Kind::Vertex, cube.from_vertex(Mesh::halfedge(Mesh::edge(h), 0)).idx());

    ed.select(ElementRef::halfedge(h));
    ed.press(key_of('G'), 0);
    selected(Kind::Face, cube.face(h).idx());
    const Face f = cube.face(h);
    ed.press(key_of('H'), 0);
    selected(Kind::Halfedge, cube.halfedge(f).idx());
    ed.select(ElementRef::face(f));
    ed.press(key_of('E'), 0);
    selected(Kind::Edge, Mesh::edge(cube.halfedge(f)).idx());
    ed.select(ElementRef::face(f));
    ed.press(key_of('V'), 0);
    selected(Kind::Vertex, cube.from_vertex(cube.halfedge(f)).idx());
    ed.press(key_of('E'), 0);
    selected(Kind::Edge, Mesh::edge(cube.halfedge(cube.from_vertex(cube.halfedge(f)))).idx());
    ed.press(key_of('G'), 0);
    EXPECT_EQ(ed.selection().kind, Kind::Face);

    // Staying put is not an error; navigation never edits.
    ed.select(ElementRef::halfedge(h));
    out = ed.press(key_of('H'), 0);
    EXPECT_FALSE(out.refused);
    EXPECT_EQ(out.message, "already a halfedge");
    selected(Kind::Halfedge, h.idx());
    EXPECT_EQ(ed.history().undo_steps(), 0u);
    EXPECT_FALSE(ed.dirty());
    EXPECT_TRUE(test::identical(ed.mesh(), cube));
}

TEST(Editor, NavigationRefusals) {
    const Mesh grid = shapes::grid(2, 2);
    Editor ed = editor_with(grid);
    Outcome out = ed.press(key_of('N'), 0);
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, "select a halfedge first (N and T move along halfedges)");
    ed.select(ElementRef::edge(Edge(0)));
    EXPECT_TRUE(ed.press(key_of('T'), 0).refused);
    EXPECT_EQ(ed.selection().kind, Kind::Edge);

    const Halfedge b = boundary_halfedge(grid);
    ed.select(ElementRef::halfedge(b));
    out = ed.press(key_of('G'), 0);
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, "the halfedge is on the boundary: it has no face");
    EXPECT_EQ(ed.selection().index, b.idx());
    // Its edge does have a face (on the other side).
    ed.press(key_of('E'), 0);
    ed.press(key_of('G'), 0);
    EXPECT_EQ(ed.selection().kind, Kind::Face);
    EXPECT_EQ(ed.selection().index, grid.face(Mesh::twin(b)).idx());

    // An isolated vertex has no halfedge, edge or face.
    Mesh lonely = grid;
    const Vertex v = lonely.new_vertex({5, 5, 5});
    Editor ed2 = editor_with(lonely);
    ed2.select(ElementRef::vertex(v));
    EXPECT_TRUE(ed2.press(key_of('H'), 0).refused);
    EXPECT_TRUE(ed2.press(key_of('E'), 0).refused);
    EXPECT_TRUE(ed2.press(key_of('G'), 0).refused);
    EXPECT_EQ(ed2.selection().index, v.idx());
}

// ----------------------------------------------------------------------- describe, info

TEST(Editor, DescribeAndInfo) {
    const Mesh cube = shapes::cube();
    const Edge e = edge_of(cube, 0, 6);
    const Halfedge h = Mesh::halfedge(e, 0);
    const std::string a = std::to_string(cube.from_vertex(h).idx());
    const std::string b = std::to_string(cube.to_vertex(h).idx());
    EXPECT_EQ(describe(cube, ElementRef::edge(e)),
              "edge " + std::to_string(e.idx()) + " (" + a + "–" + b + ")");
    EXPECT_EQ(describe(cube, ElementRef::halfedge(h)),
              "halfedge " + std::to_string(h.idx()) + " (" + a + "→" + b + ")");
    EXPECT_EQ(describe(cube, ElementRef::vertex(Vertex(3))), "vertex 3");
    EXPECT_EQ(describe(cube, ElementRef::face(Face(4))), "face 4");
    EXPECT_EQ(describe(cube, {}), "nothing selected");
    EXPECT_TRUE(is_live(cube, ElementRef::face(Face(11))));
    EXPECT_FALSE(is_live(cube, ElementRef::face(Face(12))));
    EXPECT_FALSE(is_live(cube, {}));

    const auto row = [](const std::vector<std::pair<std::string, std::string>>& rows,
                        const std::string& key) {
        for (const auto& [k, v] : rows) {
            if (k == key) {
                return v;
            }
        }
        return std::string("<missing " + key + ">");
    };
    const auto v0 = element_info(cube, ElementRef::vertex(Vertex(0)));
    EXPECT_EQ(row(v0, "type"), "vertex");
    EXPECT_EQ(row(v0, "index"), "0");
    EXPECT_EQ(row(v0, "position"), "(-1.0000, -1.0000, -1.0000)");
    EXPECT_EQ(row(v0, "degree"), "6");
    EXPECT_EQ(row(v0, "boundary"), "no");

    Mesh creased = cube;
    creased.property<Edge, std::uint8_t>(kCreaseProperty, 0)[e] = 1;
    const auto ei = element_info(creased, ElementRef::edge(e));
    EXPECT_EQ(row(ei, "vertices"), a + ", " + b);
    EXPECT_EQ(row(ei, "crease"), "yes");
    EXPECT_EQ(row(ei, "boundary"), "no");
    EXPECT_EQ(row(ei, "midpoint"), "(-1.0000, 0.0000, 0.0000)");
    EXPECT_EQ(row(ei, "length"), "2.8284");

    const auto hi = element_info(cube, ElementRef::halfedge(h));
    EXPECT_EQ(row(hi, "next"), std::to_string(cube.next(h).idx()));
    EXPECT_EQ(row(hi, "twin"), std::to_string(Mesh::twin(h).idx()));
    EXPECT_EQ(row(hi, "from (vertex())"), a);
    EXPECT_EQ(row(hi, "to"), b);
    // V goes where the panel's "from (vertex())" row points.
    Editor ed = editor_with(cube);
    ed.select(ElementRef::halfedge(h));
    ed.press(key_of('V'), 0);
    EXPECT_EQ(std::to_string(ed.selection().index), a);
    EXPECT_EQ(row(hi, "face"), std::to_string(cube.face(h).idx()));

    const Mesh grid = shapes::grid(1, 1);
    const auto bi = element_info(grid, ElementRef::halfedge(boundary_halfedge(grid)));
    EXPECT_EQ(row(bi, "face"), "none (boundary)");

    const auto fi = element_info(cube, ElementRef::face(Face(0)));
    EXPECT_EQ(row(fi, "degree"), "3");
    EXPECT_EQ(row(fi, "normal"), "(-1.0000, 0.0000, 0.0000)");
    EXPECT_EQ(row(fi, "area"), "2.0000");
    EXPECT_TRUE(element_info(cube, {}).empty());
    EXPECT_EQ(element_info(cube, ElementRef::vertex(Vertex(99)))[2].second, "not in the mesh");

    BezierCurve curve{{{0.25, 0.5, 0}, {1, 2, 0}}};
    const auto ci = control_point_info(curve, 1);
    EXPECT_EQ(row(ci, "position"), "(1.0000, 2.0000)");
    EXPECT_TRUE(control_point_info(curve, 2).empty());
}

// ----------------------------------------------------------------------------------- drag

TEST(Editor, DragIsOneUndoStep) {
    const Mesh cube = shapes::cube();
    Editor ed = editor_with(cube);
    EXPECT_FALSE(ed.begin_drag()) << "nothing selected";
    ed.select(ElementRef::edge(Edge(0)));
    EXPECT_FALSE(ed.begin_drag()) << "an edge is not dragged";

    ed.select(ElementRef::vertex(Vertex(7)));
    ASSERT_TRUE(ed.begin_drag());
    EXPECT_TRUE(ed.dragging());
    EXPECT_EQ(ed.drag_to({1.5, 1, 1}).changes, unsigned{kGeometry});
    const Outcome moving = ed.drag_to({2, 2, 2});
    EXPECT_EQ(moving.changes, unsigned{kGeometry});
    EXPECT_EQ(moving.message, "moving vertex 7 by (1.0000, 1.0000, 1.0000), 1.7321");
    // The cube's vertex 7 is (1, 1, 1): the status says what the drag did.
    EXPECT_EQ(ed.end_drag().message,
              "moved vertex 7 by (1.0000, 1.0000, 1.0000), 1.7321 (Ctrl+Z undoes it)");
    EXPECT_FALSE(ed.dragging());
    EXPECT_EQ(ed.history().undo_steps(), 1u);
    EXPECT_TRUE(ed.history().last_is_change()) << "recorded: the vertex, not the mesh";
    EXPECT_LT(ed.history().bytes(), 1024u);
    EXPECT_TRUE(ed.dirty());
    EXPECT_EQ(ed.mesh().position(Vertex(7)), (Vec3{2, 2, 2}));
    const Mesh dragged = ed.mesh();
    ed.press(key_of('Z'), kCtrl);
    EXPECT_TRUE(test::identical(ed.mesh(), cube));
    EXPECT_FALSE(ed.dirty());
    ed.press(key_of('Z'), kCtrl | kShift);  // redo: where the drag ended, not its first move
    EXPECT_TRUE(test::identical(ed.mesh(), dragged));
    ed.press(key_of('Z'), kCtrl);

    // A click without a move (or a "move" to the same place) leaves no step.
    ed.select(ElementRef::vertex(Vertex(7)));
    ASSERT_TRUE(ed.begin_drag());
    EXPECT_EQ(ed.drag_to(cube.position(Vertex(7))).changes, unsigned{kNothing});
    EXPECT_TRUE(ed.end_drag().message.empty()) << "nothing moved, nothing to say";
    EXPECT_EQ(ed.history().undo_steps(), 0u);
    EXPECT_EQ(ed.history().redo_steps(), 1u);
    EXPECT_FALSE(ed.dirty());
    // Non-finite positions are refused (validate() requires finite coordinates).
    ASSERT_TRUE(ed.begin_drag());
    EXPECT_TRUE(ed.drag_to({NAN, 0, 0}).refused);
    ed.end_drag();
    EXPECT_VALID(ed.mesh());
    EXPECT_EQ(ed.drag_to({0, 0, 0}).changes, unsigned{kNothing}) << "not dragging";
}

}  // namespace
}  // namespace meshedit::viewer

namespace meshedit::viewer {
namespace {

// Shift+V: a valid mesh says so with its counts; a corrupted one (a vertex anchored at a
// halfedge that does not leave it, as a script might leave it) gets the culprit selected and
// framed and the broken invariant named, refused so the status line shows it as a warning.
TEST(EditorValidate, ValidSaysSoAndACorruptedMeshShowsItsCulprit) {
    Editor ed = editor_with(shapes::cube());
    const Outcome ok = ed.run({Command::Validate});
    EXPECT_FALSE(ok.refused);
    EXPECT_EQ(ok.message,
              "valid: every invariant of docs/halfedge.md holds (8 vertices, 18 edges, 12 faces)");

    Mesh broken = shapes::cube();
    broken.set_halfedge(Vertex(0), broken.halfedge(Vertex(1)));
    const std::optional<ValidationError> expected = validate(broken);
    ASSERT_TRUE(expected);
    ed.set_document(mesh_document(std::move(broken)));
    const Outcome bad = ed.run({Command::Validate});
    EXPECT_TRUE(bad.refused);
    EXPECT_EQ(bad.message, "invalid (" + expected->invariant + "): " + expected->message);
    EXPECT_NE(bad.changes & kFrameSelection, 0u);
    ASSERT_EQ(expected->kind, ElementKind::Vertex);
    EXPECT_EQ(ed.selection().kind, Kind::Vertex);
    EXPECT_EQ(ed.selection().index, expected->index);
}

}  // namespace
}  // namespace meshedit::viewer

namespace meshedit::viewer {
namespace {

// The inspector's links: every row that names elements names the live ones the mesh says,
// in the row's order; a boundary gap is left out; selecting a link is an ordinary select.
TEST(EditorInspector, LinksAreTheElementsTheRowsName) {
    const Mesh cube = shapes::cube();
    const auto find = [](const auto& links, const std::string& name) {
        for (const auto& [row, refs] : links) {
            if (row == name) {
                return refs;
            }
        }
        ADD_FAILURE() << "no row " << name;
        return std::vector<ElementRef>{};
    };
    const Halfedge h = cube.halfedge(Face(2));
    const auto hl = element_links(cube, ElementRef::halfedge(h));
    EXPECT_EQ(find(hl, "next"), std::vector<ElementRef>{ElementRef::halfedge(cube.next(h))});
    EXPECT_EQ(find(hl, "prev"), std::vector<ElementRef>{ElementRef::halfedge(cube.prev(h))});
    EXPECT_EQ(find(hl, "twin"), std::vector<ElementRef>{ElementRef::halfedge(Mesh::twin(h))});
    EXPECT_EQ(find(hl, "from (vertex())"),
              std::vector<ElementRef>{ElementRef::vertex(cube.from_vertex(h))});
    EXPECT_EQ(find(hl, "edge"), std::vector<ElementRef>{ElementRef::edge(Mesh::edge(h))});
    EXPECT_EQ(find(hl, "face"), std::vector<ElementRef>{ElementRef::face(Face(2))});

    // A vertex's orbit: its outgoing halfedges, one per neighbour, in the rows' order.
    const auto vl = element_links(cube, ElementRef::vertex(Vertex(0)));
    const std::vector<ElementRef> outgoing = find(vl, "outgoing");
    ASSERT_EQ(outgoing.size(), cube.valence(Vertex(0)));
    const std::vector<ElementRef> neighbours = find(vl, "neighbours");
    for (std::size_t i = 0; i < outgoing.size(); ++i) {
        EXPECT_EQ(cube.from_vertex(Halfedge(outgoing[i].index)), Vertex(0));
        EXPECT_EQ(ElementRef::vertex(cube.to_vertex(Halfedge(outgoing[i].index))), neighbours[i]);
    }
    const auto info = element_info(cube, ElementRef::vertex(Vertex(0)));
    EXPECT_TRUE(std::any_of(info.begin(), info.end(), [](const auto& r) {
        return r.first == "outgoing";
    })) << "the orbit is a row of the panel too";

    // A boundary halfedge has no face to link to; a boundary edge links its one face.
    const Mesh grid = shapes::grid(1, 1);
    const Halfedge b = boundary_halfedge(grid);
    EXPECT_TRUE(find(element_links(grid, ElementRef::halfedge(b)), "face").empty());
    EXPECT_EQ(find(element_links(grid, ElementRef::edge(Mesh::edge(b))), "faces").size(), 1u);
    EXPECT_TRUE(element_links(cube, ElementRef::vertex(Vertex(99))).empty());

    Editor ed = editor_with(cube);
    ASSERT_FALSE(ed.select(find(hl, "twin").front()).refused);
    EXPECT_EQ(ed.selection(), ElementRef::halfedge(Mesh::twin(h)));
}

}  // namespace
}  // namespace meshedit::viewer
