// The editor's curve and surface commands: de Casteljau levels and t, control points,
// tessellation density.

#include <gtest/gtest.h>

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
#include "viewer/editor_test_util.h"

namespace meshedit::viewer {
namespace {

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
    EXPECT_EQ(ed.document().curve.control_points[2], (Vec3{0.5, 0.5, 0}));
    EXPECT_EQ(ed.selection().index, 2u);
    ed.select({});
    ed.press(Key::KeypadAdd, 0);
    ASSERT_EQ(ed.document().curve.control_points.size(), 6u);
    // 0.9 + 0.5 (0.9 - 0.7) is 1.0000000000000002 in doubles: the point is the 1 one means.
    EXPECT_EQ(ed.document().curve.control_points[5], (Vec3{1.0, 1.15, 0}));
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
    // With the pixel size given (as the window does), no digits finer than a pixel: a point
    // dragged where a pixel is 0.002 wide lands on a multiple of 0.001.
    ASSERT_TRUE(ed.begin_drag());
    const Outcome moved = ed.drag_to({0.30750003457069397, 0.51249, 0}, 0.002);
    EXPECT_EQ(moved.message, "moving control point 3 by (-0.1920, 0.0120), 0.1924");
    ed.end_drag();
    EXPECT_EQ(ed.document().curve.control_points[3], (Vec3{0.308, 0.512, 0}));
    ASSERT_TRUE(ed.begin_drag());
    ed.drag_to({123.456, -0.049, 0}, 20.0);  // far out: steps of 10
    ed.end_drag();
    EXPECT_EQ(ed.document().curve.control_points[3], (Vec3{120, -0.0, 0}));
    ed.press(key_of('Z'), kCtrl);
    ed.press(key_of('Z'), kCtrl);
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

    // B toggles the nets. Saving to the .bez writes the patches; having edited the
    // tessellation, that is asked once (the edits would be lost); saving as a mesh keeps them.
    EXPECT_FALSE(ed.view().show_nets);
    ed.press(key_of('B'), 0);
    EXPECT_TRUE(ed.view().show_nets);
    TempDir dir;
    ed.select(ElementRef::edge(Edge(40)));
    ASSERT_FALSE(ed.press(key_of('S'), 0).refused);
    out = ed.save_as(dir / "teapot.bez");
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message,
              "saving as .bez loses the edits of the tessellated mesh (a .bez file holds only "
              "the patches): save again to save anyway, or save as .dae to keep everything");
    EXPECT_FALSE(fs::exists(dir / "teapot.bez"));
    EXPECT_TRUE(ed.save_as(dir / "teapot.txt").refused);
    ASSERT_FALSE(ed.save_as(dir / "teapot.obj").refused);
    EXPECT_FALSE(ed.dirty());
    EXPECT_EQ(read_mesh(dir / "teapot.obj").mesh.n_faces(), ed.mesh().n_faces());
    out = ed.save_as(dir / "teapot.bez");
    EXPECT_TRUE(out.refused) << "asked again: the target changed";
    out = ed.save_as(dir / "teapot.bez");
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(read_bez(dir / "teapot.bez").size(), patches.size());
    for (std::size_t p = 0; p < patches.size(); ++p) {
        EXPECT_EQ(read_bez(dir / "teapot.bez")[p].control_points, patches[p].control_points);
    }

    // Unedited patches save without a question, Ctrl+S included.
    Editor fresh;
    ASSERT_FALSE(fresh.open(dir / "teapot.bez").refused);
    fresh.press(Key::Minus, 0);
    EXPECT_TRUE(fresh.dirty());
    out = fresh.save();
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(out.message, "saved teapot.bez");
    EXPECT_FALSE(fresh.dirty());
}

}  // namespace
// Shift+U steps de Casteljau on the patch at the selection: the first press finds the patch
// and (u, v) whose point is the selected vertex, each press one step more, past S(u, v) off.
TEST(Editor, PatchStepsFollowTheSelection) {
    const fs::path file = fs::path(MESHEDIT_SOURCE_DIR) / "bez" / "teapot.bez";
    const std::vector<BezierPatch> patches = read_bez(file);
    Editor ed;
    ASSERT_FALSE(ed.open(file).refused);
    // The tessellation's point of patch 5 at (u, v) = (0.25, 0.75): density 8 samples it.
    const Vec3 target = patches[5].evaluate(0.25, 0.75);
    Vertex at;
    for (const Vertex v : ed.mesh().vertices()) {
        if (distance(ed.mesh().position(v), target) < 1e-9) {
            at = v;
        }
    }
    ASSERT_TRUE(at.is_valid());
    ASSERT_FALSE(ed.select(ElementRef::vertex(at)).refused);
    Outcome out = ed.press(key_of('U'), kShift);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(ed.view().patch_step, 0);
    // A seam point is on two patches: either one, at the point's own (u, v) there.
    EXPECT_LT(
        distance(patches[ed.view().patch].evaluate(ed.view().patch_u, ed.view().patch_v), target),
        1e-9);
    EXPECT_NE(out.message.find("the control net (step 0 of 6; Shift+U: next)"), std::string::npos)
        << out.message;
    // 3 levels along u, 3 along v (the last one S(u, v)), then off.
    out = ed.press(key_of('U'), kShift);
    EXPECT_NE(out.message.find("level 1 along u (step 1 of 6"), std::string::npos) << out.message;
    for (int k = 2; k <= 6; ++k) {
        out = ed.press(key_of('U'), kShift);
        EXPECT_EQ(ed.view().patch_step, k);
    }
    EXPECT_NE(out.message.find("S(u, v) (step 6 of 6"), std::string::npos) << out.message;
    out = ed.press(key_of('U'), kShift);
    EXPECT_EQ(ed.view().patch_step, -1);
    EXPECT_EQ(out.message, "patch evaluation off");
}

}  // namespace meshedit::viewer
