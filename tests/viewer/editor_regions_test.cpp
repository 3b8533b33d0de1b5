// The editor's region selection keys (editor_regions.cpp): Alt+E loop, Alt+Shift+E ring,
// Ctrl+Shift+L linked, Ctrl+= / Ctrl+- more and less, Ctrl+I invert, on a quad grid whose
// answers are known.

#include <gtest/gtest.h>

#include <algorithm>

#include "meshedit/core/shapes.h"
#include "meshedit/ops/ops.h"
#include "meshedit/viewer/editor.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"
#include "viewer/editor_test_util.h"

namespace meshedit::viewer {
namespace {

// nx × ny unit quads (shapes.h): vertex (i, j) = j·(nx+1) + i, face (i, j) = j·nx + i; with
// `two`, a copy beside it, numbered after.
Mesh quad_grid(int nx, int ny, bool two = false) {
    const Mesh one = shapes::quad_grid(nx, ny);
    return two ? test::two_copies(one, {double(nx + 2), 0, 0}) : one;
}

std::size_t count(const Editor& ed) {
    return ed.selected().size();
}

TEST(EditorRegions, AltESelectsTheLoopAndAltShiftEtheRing) {
    Editor ed = editor_with(quad_grid(5, 4));
    const Edge e = edge_of(ed.mesh(), 2 * 6 + 2, 2 * 6 + 3);  // on the line y = 2
    ed.select(ElementRef::edge(e));
    const Outcome loop = ed.press(key_of('E'), kAlt);
    ASSERT_FALSE(loop.refused) << loop.message;
    EXPECT_EQ(count(ed), 5u);
    EXPECT_EQ(ed.selection().index, e.idx());  // the active edge stays active
    EXPECT_EQ(loop.message, "selected the edge loop: 5 edges");
    ed.select(ElementRef::edge(edge_of(ed.mesh(), 1 * 6 + 2, 2 * 6 + 2)));  // vertical
    ASSERT_FALSE(ed.press(key_of('E'), kAlt | kShift).refused);
    EXPECT_EQ(count(ed), 6u);
    ed.select(ElementRef::face(Face(0)));
    const Outcome refused = ed.press(key_of('E'), kAlt);
    EXPECT_TRUE(refused.refused);
    EXPECT_EQ(refused.message, "select an edge first, then press Alt+E for its loop");
}

TEST(EditorRegions, MoreLessInvertAndLinked) {
    Editor ed = editor_with(quad_grid(5, 5, true));  // faces 0-24 and 25-49
    ed.select(ElementRef::face(Face(12)));           // the centre of the first piece
    ASSERT_FALSE(ed.press(Key::Equal, kCtrl).refused);
    EXPECT_EQ(count(ed), 9u);
    ASSERT_FALSE(ed.press(Key::KeypadAdd, kCtrl).refused);
    EXPECT_EQ(count(ed), 25u);
    ASSERT_FALSE(ed.press(Key::Minus, kCtrl).refused);
    EXPECT_EQ(count(ed), 9u);
    ASSERT_FALSE(ed.press(key_of('I'), kCtrl).refused);
    EXPECT_EQ(count(ed), 41u);  // the other 16 of the first piece and all 25 of the second
    ed.select(ElementRef::face(Face(30)));
    ASSERT_FALSE(ed.press(key_of('L'), kCtrl | kShift).refused);
    EXPECT_EQ(count(ed), 25u);
    for (const ElementRef& e : ed.selected()) {
        EXPECT_GE(e.index, 25u);
    }
    ed.select(ElementRef::vertex(Vertex(0)));
    ASSERT_FALSE(ed.press(Key::Equal, kCtrl).refused);
    EXPECT_EQ(count(ed), 3u);  // the corner and its two neighbours
    ed.select(ElementRef::edge(Edge(0)));
    EXPECT_TRUE(ed.press(Key::Equal, kCtrl).refused);
    // Each region selection that ran is an undo step (not the clicks, not the refusal), and
    // none of them is an unsaved change.
    EXPECT_EQ(ed.history().undo_steps(), 6u);
    EXPECT_EQ(ed.document().session.size(), 6u);
    EXPECT_FALSE(ed.dirty());
}

// A region selection is an undo step with its `select` step in the session: Ctrl+Z takes the
// selection back (to the one a click made before it), Ctrl+Shift+Z forward again; the
// session's steps replayed through the language give the same selection; a brush drag is
// one step however many times it paints.
TEST(EditorRegions, RegionSelectionsUndoAndAreRecorded) {
    const Mesh grid = quad_grid(5, 5);
    Editor ed = editor_with(grid);
    ed.select(ElementRef::face(Face(12)));
    EXPECT_EQ(ed.history().undo_steps(), 0u);  // a click is how one looks, not a step
    ASSERT_FALSE(ed.press(Key::Equal, kCtrl).refused);
    const std::vector<std::string>& session = ed.document().session;
    ASSERT_EQ(session.size(), 1u);
    EXPECT_EQ(session.back(), "select:f6..8+f11..13+f16..18");
    ASSERT_FALSE(ed.press(key_of('I'), kCtrl).refused);
    EXPECT_EQ(session.back(), "select:f0..5+f9..10+f14..15+f19..24");
    EXPECT_EQ(ed.history().undo_steps(), 2u);

    ASSERT_FALSE(ed.press(key_of('Z'), kCtrl).refused);
    EXPECT_EQ(count(ed), 9u);
    EXPECT_EQ(session.size(), 1u);
    ASSERT_FALSE(ed.press(key_of('Z'), kCtrl).refused);
    EXPECT_EQ(ed.selected(), std::vector<ElementRef>{ElementRef::face(Face(12))});
    EXPECT_TRUE(session.empty());
    ASSERT_FALSE(ed.press(key_of('Z'), kCtrl | kShift).refused);
    EXPECT_EQ(count(ed), 9u);
    EXPECT_EQ(session.back(), "select:f6..8+f11..13+f16..18");
    EXPECT_TRUE(test::identical(ed.mesh(), grid));
    EXPECT_FALSE(ed.dirty());

    // Vertices, edges (an Alt+E loop) and Alt+A, each replayed through the language.
    const auto replays = [&](const char* what) {
        Mesh copy = grid;
        const ops::StepsRun run = ops::run_steps(
            copy, ops::parse_session(ops::session_text({}, session)), ops::OnRefusal::Stop);
        std::vector<std::uint32_t> want;
        for (const ElementRef& e : ed.selected()) {
            want.push_back(e.index);
        }
        std::sort(want.begin(), want.end());
        std::vector<std::uint32_t> got = run.selection.indices;
        std::sort(got.begin(), got.end());
        EXPECT_EQ(got, want) << what << ": " << session.back();
    };
    replays("grown faces");
    ed.select(ElementRef::vertex(Vertex(0)));
    ASSERT_FALSE(ed.press(Key::Equal, kCtrl).refused);
    EXPECT_EQ(session.back(), "select:v0..1+v6");
    replays("grown vertices");
    ed.select(ElementRef::edge(edge_of(ed.mesh(), 2 * 6 + 2, 2 * 6 + 3)));
    ASSERT_FALSE(ed.press(key_of('E'), kAlt).refused);
    replays("edge loop");
    ASSERT_FALSE(ed.press(key_of('A'), kAlt).refused);
    EXPECT_EQ(session.back(), "select_none");
    replays("nothing");
    const std::size_t steps = ed.history().undo_steps();

    // A brush stroke: three paints, one step; the next stroke is another.
    ed.begin_selection_stroke();
    for (const std::uint32_t f : {0u, 1u, 2u}) {
        ed.select_elements({ElementRef::face(Face(f))}, true, "brush");
    }
    ed.end_selection_stroke();
    EXPECT_EQ(ed.history().undo_steps(), steps + 1);
    EXPECT_EQ(session.back(), "select:f0..2");
    ed.begin_selection_stroke();
    ed.deselect_elements({ElementRef::face(Face(1))}, "brush");
    ed.end_selection_stroke();
    EXPECT_EQ(ed.history().undo_steps(), steps + 2);
    EXPECT_EQ(session.back(), "select:f0+f2");
    ASSERT_FALSE(ed.press(key_of('Z'), kCtrl).refused);
    ASSERT_FALSE(ed.press(key_of('Z'), kCtrl).refused);
    EXPECT_EQ(count(ed), 0u);
    EXPECT_EQ(session.back(), "select_none");
}

// B hands the drag to the window (kBoxSelect); what the box holds comes back through
// select_elements(), replacing the selection or, with Shift, adding to it.
TEST(EditorRegions, BoxSelectsWhatTheWindowFound) {
    Editor ed = editor_with(quad_grid(3, 3));
    const Outcome armed = ed.press(key_of('B'), 0);
    EXPECT_NE(armed.changes & kBoxSelect, 0u);
    EXPECT_EQ(ed.region_kind(), ElementRef::Kind::Face);
    ed.select_elements({ElementRef::face(Face(0)), ElementRef::face(Face(1))}, false, "box");
    EXPECT_EQ(count(ed), 2u);
    const Outcome added =
        ed.select_elements({ElementRef::face(Face(1)), ElementRef::face(Face(4))}, true, "box");
    EXPECT_EQ(count(ed), 3u);  // face 1 once
    EXPECT_EQ(added.message, "box: 3 faces selected in all");
    ed.select(ElementRef::vertex(Vertex(5)));
    EXPECT_EQ(ed.region_kind(), ElementRef::Kind::Vertex);
    EXPECT_EQ(ed.select_elements({}, false, "box").message,
              "box: nothing inside (the selection is empty)");
    EXPECT_EQ(count(ed), 0u);
}

// Alt+P: the shortest path between two selected vertices (corner to corner of a 3 × 2 grid:
// 5 edges, 6 vertices) or faces; refused with one selected or across two pieces.
TEST(EditorRegions, AltPSelectsTheShortestPath) {
    Editor ed = editor_with(quad_grid(3, 2, true));  // 12 vertices and 6 faces a piece
    ed.select(ElementRef::vertex(Vertex(0)));
    EXPECT_TRUE(ed.press(key_of('P'), kAlt).refused);
    ed.toggle_select(ElementRef::vertex(Vertex(11)));
    const Outcome path = ed.press(key_of('P'), kAlt);
    ASSERT_FALSE(path.refused) << path.message;
    EXPECT_EQ(path.message, "selected the shortest path: 6 vertices");
    ed.select(ElementRef::face(Face(0)));
    ed.toggle_select(ElementRef::face(Face(5)));
    ASSERT_FALSE(ed.press(key_of('P'), kAlt).refused);
    EXPECT_EQ(count(ed), 4u);  // (0,0) to (2,1): 3 steps
    ed.select(ElementRef::face(Face(0)));
    ed.toggle_select(ElementRef::face(Face(6)));  // the other piece
    const Outcome apart = ed.press(key_of('P'), kAlt);
    EXPECT_TRUE(apart.refused);
    EXPECT_EQ(apart.message, "no path joins the two faces: they are on separate pieces");
}

// Shift+X on the middle 3 x 3 of a 5 x 5 grid: the drag builds the walls once and then only
// moves the top; Enter gives, bit for bit, the session's extrude_region step replayed through
// the language, and the top stays selected. Shift+W then subdivides it with its transition
// ring, again as its recorded step replays.
TEST(EditorRegions, ShiftXExtrudesTheRegionAsOneAndShiftWSubdividesIt) {
    Mesh grid = quad_grid(5, 5);
    auto corner = grid.add_property<Halfedge, double>("h:corner");
    for (const Halfedge h : grid.halfedges()) {
        corner[h] = 0.5 * h.idx();
    }
    Editor ed = editor_with(grid);
    std::vector<ElementRef> nine;
    for (const std::uint32_t f : {6u, 7u, 8u, 11u, 12u, 13u, 16u, 17u, 18u}) {
        nine.push_back(ElementRef::face(Face(f)));
    }
    ed.select_elements(nine, false, "box");
    ASSERT_FALSE(ed.press(key_of('X'), kShift).refused);
    ModalInput in;
    in.pixel = 0.01;
    for (int k = 1; k <= 50; ++k) {
        in.dy = k;
        ed.modal_input(in);
    }
    EXPECT_EQ(ed.modal_counts().topology_changes, 1u);
    EXPECT_EQ(ed.modal_counts().position_amendments, 50u);  // the key's preview built it
    EXPECT_EQ(ed.modal_status().rfind("extrude region height 0.5 ", 0), 0u) << ed.modal_status();
    ASSERT_FALSE(ed.press(Key::Enter, 0).refused);
    EXPECT_EQ(ed.history().undo_steps(), 2u);  // the box's selection, then the extrusion
    const std::vector<std::string>& session = ed.document().session;
    ASSERT_FALSE(session.empty());
    EXPECT_EQ(session.back(), "extrude_region:f6..8+f11..13+f16..18:0.5");
    EXPECT_EQ(count(ed), 9u);
    Mesh expected = grid;
    ops::apply_steps(expected, ops::parse(session.back()));
    expect_as_replayed(ed, grid, expected);

    const Mesh extruded = ed.mesh();
    const Outcome sub = ed.press(key_of('W'), kShift);
    ASSERT_FALSE(sub.refused) << sub.message;
    EXPECT_EQ(session.back(), "subdivide_region:f6..8+f11..13+f16..18");
    EXPECT_EQ(count(ed), 36u);
    Mesh subdivided = extruded;
    ops::apply_steps(subdivided, ops::parse(session.back()));
    expect_as_replayed(ed, extruded, subdivided);

    ed.select(ElementRef::vertex(Vertex(0)));
    const Outcome refused = ed.press(key_of('W'), kShift);
    EXPECT_TRUE(refused.refused);
    EXPECT_EQ(refused.message, "select faces (click, Shift+click, B or Ctrl+right-drag) first");
}

// Alt+I insets the selected faces as one region: a drag builds the ring once and then only
// moves its inner border; the session's step replays to the same mesh; Ctrl+Shift+M then
// smooths the inner region only (its border, the ring's inner side, stays).
TEST(EditorRegions, AltIInsetsTheRegionAsOne) {
    const Mesh grid = quad_grid(5, 5);
    Editor ed = editor_with(grid);
    std::vector<ElementRef> nine;
    for (const std::uint32_t f : {6u, 7u, 8u, 11u, 12u, 13u, 16u, 17u, 18u}) {
        nine.push_back(ElementRef::face(Face(f)));
    }
    ed.select_elements(nine, false, "box");
    ASSERT_FALSE(ed.press(key_of('I'), kAlt).refused);
    ModalInput in;
    in.pixel = 0.01;
    for (int k = 1; k <= 25; ++k) {
        in.dx = k;
        ed.modal_input(in);
    }
    EXPECT_EQ(ed.modal_counts().topology_changes, 1u);
    EXPECT_EQ(ed.modal_counts().position_amendments, 25u);
    EXPECT_EQ(ed.modal_status().rfind("inset region thickness 0.25", 0), 0u) << ed.modal_status();
    ASSERT_FALSE(ed.press(Key::Enter, 0).refused);
    EXPECT_EQ(ed.history().undo_steps(), 2u);  // the box's selection, then the inset
    const std::vector<std::string>& session = ed.document().session;
    ASSERT_FALSE(session.empty());
    EXPECT_EQ(session.back(), "inset_region:f6..8+f11..13+f16..18:0.25");
    EXPECT_EQ(ed.mesh().n_faces(), 37u);
    EXPECT_EQ(count(ed), 9u);
    Mesh expected = grid;
    ops::apply_steps(expected, ops::parse(session.back()));
    expect_as_replayed(ed, grid, expected);

    const Mesh inset = ed.mesh();
    const Outcome smoothed = ed.press(key_of('M'), kCtrl | kShift);
    ASSERT_FALSE(smoothed.refused) << smoothed.message;
    EXPECT_EQ(session.back(), "smooth_region:f6..8+f11..13+f16..18:10,0.5");
    EXPECT_EQ(smoothed.message.rfind("smoothed 10 iterations of 4 inner vertices of 9 faces", 0),
              0u)
        << smoothed.message;
    Mesh replayed = inset;
    ops::apply_steps(replayed, ops::parse(session.back()));
    expect_as_replayed(ed, inset, replayed);
}

// Ctrl+Shift+R remeshes the selected faces only (a verb that rebuilds the mesh: undone from a
// copy, not recorded): the session's step replays to the same mesh, and undo gives back the
// sphere bit for bit.
TEST(EditorRegions, CtrlShiftRRemeshesTheSelectionAndUndoes) {
    const Mesh sphere = shapes::icosphere(2);
    Editor ed = editor_with(sphere);
    std::vector<ElementRef> cap;
    for (const Face f : sphere.faces()) {
        bool near = true;
        for (const Vertex v : sphere.vertices(f)) {
            near = near && distance(sphere.position(v), Vec3{0, 0, 1}) < 0.7;
        }
        if (near) {
            cap.push_back(ElementRef::face(f));
        }
    }
    ASSERT_GT(cap.size(), 10u);
    ed.select_elements(cap, false, "box");
    const Outcome out = ed.press(key_of('R'), kCtrl | kShift);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(
        out.message.rfind("remeshed the region of " + std::to_string(cap.size()) + " faces", 0), 0u)
        << out.message;
    EXPECT_VALID(ed.mesh());
    const std::vector<std::string>& session = ed.document().session;
    ASSERT_FALSE(session.empty());
    EXPECT_EQ(session.back().rfind("remesh_region:", 0), 0u) << session.back();
    Mesh replayed = sphere;
    ops::apply_steps(replayed, ops::parse(session.back()));
    EXPECT_TRUE(test::identical(replayed, ed.mesh()));
    ed.press(key_of('Z'), kCtrl);
    EXPECT_TRUE(test::identical(ed.mesh(), sphere));
}

// Shift+G selects by the trait the info panel sets: on a 5 x 5 grid the border faces (16),
// the border's vertices of valence 3 (16), the quads (25), a crease; turned away from the
// eye, nothing until the eye goes behind the grid.
TEST(EditorRegions, ShiftGSelectsByTrait) {
    Editor ed = editor_with(quad_grid(5, 5));
    const auto trait = [&](Trait t, std::size_t k = 4) {
        ed.tools().trait.trait = t;
        ed.tools().trait.k = k;
        const Outcome out = ed.press(key_of('G'), kShift);
        EXPECT_FALSE(out.refused) << out.message;
        return out.message;
    };
    EXPECT_EQ(trait(Trait::Boundary), "selected the border: 16 faces");
    EXPECT_EQ(trait(Trait::Valence, 3), "selected the vertices of valence 3: 16 vertices");
    EXPECT_EQ(ed.selected()[0].kind, ElementRef::Kind::Vertex);
    EXPECT_EQ(trait(Trait::Boundary), "selected the border: 20 vertices");  // in vertex mode
    EXPECT_EQ(trait(Trait::Degree, 4), "selected the faces of 4 corners: 25 faces");
    EXPECT_EQ(trait(Trait::Crease), "selected the crease edges: nothing (the selection is empty)");
    ed.tools().trait.angle_deg = 90;
    ed.set_view_direction({0, 0, 1});
    EXPECT_EQ(trait(Trait::FacingAway),
              "selected the faces turned away from you by more than "
              "90°: nothing (the selection is empty)");
    ed.set_view_direction({0, 0, -1});
    EXPECT_EQ(trait(Trait::FacingAway),
              "selected the faces turned away from you by more than 90°: 25 faces");
}

// The brush's Shift+drag takes elements out of the selection; the last one left is active.
TEST(EditorRegions, DeselectTakesElementsOut) {
    Editor ed = editor_with(quad_grid(3, 3));
    std::vector<ElementRef> all;
    for (std::uint32_t f = 0; f < 9; ++f) {
        all.push_back(ElementRef::face(Face(f)));
    }
    ed.select_elements(all, false, "box");
    const Outcome out =
        ed.deselect_elements({ElementRef::face(Face(8)), ElementRef::face(Face(4))}, "brush");
    EXPECT_EQ(out.message, "brush: 7 faces selected");
    EXPECT_EQ(count(ed), 7u);
    EXPECT_EQ(ed.selection().index, 7u);
    EXPECT_EQ(ed.deselect_elements(all, "brush").message, "brush: the selection is empty");
    EXPECT_TRUE(ed.selection().is_none());
}

}  // namespace
}  // namespace meshedit::viewer
