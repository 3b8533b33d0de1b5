/// \file
/// End-to-end test of the polygon operations in a real window: a face extruded with a mouse
/// drag (then cancelled with Esc, and confirmed and undone), a vertex bevelled with a typed
/// amount, two faces made boundary and two of the hole's edges welded, picked with
/// Shift+click — and the saved file equal to the same `--ops` run through `meshedit convert`.
///
/// Every click lands on a pixel computed from the viewer's opening camera (opening_camera),
/// so the test follows the mesh rather than hard-coded screen positions.

#include "view_pixels.h"
#include "viewer_fixture.h"

namespace meshedit::test::e2e {
namespace {

constexpr int kWidth = 1000;
constexpr int kHeight = 700;

/// The vertex to bevel: every face around it looks at the camera, it is at least 10 px from
/// every other vertex on screen, and it touches no face that shares a corner with `avoid`.
std::optional<std::pair<Vertex, Pixel>> bevel_target(const View& view, const Mesh& mesh,
                                                     const std::vector<Face>& avoid) {
    std::vector<bool> near_avoided(mesh.n_vertices(), false);
    for (Face f : avoid) {
        for (Vertex corner : mesh.vertices(f)) {
            for (Face g : mesh.faces(corner)) {
                for (Vertex w : mesh.vertices(g)) {
                    near_avoided[w.idx()] = true;
                }
            }
        }
    }
    std::optional<std::pair<Vertex, Pixel>> best;
    double best_facing = 0.3;
    for (Vertex v : mesh.vertices()) {
        if (near_avoided[v.idx()]) {
            continue;
        }
        double facing = 1.0;
        for (Face f : mesh.faces(v)) {
            facing = std::min(facing, view.facing(mesh, f));
        }
        const glm::vec2 p = view.pixel(mesh.position(v));
        float clearance = 1e9f;
        for (Vertex w : mesh.vertices()) {
            if (w != v) {
                clearance = std::min(clearance, glm::length(view.pixel(mesh.position(w)) - p));
            }
        }
        const std::optional<Pixel> px = clickable(view, p);
        if (px && clearance >= 10.0f && facing > best_facing) {
            best_facing = facing;
            best = std::make_pair(v, *px);
        }
    }
    return best;
}

TEST_F(ViewerE2E, PolygonExtrudeBevelWeldSave) {
    const fs::path original = source_dir() / "dae" / "quadball.dae";
    const fs::path doc = work_ / "quadball.dae";
    fs::copy_file(original, doc);
    const Mesh input = load(doc);
    const View view(input, kWidth, kHeight);

    // The hole: faces 75 (85-22-23-88) and 74 (84-85-88-87); the weld zips its edges 22-23
    // and 85-22 at their shared corner 22 (the demo of the poly_weld golden).
    const Face f75(75), f74(74);
    const Vertex v85(85), v22(22), v23(23);
    const std::optional<Pixel> at75 = face_pixel(view, input, f75);
    const std::optional<Pixel> at74 = face_pixel(view, input, f74);
    const std::optional<Pixel> at22_23 =
        edge_pixel(view, input, v22, v23, other_face(input, v22, v23, f75));
    const std::optional<Pixel> at85_22 =
        edge_pixel(view, input, v85, v22, other_face(input, v85, v22, f75));
    ASSERT_TRUE(at75 && at74 && at22_23 && at85_22)
        << "faces 74 and 75 of quadball.dae no longer face the opening camera";
    const auto bevel = bevel_target(view, input, {f75, f74});
    ASSERT_TRUE(bevel) << "no vertex of quadball.dae to bevel in the opening view";

    // The face to extrude: the one that looks most squarely at the camera.
    Face extruded;
    double best = 0.0;
    for (Face f : input.faces()) {
        if (view.facing(input, f) > best && face_pixel(view, input, f)) {
            best = view.facing(input, f);
            extruded = f;
        }
    }
    ASSERT_TRUE(extruded.is_valid());
    const Pixel at_extruded = *face_pixel(view, input, extruded);

    // What the session must save, and the counts the title shows on the way, through the
    // CLI's own op path (indices are not renumbered inside one --ops list).
    const std::string bevel_step = "bevel:v" + std::to_string(bevel->first.idx()) + ":0.25";
    const std::vector<std::string> stages = {
        "extrude:f" + std::to_string(extruded.idx()) + ":0.1",
        bevel_step,
        bevel_step + ",make_boundary:f75,make_boundary:f74",
        bevel_step + ",make_boundary:f75,make_boundary:f74,weld:85-22+22-23",
    };
    std::vector<Mesh> expected;
    for (std::size_t i = 0; i < stages.size(); ++i) {
        const fs::path file = logs_ / ("stage" + std::to_string(i) + ".dae");
        const RunResult r =
            run_meshedit({"convert", original.string(), file.string(), "--ops", stages[i]});
        ASSERT_EQ(r.exit_code, 0) << stages[i] << ": " << r.err;
        expected.push_back(load(file));
    }
    std::cout << "extruding f" << extruded.idx() << " at (" << at_extruded.x << ", "
              << at_extruded.y << "), bevelling v" << bevel->first.idx() << " at ("
              << bevel->second.x << ", " << bevel->second.y << ")\n";

    auto viewer = start_viewer(doc, std::to_string(kWidth) + "x" + std::to_string(kHeight));
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    const std::string opened = "MeshEdit — quadball.dae — " + counts(input);
    std::string title;
    ASSERT_TRUE(window.wait_title(opened, false, 20s, &title)) << title;

    // Pick the face, X: moving the mouse extrudes live; Esc cancels back to the clean input.
    window.click(at_extruded.x, at_extruded.y);
    window.key("x");
    const fs::path still = logs_ / "drag_start.png";
    const fs::path dragged = logs_ / "drag_moved.png";
    window.move_to(at_extruded.x + 10, at_extruded.y - 90);
    // The title shows the live mesh, without the unsaved mark until the drag is confirmed.
    ASSERT_TRUE(window.wait_title(counts(expected[0]), false, 20s, &title))
        << "dragging after X did not extrude f" << extruded.idx() << "; title '" << title << "'\n"
        << viewer->err();
    ASSERT_TRUE(window.capture(still));
    window.move_to(at_extruded.x + 10, at_extruded.y - 160);
    ASSERT_TRUE(window.capture(dragged));
    {
        const RgbImage a = read_rgb(still), b = read_rgb(dragged);
        ASSERT_EQ(a.width, b.width);
        int changed = 0;
        for (int y = 0; y < a.height; ++y) {
            for (int x = info_panel_pixels(kWidth); x < a.width; ++x) {
                changed += channel_difference(a, x, y, b, x, y) > 40;
            }
        }
        EXPECT_GT(changed, 200) << "moving the mouse 70 px during the drag changed only " << changed
                                << " pixels";
    }
    window.key("Escape");
    ASSERT_TRUE(window.wait_title(opened, false, 20s, &title)) << title;
    EXPECT_EQ(title, opened) << "Esc must leave the document untouched (and clean)";

    // Again, confirmed by a click: one undo step, and Ctrl+Z returns to the clean input.
    window.key("x");
    window.click(at_extruded.x + 10, at_extruded.y - 90);
    ASSERT_TRUE(window.wait_title(counts(expected[0]) + " *", false, 20s, &title)) << title;
    window.key("ctrl+z");
    ASSERT_TRUE(window.wait_title(opened, false, 20s, &title)) << title;
    EXPECT_EQ(title, opened);

    // Bevel a vertex by a typed amount: Ctrl+B, 0.25, Enter (the mouse stays still).
    window.click(bevel->second.x, bevel->second.y);
    window.key("ctrl+b");
    window.type("0.25");
    window.key("Return");
    ASSERT_TRUE(window.wait_title(counts(expected[1]) + " *", false, 20s, &title))
        << bevel_step << ": title '" << title << "'\n"
        << viewer->err();

    // Faces 75 and 74 (Shift+click adds the second), Shift+Delete: one hole.
    window.click(at75->x, at75->y);
    window.shift_click(at74->x, at74->y);
    window.key("shift+Delete");
    ASSERT_TRUE(window.wait_title(counts(expected[2]) + " *", false, 20s, &title))
        << "make_boundary of faces 75 and 74: title '" << title << "'\n"
        << viewer->err();

    // Weld: 22-23, then Shift+click 85-22 (the active edge stays: weld:85-22+22-23), J.
    window.click(at22_23->x, at22_23->y);
    window.shift_click(at85_22->x, at85_22->y);
    window.key("j");
    ASSERT_TRUE(window.wait_title(counts(expected[3]) + " *", false, 20s, &title))
        << "weld of 85-22 and 22-23: title '" << title << "'\n"
        << viewer->err();

    // Save: the file equals the --ops run, bit for bit in positions.
    window.key("ctrl+s");
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;
    EXPECT_TRUE(same_mesh(load(doc), expected[3])) << "--ops " << stages[3];
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

}  // namespace
}  // namespace meshedit::test::e2e
