// The viewer's command layer without a window: mesh operations on the selection, refusals
// that leave the document untouched, navigation, selection remapping, undo/redo and the
// dirty flag, quit protection, drags, curve and surface commands, and files.

#include "meshedit/viewer/editor.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/io/io.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit::viewer {
namespace {

namespace fs = std::filesystem;
using Kind = ElementRef::Kind;

/// A fresh folder under the system temp folder, removed at the end of the test.
class TempDir {
public:
    TempDir() {
        static std::atomic<int> counter{0};
        path_ = fs::temp_directory_path() / ("meshedit_viewer_test_" + std::to_string(::getpid()) +
                                             "_" + std::to_string(counter.fetch_add(1)));
        fs::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    fs::path operator/(const std::string& name) const { return path_ / name; }

private:
    fs::path path_;
};

Document mesh_document(Mesh mesh, Mode mode = Mode::Mesh) {
    Document d;
    d.mode = mode;
    d.mesh = std::move(mesh);
    return d;
}

Editor editor_with(Mesh mesh) {
    Editor ed;
    ed.set_document(mesh_document(std::move(mesh)));
    return ed;
}

Edge edge_of(const Mesh& mesh, std::uint32_t a, std::uint32_t b) {
    const Edge e = mesh.find_edge(Vertex(a), Vertex(b));
    EXPECT_TRUE(e.is_valid()) << a << "-" << b;
    return e;
}

int crease_of(const Mesh& mesh, Edge e) {
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    return crease ? crease[e] : -1;
}

Halfedge boundary_halfedge(const Mesh& mesh) {
    for (Halfedge h : mesh.halfedges()) {
        if (mesh.is_boundary(h)) {
            return h;
        }
    }
    ADD_FAILURE() << "no boundary";
    return {};
}

// ------------------------------------------------------------------------ mesh operations

TEST(Editor, FlipEqualsDirectFlip) {
    const Mesh cube = shapes::cube();
    const Edge e = edge_of(cube, 0, 6);
    Mesh expected = cube;
    ASSERT_TRUE(flip(expected, e));

    Editor ed = editor_with(cube);
    EXPECT_FALSE(ed.dirty());
    ed.select(ElementRef::edge(e));
    const Outcome out = ed.press(key_of('F'), 0);
    EXPECT_FALSE(out.refused) << out.message;
    EXPECT_EQ(out.changes, unsigned{kTopology | kSelection});
    EXPECT_EQ(out.message.rfind("flipped edge " + std::to_string(e.idx()), 0), 0u) << out.message;
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    EXPECT_EQ(ed.selection().kind, Kind::Edge);
    EXPECT_EQ(ed.selection().index, e.idx());
    EXPECT_TRUE(ed.dirty());
    EXPECT_EQ(ed.history().undo_steps(), 1u);

    // A selected halfedge stands for its edge: flipping twice through it restores the cube's
    // faces (not its halfedge layout, which flip does not promise).
    Editor ed2 = editor_with(cube);
    ed2.select(ElementRef::halfedge(Mesh::halfedge(e, 1)));
    EXPECT_FALSE(ed2.run(edit("flip")).refused);
    EXPECT_TRUE(test::identical(ed2.mesh(), expected));
}

TEST(Editor, RefusedFlipLeavesEverythingUntouched) {
    const Mesh grid = shapes::grid(2, 2);
    Editor ed = editor_with(grid);
    const std::uint64_t revision = ed.document().revision;
    const Edge boundary = edge_of(grid, 0, 1);
    ed.select(ElementRef::edge(boundary));
    const Outcome out = ed.press(key_of('F'), 0);
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, "cannot flip: boundary edge");
    EXPECT_EQ(out.changes, unsigned{kNothing});
    EXPECT_TRUE(test::identical(ed.mesh(), grid));
    EXPECT_EQ(ed.history().undo_steps(), 0u);
    EXPECT_EQ(ed.document().revision, revision);
    EXPECT_FALSE(ed.dirty());
    EXPECT_EQ(ed.selection().index, boundary.idx()) << "the selection stays";
}

TEST(Editor, MeshOpsNeedAnEdge) {
    Editor ed = editor_with(shapes::cube());
    for (Key k : {key_of('F'), key_of('S'), key_of('C'), key_of('K')}) {
        Outcome out = ed.press(k, 0);
        EXPECT_TRUE(out.refused);
        EXPECT_EQ(out.message, "select an edge first (click near an edge)");
        ed.select(ElementRef::vertex(Vertex(2)));
        out = ed.press(k, 0);
        EXPECT_TRUE(out.refused);
        EXPECT_EQ(out.message, "select an edge first (click near an edge)");
        ed.select(ElementRef::face(Face(2)));
        EXPECT_TRUE(ed.press(k, 0).refused);
        ed.select({});
    }
    EXPECT_TRUE(test::identical(ed.mesh(), shapes::cube()));
    EXPECT_FALSE(ed.dirty());
}

TEST(Editor, CollapseRefusalKeepsMeshAndReason) {
    // Every edge of a tetrahedron is refused ("the mesh would degenerate").
    const Mesh tet = shapes::tetrahedron();
    Editor ed = editor_with(tet);
    ed.select(ElementRef::edge(Edge(0)));
    const Outcome out = ed.press(key_of('C'), 0);
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, std::string(is_collapse_ok(tet, Edge(0)).reason()));
    EXPECT_TRUE(test::identical(ed.mesh(), tet));
    EXPECT_EQ(ed.history().undo_steps(), 0u);
}

TEST(Editor, SplitSelectsTheNewVertex) {
    const Mesh cube = shapes::cube();
    const Edge e = edge_of(cube, 0, 6);
    Mesh expected = cube;
    const Vertex m = *split(expected, e);

    Editor ed = editor_with(cube);
    ed.select(ElementRef::edge(e));
    const Outcome out = ed.press(key_of('S'), 0);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    EXPECT_EQ(ed.selection().kind, Kind::Vertex);
    EXPECT_EQ(ed.selection().index, m.idx());
    EXPECT_EQ(m.idx(), 8u);
    EXPECT_EQ(out.message, "split edge " + std::to_string(e.idx()) + ": new vertex 8");
    EXPECT_EQ(ed.mesh().position(m), (Vec3{-1, 0, 0}));
    EXPECT_VALID(ed.mesh());
}

TEST(Editor, CollapseSelectsSurvivorAndCollectsGarbage) {
    const Mesh ico = shapes::icosphere(1);
    const Edge e = Edge(17);
    const Vertex a = ico.from_vertex(Mesh::halfedge(e, 0));
    const Vertex b = ico.to_vertex(Mesh::halfedge(e, 0));
    const Vertex survivor(std::min(a.idx(), b.idx()));
    const Vec3 mid = 0.5 * (ico.position(a) + ico.position(b));
    Mesh expected = ico;
    ASSERT_TRUE(collapse(expected, e));
    expected.garbage_collection();

    Editor ed = editor_with(ico);
    ed.select(ElementRef::edge(e));
    const Outcome out = ed.press(key_of('C'), 0);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_FALSE(ed.mesh().has_garbage());
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    EXPECT_VALID(ed.mesh());
    ASSERT_EQ(ed.selection().kind, Kind::Vertex);
    EXPECT_EQ(ed.selection().index, survivor.idx());
    EXPECT_EQ(ed.mesh().position(Vertex(ed.selection().index)), mid);
    EXPECT_EQ(out.message, "collapsed edge 17 into vertex " + std::to_string(survivor.idx()));
    EXPECT_EQ(ed.mesh().n_vertices(), ico.n_vertices() - 1);
}

TEST(Editor, SelectionIsRemappedWhenGarbageIsCollected) {
    // A document that still holds tombstones (collapsed directly, not collected): selecting a
    // high-index vertex and saving collects the garbage; the selection must follow the
    // vertex to its new, lower index.
    Mesh mesh = shapes::icosphere(1);
    const Edge e = Edge(3);
    const std::uint32_t deleted = std::max(mesh.from_vertex(Mesh::halfedge(e, 0)).idx(),
                                           mesh.to_vertex(Mesh::halfedge(e, 0)).idx());
    ASSERT_TRUE(collapse(mesh, e));
    ASSERT_TRUE(mesh.has_garbage());
    const Vertex high(static_cast<std::uint32_t>(mesh.vertices_size() - 1));
    ASSERT_GT(high.idx(), deleted);
    const Vec3 p = mesh.position(high);

    Editor ed;
    ed.set_document(mesh_document(mesh));
    ed.select(ElementRef::vertex(high));
    ASSERT_EQ(ed.selection().index, high.idx());
    TempDir dir;
    const Outcome out = ed.save_as(dir / "remap.obj");
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_FALSE(ed.mesh().has_garbage());
    ASSERT_EQ(ed.selection().kind, Kind::Vertex);
    EXPECT_EQ(ed.selection().index, high.idx() - 1);
    EXPECT_EQ(ed.mesh().position(Vertex(ed.selection().index)), p);

    // A deleted element cannot be selected at all.
    Editor ed2;
    ed2.set_document(mesh_document(mesh));
    ed2.select(ElementRef::vertex(Vertex(deleted)));
    EXPECT_TRUE(ed2.selection().is_none());
    ed2.select(ElementRef::face(Face(9999)));
    EXPECT_TRUE(ed2.selection().is_none());
}

TEST(Editor, RemapThroughAHandMadeMap) {
    GarbageCollectionMap map;
    map.vertices = {Vertex(0), Vertex(), Vertex(1), Vertex(2)};
    map.edges = {Edge(), Edge(0), Edge(1)};
    map.halfedges = {Halfedge(), Halfedge(), Halfedge(0), Halfedge(1), Halfedge(2), Halfedge(3)};
    map.faces = {Face(), Face(0)};

    const auto check = [&](ElementRef in, Kind kind, std::uint32_t index) {
        const ElementRef out = remap(in, map);
        EXPECT_EQ(out.kind, kind);
        if (kind != Kind::None) {
            EXPECT_EQ(out.index, index);
        }
    };
    check(ElementRef::vertex(Vertex(0)), Kind::Vertex, 0);
    check(ElementRef::vertex(Vertex(1)), Kind::None, 0);
    check(ElementRef::vertex(Vertex(3)), Kind::Vertex, 2);
    check(ElementRef::vertex(Vertex(4)), Kind::None, 0);  // out of range
    check(ElementRef::edge(Edge(0)), Kind::None, 0);
    check(ElementRef::edge(Edge(2)), Kind::Edge, 1);
    check(ElementRef::halfedge(Halfedge(5)), Kind::Halfedge, 3);
    check(ElementRef::halfedge(Halfedge(1)), Kind::None, 0);
    check(ElementRef::face(Face(1)), Kind::Face, 0);
    check(ElementRef::face(Face(0)), Kind::None, 0);
    check(ElementRef{}, Kind::None, 0);
}

TEST(Editor, ToggleCreaseIsAnUndoableEdit) {
    const Mesh cube = shapes::cube();
    Editor ed = editor_with(cube);
    const Edge e = edge_of(cube, 0, 1);
    ed.select(ElementRef::edge(e));
    Outcome out = ed.press(key_of('K'), 0);
    ASSERT_FALSE(out.refused);
    EXPECT_EQ(out.message, "edge " + std::to_string(e.idx()) + " is now a crease");
    EXPECT_TRUE(out.changes & kDisplay);
    auto crease = ed.mesh().get_property<Edge, std::uint8_t>(kCreaseProperty);
    ASSERT_TRUE(crease);
    EXPECT_EQ(crease[e], 1);
    EXPECT_TRUE(ed.dirty());

    out = ed.press(key_of('K'), 0);
    EXPECT_EQ(out.message, "edge " + std::to_string(e.idx()) + " is no longer a crease");
    EXPECT_EQ(crease_of(ed.mesh(), e), 0);
    EXPECT_EQ(ed.history().undo_steps(), 2u);

    ASSERT_FALSE(ed.press(key_of('Z'), kCtrl).refused);
    EXPECT_EQ(crease_of(ed.mesh(), e), 1);
    ASSERT_FALSE(ed.press(key_of('Z'), kCtrl).refused);
    EXPECT_TRUE(test::identical(ed.mesh(), cube));
    EXPECT_FALSE(ed.mesh().has_property<Edge>(kCreaseProperty)) << "bit-exact undo";
    EXPECT_FALSE(ed.dirty());

    // Boundary edges may be creased (harmless: Loop treats them as sharp anyway).
    Editor open = editor_with(shapes::grid(2, 2));
    open.select(ElementRef::edge(edge_of(open.mesh(), 0, 1)));
    EXPECT_FALSE(open.press(key_of('K'), 0).refused);
}

TEST(Editor, LoopKeepsTheSelectedVertex) {
    const Mesh cube = shapes::cube();
    Mesh expected = cube;
    loop_subdivide(expected);

    Editor ed = editor_with(cube);
    ed.select(ElementRef::vertex(Vertex(5)));
    const Outcome out = ed.press(key_of('L'), 0);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(out.message, "Loop: 48 faces");
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    EXPECT_EQ(ed.selection().kind, Kind::Vertex);
    EXPECT_EQ(ed.selection().index, 5u);

    // U is Loop too; any other selection is cleared (indices change).
    ed.select(ElementRef::edge(Edge(3)));
    ASSERT_FALSE(ed.press(key_of('U'), 0).refused);
    EXPECT_TRUE(ed.selection().is_none());
    EXPECT_EQ(ed.mesh().n_faces(), 192u);
    EXPECT_EQ(ed.history().undo_steps(), 2u);

    Editor empty = editor_with(Mesh());
    EXPECT_TRUE(empty.press(key_of('L'), 0).refused);
}

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
    EXPECT_EQ(row(hi, "from"), a);
    EXPECT_EQ(row(hi, "vertex"), b);
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

// ------------------------------------------------------------------------ display, mode

TEST(Editor, DisplayTogglesAreNotEdits) {
    Editor ed = editor_with(shapes::cube());
    const bool smooth = ed.view().render.smooth;
    EXPECT_EQ(ed.press(key_of('Q'), 0).changes, unsigned{kDisplay});
    EXPECT_NE(ed.view().render.smooth, smooth);
    const bool wireframe = ed.view().render.wireframe;
    EXPECT_EQ(ed.press(key_of('W'), 0).message, wireframe ? "wireframe off" : "wireframe on");
    EXPECT_NE(ed.view().render.wireframe, wireframe);
    const Outcome out = ed.press(key_of('5'), 0);
    EXPECT_EQ(ed.view().render.shading, 5);
    EXPECT_EQ(out.message, "shading 5: depth");
    EXPECT_EQ(ed.press(key_of('1'), 0).message, "shading 1: phong");
    const bool info = ed.view().show_info;
    ed.press(key_of('I'), 0);
    EXPECT_NE(ed.view().show_info, info);
    ed.press(Key::F1, 0);
    EXPECT_TRUE(ed.view().show_help);
    ed.press(Key::Slash, kShift);
    EXPECT_FALSE(ed.view().show_help);
    EXPECT_EQ(ed.press(Key::Space, 0).changes, unsigned{kResetCamera});
    EXPECT_EQ(ed.press(key_of('P'), 0).changes, unsigned{kScreenshot});
    EXPECT_EQ(ed.press(key_of('S'), kCtrl | kShift).changes, unsigned{kAskSavePath});
    EXPECT_EQ(ed.press(key_of('O'), kCtrl).changes, unsigned{kAskOpenPath});
    EXPECT_FALSE(ed.dirty());
    EXPECT_EQ(ed.history().undo_steps(), 0u);
    // Unbound keys do nothing; commands of another mode are refused when run directly.
    const Outcome none = ed.press(key_of('B'), 0);
    EXPECT_EQ(none.changes, unsigned{kNothing});
    EXPECT_TRUE(none.message.empty());
    EXPECT_TRUE(ed.run({Command::AddPoint}).refused);
    EXPECT_TRUE(ed.run({Command::Shading, 12}).refused);
}

// ------------------------------------------------------------------- history, dirty, quit

TEST(Editor, DirtyFollowsUndoAcrossSave) {
    TempDir dir;
    const fs::path file = dir / "cube.obj";
    write_mesh(shapes::cube(), file);
    Editor ed;
    ed.open(file);
    EXPECT_FALSE(ed.dirty());
    EXPECT_EQ(ed.title(), "cube.obj — V 8 E 18 F 12");

    ed.select(ElementRef::edge(edge_of(ed.mesh(), 0, 6)));
    ASSERT_FALSE(ed.press(key_of('F'), 0).refused);
    EXPECT_TRUE(ed.dirty());
    EXPECT_EQ(ed.title(), "cube.obj — V 8 E 18 F 12 *");
    const Outcome saved = ed.press(key_of('S'), kCtrl);
    ASSERT_FALSE(saved.refused) << saved.message;
    EXPECT_EQ(saved.message, "saved cube.obj");
    EXPECT_FALSE(ed.dirty());
    EXPECT_TRUE(test::same_faces_by_position(read_mesh(file).mesh, ed.mesh()));

    Outcome out = ed.press(key_of('Z'), kCtrl);
    EXPECT_EQ(out.message, "undo (0 left)");
    EXPECT_TRUE(ed.dirty()) << "undo after save: differs from the file";
    out = ed.press(key_of('Z'), kCtrl);
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, "nothing to undo");
    out = ed.press(key_of('Z'), kCtrl | kShift);
    EXPECT_EQ(out.message, "redo (0 left)");
    EXPECT_FALSE(ed.dirty()) << "redo back to the saved state";
    EXPECT_TRUE(ed.press(key_of('Y'), kCtrl).refused);

    // Undo back to the saved state after another edit: clean again.
    ed.select(ElementRef::edge(Edge(0)));
    ASSERT_FALSE(ed.press(key_of('K'), 0).refused);
    EXPECT_TRUE(ed.dirty());
    ed.press(key_of('Z'), kCtrl);
    EXPECT_FALSE(ed.dirty());
}

TEST(Editor, UndoRestoresSelection) {
    Editor ed = editor_with(shapes::cube());
    const Edge e = edge_of(ed.mesh(), 0, 6);
    ed.select(ElementRef::edge(e));
    ed.press(key_of('S'), 0);
    EXPECT_EQ(ed.selection().kind, Kind::Vertex);
    const Outcome out = ed.press(key_of('Z'), kCtrl);
    EXPECT_TRUE(out.changes & kDocument);
    EXPECT_EQ(ed.selection().kind, Kind::Edge);
    EXPECT_EQ(ed.selection().index, e.idx());
    ed.set_hover(ElementRef::vertex(Vertex(8)));
    ed.press(key_of('Y'), kCtrl);
    EXPECT_EQ(ed.selection().kind, Kind::Vertex);
    EXPECT_EQ(ed.selection().index, 8u);
    EXPECT_TRUE(ed.hover().is_none());
}

TEST(Editor, QuitAsksOnceWhenDirty) {
    Editor clean = editor_with(shapes::cube());
    EXPECT_EQ(clean.press(key_of('Q'), kCtrl).changes, unsigned{kQuit});
    EXPECT_EQ(clean.press(Key::Escape, 0).changes, unsigned{kQuit});

    Editor ed = editor_with(shapes::cube());
    ed.select(ElementRef::edge(Edge(0)));
    ed.press(key_of('K'), 0);
    ASSERT_TRUE(ed.dirty());
    Outcome out = ed.press(key_of('Q'), kCtrl);
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message,
              "unsaved changes: press Esc or Ctrl+Q again to quit without saving, or Ctrl+S to "
              "save");
    EXPECT_TRUE(ed.quit_armed());
    EXPECT_EQ(ed.press(key_of('Q'), kCtrl).changes, unsigned{kQuit});

    // Any other command disarms; Escape first clears the selection, then quits the same way.
    Editor ed2 = editor_with(shapes::cube());
    ed2.select(ElementRef::edge(Edge(0)));
    ed2.press(key_of('K'), 0);
    EXPECT_TRUE(ed2.press(key_of('Q'), kCtrl).refused);
    ed2.press(key_of('W'), 0);
    EXPECT_FALSE(ed2.quit_armed());
    out = ed2.press(Key::Escape, 0);
    EXPECT_EQ(out.changes, unsigned{kSelection});
    EXPECT_EQ(out.message, "selection cleared");
    EXPECT_TRUE(ed2.selection().is_none());
    EXPECT_TRUE(ed2.press(Key::Escape, 0).refused);
    EXPECT_TRUE(ed2.quit_armed());
    EXPECT_EQ(ed2.press(Key::Escape, 0).changes, unsigned{kQuit});
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
    EXPECT_EQ(ed.drag_to({2, 2, 2}).changes, unsigned{kGeometry});
    ed.end_drag();
    EXPECT_FALSE(ed.dragging());
    EXPECT_EQ(ed.history().undo_steps(), 1u);
    EXPECT_TRUE(ed.dirty());
    EXPECT_EQ(ed.mesh().position(Vertex(7)), (Vec3{2, 2, 2}));
    ed.press(key_of('Z'), kCtrl);
    EXPECT_TRUE(test::identical(ed.mesh(), cube));
    EXPECT_FALSE(ed.dirty());

    // A click without a move (or a "move" to the same place) leaves no step.
    ed.select(ElementRef::vertex(Vertex(7)));
    ASSERT_TRUE(ed.begin_drag());
    EXPECT_EQ(ed.drag_to(cube.position(Vertex(7))).changes, unsigned{kNothing});
    ed.end_drag();
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

// ---------------------------------------------------------------------------------- curve

TEST(Editor, CurveLevelsPointsAndT) {
    TempDir dir;
    const fs::path file = dir / "c.bzc";
    BezierCurve curve{{{0.1, 0.2, 0}, {0.3, 0.9, 0}, {0.7, 0.1, 0}, {0.9, 0.8, 0}}};
    write_bzc(curve, file);
    Editor ed;
    const Outcome opened = ed.open(file);
    EXPECT_EQ(opened.message, "opened c.bzc: 4 control points");
    EXPECT_EQ(ed.mode(), Mode::Curve);
    EXPECT_EQ(ed.title(), "c.bzc — curve, 4 points");
    EXPECT_EQ(ed.view().level, 0);

    // E shows one more level down to B(t) (level 3 of a cubic); Shift+E back to the polygon.
    for (int k = 1; k <= 3; ++k) {
        const Outcome out = ed.press(key_of('E'), 0);
        EXPECT_FALSE(out.refused);
        EXPECT_EQ(out.message, "de Casteljau level " + std::to_string(k) + " of 3");
        EXPECT_EQ(ed.view().level, k);
    }
    Outcome out = ed.press(key_of('E'), 0);
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, "already at the last level (B(t))");
    for (int k = 2; k >= 0; --k) {
        EXPECT_FALSE(ed.press(key_of('E'), kShift).refused);
        EXPECT_EQ(ed.view().level, k);
    }
    out = ed.press(key_of('E'), kShift);
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, "already at the control polygon");

    // t: [ and ] step 0.01, clamped to [0, 1].
    EXPECT_DOUBLE_EQ(ed.view().t, 0.5);
    ed.press(Key::RightBracket, 0);
    EXPECT_DOUBLE_EQ(ed.view().t, 0.51);
    ed.press(Key::LeftBracket, 0);
    ed.press(Key::LeftBracket, 0);
    EXPECT_DOUBLE_EQ(ed.view().t, 0.49);
    for (int i = 0; i < 100; ++i) {
        ed.press(Key::RightBracket, 0);
    }
    EXPECT_EQ(ed.view().t, 1.0);
    EXPECT_EQ(ed.set_t(-3).changes, unsigned{kDisplay});
    EXPECT_EQ(ed.view().t, 0.0);
    ed.press(Key::LeftBracket, 0);
    EXPECT_EQ(ed.view().t, 0.0);
    EXPECT_FALSE(ed.dirty()) << "t and levels are view state";

    // + inserts after the selected point, midway; without a selection it extends the end.
    ed.select(ElementRef::vertex(Vertex(1)));
    out = ed.press(Key::Equal, kShift);
    ASSERT_FALSE(out.refused);
    ASSERT_EQ(ed.document().curve.control_points.size(), 5u);
    EXPECT_EQ(ed.document().curve.control_points[2],
              0.5 * (curve.control_points[1] + curve.control_points[2]));
    EXPECT_EQ(ed.selection().index, 2u);
    ed.select({});
    ed.press(Key::KeypadAdd, 0);
    ASSERT_EQ(ed.document().curve.control_points.size(), 6u);
    const Vec3 last = curve.control_points[3];
    const Vec3 prev = curve.control_points[2];
    EXPECT_EQ(ed.document().curve.control_points[5], last + 0.5 * (last - prev));
    EXPECT_EQ(ed.selection().index, 5u);
    EXPECT_TRUE(ed.dirty());
    EXPECT_EQ(ed.history().undo_steps(), 2u);

    // - removes the selected point (else the last), never below two.
    ed.press(key_of('E'), 0);
    ed.press(key_of('E'), 0);
    ed.press(key_of('E'), 0);
    ed.press(key_of('E'), 0);
    ed.press(key_of('E'), 0);
    EXPECT_EQ(ed.view().level, 5);
    ed.select(ElementRef::vertex(Vertex(2)));
    ed.press(Key::Minus, 0);
    EXPECT_EQ(ed.document().curve.control_points.size(), 5u);
    EXPECT_EQ(ed.view().level, 4) << "the level stays within the new degree";
    ed.press(Key::Minus, 0);
    ed.press(Key::KeypadSubtract, 0);
    ed.press(Key::Minus, 0);
    EXPECT_EQ(ed.document().curve.control_points.size(), 2u);
    out = ed.press(Key::Minus, 0);
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, "a curve needs at least 2 control points");
    EXPECT_LE(ed.view().level, 1);

    // Undo everything: back to the file's curve, clean.
    while (!ed.press(key_of('Z'), kCtrl).refused) {
    }
    EXPECT_EQ(ed.document().curve.control_points, curve.control_points);
    EXPECT_FALSE(ed.dirty());

    // Drag a control point: z is kept, one undo step; then save and reload.
    ed.select(ElementRef::vertex(Vertex(3)));
    ASSERT_TRUE(ed.begin_drag());
    EXPECT_EQ(ed.drag_to({0.5, 0.5, 7}).changes, unsigned{kCurve});
    ed.end_drag();
    EXPECT_EQ(ed.document().curve.control_points[3], (Vec3{0.5, 0.5, 0}));
    ed.press(Key::Equal, 0);
    ASSERT_FALSE(ed.press(key_of('S'), kCtrl).refused);
    EXPECT_FALSE(ed.dirty());
    EXPECT_EQ(read_bzc(file).control_points, ed.document().curve.control_points);

    // Mesh commands are not bound in curve mode; C toggles the curve.
    EXPECT_EQ(ed.press(key_of('F'), 0).changes, unsigned{kNothing});
    EXPECT_TRUE(ed.view().show_curve);
    ed.press(key_of('C'), 0);
    EXPECT_FALSE(ed.view().show_curve);
    EXPECT_TRUE(ed.save_as(dir / "c.obj").refused);
    EXPECT_FALSE(ed.save_as(dir / "d.bzc").refused);
    EXPECT_EQ(ed.path(), dir / "d.bzc");

    // Selecting in curve mode names a control point; out of range selects nothing.
    ed.select(ElementRef::vertex(Vertex(9)));
    EXPECT_TRUE(ed.selection().is_none());
    ed.select(ElementRef::edge(Edge(0)));
    EXPECT_TRUE(ed.selection().is_none());
}

// -------------------------------------------------------------------------------- surface

TEST(Editor, SurfaceDensityRetessellates) {
    const fs::path file = fs::path(MESHEDIT_SOURCE_DIR) / "bez" / "teapot.bez";
    const std::vector<BezierPatch> patches = read_bez(file);
    const auto faces_at = [&](int density) {
        TessellationOptions o;
        o.density = density;
        return tessellate(patches, o).n_faces();
    };
    Editor ed;
    const Outcome opened = ed.open(file);
    EXPECT_EQ(ed.mode(), Mode::Surface);
    EXPECT_EQ(ed.document().density, 8);
    EXPECT_EQ(ed.mesh().n_faces(), faces_at(8));
    EXPECT_EQ(opened.message.rfind("opened teapot.bez: 32 patches, V ", 0), 0u) << opened.message;

    Outcome out = ed.press(Key::Equal, kShift);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(ed.document().density, 12);
    EXPECT_EQ(ed.mesh().n_faces(), faces_at(12));
    EXPECT_EQ(out.message, "density 12: " + std::to_string(faces_at(12)) + " faces");
    ed.press(Key::Minus, 0);
    ed.press(Key::Minus, 0);
    EXPECT_EQ(ed.document().density, 6);
    EXPECT_EQ(ed.mesh().n_faces(), faces_at(6));
    EXPECT_TRUE(ed.dirty());

    // Mesh operations work on the welded mesh; a later density change replaces them.
    ed.select(ElementRef::edge(Edge(40)));
    ASSERT_FALSE(ed.press(key_of('S'), 0).refused);
    EXPECT_VALID(ed.mesh());
    const std::size_t edited_faces = ed.mesh().n_faces();
    EXPECT_GT(edited_faces, faces_at(6));
    out = ed.press(Key::KeypadAdd, 0);
    EXPECT_EQ(out.message,
              "density 8: " + std::to_string(faces_at(8)) + " faces (mesh edits replaced)");
    EXPECT_TRUE(ed.selection().is_none());
    // ...and undo brings the edited mesh back.
    ed.press(key_of('Z'), kCtrl);
    EXPECT_EQ(ed.document().density, 6);
    EXPECT_EQ(ed.mesh().n_faces(), edited_faces);

    // Bounds.
    Editor low;
    low.open(file);
    for (int i = 0; i < 5; ++i) {
        EXPECT_FALSE(low.press(Key::Minus, 0).refused);
    }
    EXPECT_EQ(low.document().density, 1);
    out = low.press(Key::Minus, 0);
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, "density is already at the minimum (1)");

    // B toggles the nets; saving to the .bez is refused, saving as a mesh works.
    EXPECT_FALSE(ed.view().show_nets);
    ed.press(key_of('B'), 0);
    EXPECT_TRUE(ed.view().show_nets);
    out = ed.save();
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message,
              "a .bez file holds patches, not the edited mesh: save as .dae, .obj or .gltf "
              "(Ctrl+Shift+S)");
    TempDir dir;
    EXPECT_TRUE(ed.save_as(dir / "teapot.bez").refused);
    ASSERT_FALSE(ed.save_as(dir / "teapot.obj").refused);
    EXPECT_FALSE(ed.dirty());
    EXPECT_EQ(read_mesh(dir / "teapot.obj").mesh.n_faces(), ed.mesh().n_faces());
}

// ---------------------------------------------------------------------------------- files

TEST(Editor, BrokenFileLeavesTheDocumentUntouched) {
    TempDir dir;
    const fs::path good = dir / "cube.dae";
    write_mesh(shapes::cube(), good);
    Editor ed;
    ed.open(good);
    ed.select(ElementRef::edge(Edge(2)));
    ed.press(key_of('K'), 0);
    const Mesh before = ed.mesh();
    const std::uint64_t revision = ed.document().revision;

    const fs::path bad = dir / "broken.dae";
    std::ofstream(bad) << "<COLLADA><this is not xml";
    EXPECT_THROW(ed.open(bad), IoError);
    EXPECT_THROW(ed.open(dir / "missing.obj"), IoError);
    EXPECT_THROW(ed.open(dir / "file.xyz"), IoError);
    std::ofstream(dir / "bad.bzc") << "1\n0 0\n";
    EXPECT_THROW(ed.open(dir / "bad.bzc"), IoError);
    EXPECT_TRUE(test::identical(ed.mesh(), before));
    EXPECT_EQ(ed.path(), good);
    EXPECT_EQ(ed.document().revision, revision);
    EXPECT_EQ(ed.history().undo_steps(), 1u);
    EXPECT_TRUE(ed.dirty());
    EXPECT_EQ(ed.selection().kind, Kind::Edge);
}

TEST(Editor, OpenClearsHistoryAndSelection) {
    TempDir dir;
    write_mesh(shapes::icosahedron(), dir / "ico.obj");
    Editor ed = editor_with(shapes::cube());
    ed.select(ElementRef::edge(Edge(0)));
    ed.press(key_of('K'), 0);
    const Outcome out = ed.open(dir / "ico.obj");
    EXPECT_EQ(out.message, "opened ico.obj: V 12 E 30 F 20");
    EXPECT_TRUE(out.changes & kDocument);
    EXPECT_EQ(ed.history().undo_steps(), 0u);
    EXPECT_TRUE(ed.selection().is_none());
    EXPECT_FALSE(ed.dirty());
    EXPECT_FALSE(ed.quit_armed());
    EXPECT_EQ(ed.mode(), Mode::Mesh);
}

TEST(Editor, SaveRefusals) {
    Editor ed = editor_with(shapes::cube());
    EXPECT_EQ(ed.title(), "untitled — V 8 E 18 F 12");
    Outcome out = ed.save();
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, "no file name: use Ctrl+Shift+S");
    EXPECT_TRUE(ed.save_as("/no/such/folder/x.obj").refused);
    EXPECT_TRUE(ed.path().empty()) << "a failed save as keeps the old path";
    out = ed.save_as("cube.bzc");
    EXPECT_TRUE(out.refused);
    EXPECT_NE(out.message.find(".obj"), std::string::npos) << out.message;
}

}  // namespace
}  // namespace meshedit::viewer
