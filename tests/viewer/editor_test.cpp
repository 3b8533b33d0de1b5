// The editor's dispatcher and history: display toggles that are not edits, undo/redo and the
// dirty flag, quit protection.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "meshedit/core/fields.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/subdivision.h"
#include "meshedit/io/io.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"
#include "viewer/editor_test_util.h"

namespace meshedit::viewer {
namespace {

// ------------------------------------------------------------------------ display, mode

TEST(Editor, SmallMeshesOpenFlatAndCurvedOnesSmooth) {
    EXPECT_FALSE(editor_with(shapes::cube()).view().render.smooth) << "12 faces";
    const Mesh sphere = shapes::icosphere(2);  // 320 faces
    ASSERT_LT(sphere.n_faces(), kSmoothFromFaces);
    EXPECT_FALSE(editor_with(sphere).view().render.smooth);
    const Mesh finer = shapes::icosphere(3);  // 1280 faces
    ASSERT_GE(finer.n_faces(), kSmoothFromFaces);
    EXPECT_TRUE(editor_with(finer).view().render.smooth);
    // Each document gets its own default, whatever Q did to the last one.
    Editor ed = editor_with(finer);
    ed.press(key_of('Q'), 0);
    EXPECT_FALSE(ed.view().render.smooth);
    ed.set_document(mesh_document(finer), "finer.obj");
    EXPECT_TRUE(ed.view().render.smooth);
}

TEST(Editor, StencilViewCyclesItsSchemesAndFollowsHoverThenSelection) {
    Editor ed = editor_with(shapes::cube());
    EXPECT_TRUE(ed.stencil_element().is_none());
    const std::vector<std::string> expected{"Loop (Warren's weights)", "Loop (Loop's weights)",
                                            "Catmull-Clark"};
    for (const std::string& name : expected) {
        const Outcome out = ed.press(key_of('W'), kAlt);
        ASSERT_TRUE(ed.view().stencil.has_value());
        EXPECT_EQ(scheme_name(*ed.view().stencil), name);
        EXPECT_NE(out.message.find(name), std::string::npos) << out.message;
    }
    EXPECT_EQ(ed.press(key_of('W'), kAlt).message, "stencil view off");
    EXPECT_FALSE(ed.view().stencil.has_value());
    ed.press(key_of('W'), kAlt);
    EXPECT_TRUE(ed.stencil_element().is_none());  // nothing hovered or selected
    ed.select(ElementRef::vertex(Vertex(2)));
    EXPECT_EQ(ed.stencil_element(), ElementRef::vertex(Vertex(2)));
    ed.set_hover(ElementRef::edge(Edge(1)));
    EXPECT_EQ(ed.stencil_element(), ElementRef::edge(Edge(1)));
    ed.set_hover({});
    EXPECT_EQ(ed.stencil_element(), ElementRef::vertex(Vertex(2)));
    // A display state: no edit, nothing to undo.
    EXPECT_FALSE(ed.dirty());
    EXPECT_EQ(ed.history().undo_steps(), 0u);
}

TEST(Editor, AltFStepsThroughTheComputedFieldsThenTheMeshsOwnNumbers) {
    // A compare --field file's deviation (a PLY column) is a field like the curvatures.
    Mesh cube = shapes::cube();
    cube.add_property<Vertex, double>("v:ply:deviation", 0.25);
    Editor ed = editor_with(std::move(cube));
    for (const FieldInfo& info : field_infos()) {
        ed.press(key_of('F'), kAlt);
        ASSERT_EQ(ed.view().field, &info);
    }
    const Outcome out = ed.press(key_of('F'), kAlt);
    ASSERT_NE(ed.view().field, nullptr);
    EXPECT_EQ(ed.view().field->name, "deviation");
    EXPECT_EQ(out.message, "field: deviation (Alt+F: next)");
    EXPECT_EQ(ed.press(key_of('F'), kAlt).message, "field off");
    EXPECT_EQ(ed.view().field, nullptr);
    EXPECT_FALSE(ed.dirty());
}

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
    // 8 and 9 are the user's shaders: the message says where the file is.
    EXPECT_EQ(ed.press(key_of('8'), 0).message,
              "shading 8: your shader: mesh8.frag in the user shader folder (docs/shaders.md)");
    EXPECT_EQ(ed.view().render.shading, 8);
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
    const Outcome none = ed.press(key_of('Z'), 0);
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

}  // namespace
}  // namespace meshedit::viewer

namespace meshedit::viewer {
namespace {

// Shift+K marks the edges sharper than the info panel's feature angle; the count is in the
// status line, the session records the step, and undo takes the marks away.
TEST(Editor, ShiftKMarksSharpEdgesByTheToolAngle) {
    Editor ed = editor_with(shapes::cube());
    const Mesh before = ed.mesh();
    ed.tools().amounts("crease_by_angle")[0] = 100.0;
    EXPECT_EQ(ed.press(key_of('K'), kShift).message, "marked 0 edges sharper than 100° as creases");
    ed.tools().amounts("crease_by_angle")[0] = 60.0;
    const Outcome out = ed.press(key_of('K'), kShift);
    EXPECT_EQ(out.message, "marked 12 edges sharper than 60° as creases");
    const auto crease = ed.mesh().get_property<Edge, std::uint8_t>(kCreaseProperty);
    ASSERT_TRUE(crease);
    std::size_t n = 0;
    for (Edge e : ed.mesh().edges()) {
        n += crease[e] != 0;
    }
    EXPECT_EQ(n, 12u);
    EXPECT_VALID(ed.mesh());
    ed.press(key_of('Z'), kCtrl);
    ed.press(key_of('Z'), kCtrl);
    EXPECT_TRUE(test::identical(ed.mesh(), before));
}

}  // namespace
}  // namespace meshedit::viewer
