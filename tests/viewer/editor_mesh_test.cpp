// The editor's mesh edits: each key runs its verb on the selection exactly as the core op
// would, refusals leave the document untouched, the selection follows the result and is
// remapped through garbage collection.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/loop_steps.h"
#include "meshedit/core/quad_subdivision.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/simplify.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/io/io.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"
#include "viewer/editor_test_util.h"

namespace meshedit::viewer {
namespace {

// ------------------------------------------------------------------------ mesh operations

// Whole-mesh operations and their undo leave the view where the user put it (issue 40: Loop
// used to re-frame onto the shrunk mesh): they ask only for the depth range to follow.
TEST(Editor, WholeMeshEditsAndUndoKeepTheView) {
    Editor ed = editor_with(test::quad_cube());
    for (const auto& [key, mods] : {std::pair{key_of('C'), kShift}, std::pair{key_of('T'), kCtrl},
                                    std::pair{key_of('L'), kNoMods}}) {
        const Outcome out = ed.press(key, mods);
        ASSERT_FALSE(out.refused) << out.message;
        EXPECT_NE(out.changes & kSceneBounds, 0u) << out.message;
        EXPECT_EQ(out.changes & kResetCamera, 0u) << out.message;
    }
    const Outcome undone = ed.run({Command::Undo});
    EXPECT_EQ(undone.changes & kResetCamera, 0u);
}

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
    for (Key k : {key_of('F'), key_of('S'), key_of('K'), key_of('C')}) {
        const std::string wanted =
            k == key_of('C') ? "select an edge or a face first" : "select an edge first";
        Outcome out = ed.press(k, 0);
        EXPECT_TRUE(out.refused);
        EXPECT_EQ(out.message, wanted);
        ed.select(ElementRef::vertex(Vertex(2)));
        out = ed.press(k, 0);
        EXPECT_TRUE(out.refused);
        EXPECT_EQ(out.message, wanted);
        if (k != key_of('C')) {
            ed.select(ElementRef::face(Face(2)));
            EXPECT_TRUE(ed.press(k, 0).refused);
        }
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

// A local edit leaves its deleted elements as tombstones: every other index stays, and the
// edit costs what it touches, not a renumbering of the mesh (saving collects them).
TEST(Editor, CollapseSelectsSurvivorAndKeepsIndices) {
    const Mesh ico = shapes::icosphere(1);
    const Edge e = Edge(17);
    const Vertex a = ico.from_vertex(Mesh::halfedge(e, 0));
    const Vertex b = ico.to_vertex(Mesh::halfedge(e, 0));
    const Vertex survivor(std::min(a.idx(), b.idx()));
    const Vec3 mid = 0.5 * (ico.position(a) + ico.position(b));
    Mesh expected = ico;
    ASSERT_TRUE(collapse(expected, e));

    Editor ed = editor_with(ico);
    ed.select(ElementRef::edge(e));
    const Outcome out = ed.press(key_of('C'), 0);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_TRUE(ed.mesh().has_garbage());
    EXPECT_TRUE(ed.history().last_is_change());
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

// Shift+C is Catmull-Clark and Ctrl+L linear subdivision, on polygons too: one undo step
// each, the selected vertex kept, the result as the core computes it.
TEST(Editor, CatmullClarkAndLinearKeys) {
    const Mesh cube = test::quad_cube();
    Mesh expected = cube;
    quad_subdivide(expected);

    Editor ed = editor_with(cube);
    ed.select(ElementRef::vertex(Vertex(2)));
    const Outcome out = ed.press(key_of('C'), kShift);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(out.message, "Catmull-Clark: 24 quads");
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    EXPECT_EQ(ed.selection(), ElementRef::vertex(Vertex(2)));

    QuadSubdivisionOptions linear;
    linear.scheme = QuadScheme::Linear;
    quad_subdivide(expected, linear);
    EXPECT_EQ(ed.press(key_of('L'), kCtrl).message, "linear subdivision: 96 quads");
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    EXPECT_EQ(ed.history().undo_steps(), 2u);
    ed.run({Command::Undo});
    ed.run({Command::Undo});
    EXPECT_TRUE(test::identical(ed.mesh(), cube));

    Editor empty = editor_with(Mesh());
    EXPECT_TRUE(empty.press(key_of('C'), kShift).refused);
}

// D simplifies to half the faces (QEM), one undo step; polygons are refused with the reason.
TEST(Editor, DSimplifiesToHalf) {
    const Mesh ball = shapes::icosphere(3);  // 1,280 triangles
    Mesh expected = ball;
    SimplifyOptions half;
    half.target_faces = 640;
    simplify(expected, half);
    expected.garbage_collection();

    Editor ed = editor_with(ball);
    const Outcome out = ed.press(key_of('D'), 0);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(out.message.rfind("simplified 1280 faces to 640", 0), 0u) << out.message;
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    ed.run({Command::Undo});
    EXPECT_TRUE(test::identical(ed.mesh(), ball));

    Editor quads = editor_with(test::quad_cube());
    const Outcome refused = quads.press(key_of('D'), 0);
    EXPECT_TRUE(refused.refused);
    EXPECT_NE(refused.message.find("6 of the 6 faces are polygons"), std::string::npos);
}

// Shift+R remeshes toward the mean edge length, one undo step.
TEST(Editor, ShiftRRemeshes) {
    const Mesh ball = shapes::icosphere(2);
    Mesh expected = ball;
    remesh(expected, RemeshOptions{});
    Editor ed = editor_with(ball);
    const Outcome out = ed.press(key_of('R'), kShift);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(out.message.rfind("remeshed to edge length ", 0), 0u) << out.message;
    EXPECT_TRUE(test::identical(ed.mesh(), expected));
    ed.run({Command::Undo});
    EXPECT_TRUE(test::identical(ed.mesh(), ball));
}

// The tool settings (the panel's "Global operations") set D's ratio and Shift+R's length and
// rounds.
TEST(Editor, ToolSettingsSetTheAmounts) {
    const Mesh ball = shapes::icosphere(3);  // 1,280 triangles
    Editor ed = editor_with(ball);
    ed.tools().amounts("simplify")[0] = 0.25;
    ASSERT_FALSE(ed.press(key_of('D'), 0).refused);
    EXPECT_EQ(ed.mesh().n_faces(), 320u);

    Editor remeshing = editor_with(ball);
    remeshing.tools().amounts("remesh")[0] = 0.3;
    remeshing.tools().amounts("remesh")[1] = 2;
    Mesh expected = ball;
    RemeshOptions options;
    options.target_length = 0.3;
    options.iterations = 2;
    remesh(expected, options);
    const Outcome out = remeshing.press(key_of('R'), kShift);
    EXPECT_EQ(out.message.rfind("remeshed to edge length 0.3:", 0), 0u) << out.message;
    EXPECT_TRUE(test::identical(remeshing.mesh(), expected));

    remeshing.tools().amounts("remesh")[1] = 0;
    EXPECT_TRUE(remeshing.press(key_of('R'), kShift).refused);
}

// A whole-mesh operation reports its progress through the hook: its verb, from 0 up to 1.
TEST(Editor, ProgressHookSeesTheOperationRise) {
    Editor ed = editor_with(shapes::icosphere(3));
    std::vector<double> seen;
    ed.set_progress_hook([&](std::string_view verb, double f) {
        EXPECT_EQ(verb, "remesh");
        seen.push_back(f);
    });
    ASSERT_FALSE(ed.press(key_of('R'), kShift).refused);
    ASSERT_GE(seen.size(), 2u);
    EXPECT_EQ(seen.front(), 0.0);
    EXPECT_EQ(seen.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
}

// Alt+L: Loop one phase per press, each one undo step named in the status line; L refuses
// mid-way; four presses are the classic Loop; undo walks back through the phases.
TEST(EditorLoopSteps, FourPressesAreLoopAndUndoWalksBack) {
    Editor ed = editor_with(shapes::icosahedron());
    std::vector<Mesh> states = {ed.mesh()};
    const char* const messages[] = {
        // One message over two lines: the parentheses tell clang the joined literals are meant.
        ("Loop 1/4: computed the new position of 12 vertices and 30 edge points (nothing moved "
         "yet)"),
        "Loop 2/4: split 30 edges",
        "Loop 3/4: flipped 20 new edges that join an old and a new vertex",
        "Loop 4/4: moved 42 vertices to their new positions"};
    for (int phase = 1; phase <= 4; ++phase) {
        const Outcome out = ed.press(key_of('L'), kAlt);
        ASSERT_FALSE(out.refused) << out.message;
        EXPECT_EQ(out.message, messages[phase - 1]);
        states.push_back(ed.mesh());
        if (phase == 2) {
            const Outcome loop = ed.press(key_of('L'), kNoMods);
            EXPECT_TRUE(loop.refused);
            EXPECT_EQ(loop.message,
                      "cannot subdivide: a phased Loop is under way (phase 3 of 4 is next: "
                      "`loop_step:2` finishes it, undo goes back)");
        }
    }
    Mesh classic = shapes::icosahedron();
    loop_subdivide_classic(classic);
    EXPECT_TRUE(test::identical(ed.mesh(), classic));
    EXPECT_EQ(ed.document().session,
              (std::vector<std::string>{"loop_step", "loop_step", "loop_step", "loop_step"}));
    for (int phase = 3; phase >= 0; --phase) {
        ASSERT_FALSE(ed.run({Command::Undo}).refused);
        EXPECT_TRUE(test::identical(ed.mesh(), states[static_cast<std::size_t>(phase)]))
            << "undo to before phase " << phase + 1;
        EXPECT_EQ(next_loop_phase(ed.mesh()), phase + 1);
    }
}

}  // namespace
}  // namespace meshedit::viewer
