/// \file
/// End-to-end test of a long operation in a real window (issue 40): the 1.2M-face bunny
/// (CGAL's bunny00 Loop-subdivided twice), D (simplify to half) running in the background
/// while the view orbits, Esc (the document as it was), D again to the end, Ctrl+Z (the
/// original, the camera where the user left it), and Save as to an absolute path, then with
/// Backspaces and to a relative path, on a document whose frames are slow.

#include <thread>

#include "meshedit/core/subdivision.h"
#include "support/demo_meshes.h"
#include "viewer_fixture.h"

namespace meshedit::test::e2e {
namespace {

constexpr int kWidth = 1000;
constexpr int kHeight = 700;

/// Pixels of the 3D view right of the info panel and above the status line that differ by
/// more than 40 in some channel.
int view_pixels_changed(const fs::path& a_png, const fs::path& b_png) {
    const RgbImage a = read_rgb(a_png);
    const RgbImage b = read_rgb(b_png);
    if (a.width != b.width || a.height != b.height) {
        return a.width * a.height;
    }
    int changed = 0;
    for (int y = 0; y < a.height - 120; ++y) {
        for (int x = info_panel_pixels(a.width); x < a.width; ++x) {
            changed += channel_difference(a, x, y, b, x, y) > 40;
        }
    }
    return changed;
}

using JobsE2E = ViewerE2E;

TEST_F(JobsE2E, SimplifyRunsInTheBackgroundAndEscCancels) {
    Mesh bunny = read_mesh(test::demo_mesh("bunny00", out_dir() / "demo")).mesh;
    loop_subdivide(bunny);
    loop_subdivide(bunny);
    ASSERT_EQ(bunny.n_faces(), 1206528u);
    const fs::path doc = work_ / "bunny_l2.ply";
    write_mesh(bunny, doc);
    const Mesh original = load(doc);

    auto viewer = start_viewer(doc, std::to_string(kWidth) + "x" + std::to_string(kHeight));
    ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    // While the file is read (on a worker), the window already shows its panels: the info
    // panel's dark rectangle stands at the top left of the first frames.
    // Polled: under load the window may map before its first frame is drawn.
    const fs::path reading = logs_ / "reading.png";
    bool panel_while_reading = false, loaded_first = false;
    for (int i = 0; i < 100 && !panel_while_reading && !loaded_first; ++i) {
        ASSERT_TRUE(window.capture(reading));
        loaded_first = window.title().find("F 1206528") != std::string::npos;
        const RgbImage first = read_rgb(reading);
        ASSERT_EQ(first.width, kWidth);
        const std::uint8_t* panel = first.at(150, 40);
        panel_while_reading = !loaded_first && int(panel[0]) + panel[1] + panel[2] < 3 * 90;
        std::this_thread::sleep_for(50ms);
    }
    EXPECT_TRUE(panel_while_reading || loaded_first)
        << "no info panel while the file is read (the first frame waited for it)";
    std::string title;
    ASSERT_TRUE(window.wait_title("F 1206528", false, 60s, &title)) << title << viewer->err();
    const std::string opened = window.title();
    window.move_to(kWidth - 5, 5);  // no hover highlight in the pictures
    const fs::path before = logs_ / "before.png";
    ASSERT_TRUE(window.capture(before));

    // D, then an orbit while it runs: new frames show the turned view, the title (the
    // document) still the original.
    window.key("d");
    window.drag(650, 350, 800, 340, 3);
    window.move_to(kWidth - 5, 5);
    // A frame of the turned view comes within a frame's time (seconds on a loaded machine).
    const fs::path during = logs_ / "during.png";
    const bool turned = wait_until(
        [&] { return window.capture(during) && view_pixels_changed(before, during) > 2000; }, 30s,
        200ms);
    EXPECT_EQ(window.title(), opened) << "simplify ended before the orbit was seen: nothing was "
                                         "shown running; make the mesh bigger";
    EXPECT_TRUE(turned) << "the view did not turn while it ran";

    // Esc: cancelled; the document is as it was (no '*', the same counts).
    window.key("Escape");
    sleep_for(1500ms);
    EXPECT_EQ(window.title(), opened);
    const fs::path cancelled = logs_ / "cancelled.png";
    ASSERT_TRUE(window.capture(cancelled));

    // D to the end, then Ctrl+Z: the original, seen from where the orbit left the camera.
    window.key("d");
    ASSERT_TRUE(window.wait_title("F 603264 *", false, 90s, &title)) << title << viewer->err();
    window.key("ctrl+z");
    ASSERT_TRUE(window.wait_title(" *", true, 30s, &title)) << title;
    EXPECT_EQ(window.title(), opened);
    sleep_for(1000ms);
    window.move_to(kWidth - 6, 6);
    const fs::path undone = logs_ / "undone.png";
    ASSERT_TRUE(window.capture(undone));
    EXPECT_LT(view_pixels_changed(cancelled, undone), 200) << "the camera moved";

    // Save as, to an absolute path in another folder: the original, exactly.
    const fs::path saved = work_ / "saved" / "bunny_back.ply";
    fs::create_directories(saved.parent_path());
    answer_prompt(window, "ctrl+shift+s", saved);
    ASSERT_TRUE(wait_until([&] { return fs::exists(saved); }, 60s)) << viewer->err();
    ASSERT_TRUE(window.wait_title("bunny_back.ply", false, 30s, &title)) << title;
    EXPECT_TRUE(same_mesh(load(saved), original));

    // Save as again, the field starting with the document's name: End, then eight Backspaces
    // at once take "back.ply" away (none lost between two slow frames), "two.ply" is typed.
    const fs::path two = saved.parent_path() / "bunny_two.ply";
    std::vector<std::string> keys{"End"};
    keys.insert(keys.end(), 8, "BackSpace");
    edit_prompt(window, "ctrl+shift+s", keys, "two.ply");
    ASSERT_TRUE(window.wait_title("bunny_two.ply", false, 60s, &title)) << title << viewer->err();
    EXPECT_TRUE(fs::exists(two));
    // A relative path is relative to the document's folder.
    fs::create_directories(saved.parent_path() / "rel");
    answer_prompt(window, "ctrl+shift+s", fs::path("rel/bunny_rel.ply"));
    ASSERT_TRUE(window.wait_title("bunny_rel.ply", false, 60s, &title)) << title << viewer->err();
    EXPECT_TRUE(fs::exists(saved.parent_path() / "rel" / "bunny_rel.ply"));
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

}  // namespace
}  // namespace meshedit::test::e2e
