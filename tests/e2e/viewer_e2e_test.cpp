/// \file
/// End-to-end tests of the interactive viewer: the real `meshedit FILE` (which execs
/// meshedit-view) in a private Xvfb, driven like a person drives it — pointer and keys
/// through xdotool, the window title read back to synchronise, screenshots (P) compared with
/// golden images and with the headless renderer, saved files read back and compared face by
/// face.
///
/// MESHEDIT_UPDATE_GOLDEN=1 rewrites tests/e2e/golden/ instead of comparing (look at every
/// rewritten PNG before committing it). The headless goldens of tests/golden/ are only read.

#include "view_pixels.h"
#include "viewer_fixture.h"

namespace meshedit::test::e2e {
namespace {

// Click an edge, flip it, save; Loop twice and screenshot (golden + headless render); undo
// back through the flip to the input, saving on the way; quit.
TEST_F(ViewerE2E, CubeFlipSaveLoopUndo) {
    const fs::path original = source_dir() / "dae" / "cube.dae";
    const fs::path doc = work_ / "cube.dae";
    fs::copy_file(original, doc);
    const Mesh input = load(doc);

    std::string candidates;
    const std::optional<EdgeTarget> target = flip_target(input, 800, 600, candidates);
    ASSERT_TRUE(target) << "no visible flippable edge to click; candidates:\n" << candidates;
    std::cout << "clicking edge " << target->a << "-" << target->b << " at (" << target->x << ", "
              << target->y << ")\n";

    // The expected flip, through the CLI's own op path.
    const fs::path expected_file = logs_ / "expected.dae";
    const RunResult convert = run_meshedit(
        {"convert", original.string(), expected_file.string(), "--ops", target->ops()});
    ASSERT_EQ(convert.exit_code, 0) << convert.err;
    const Mesh expected = load(expected_file);

    auto viewer = start_viewer(doc, "800x600");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title(kCubeTitle, false, 20s, &title)) << title;

    // Select the edge and flip it: the title gets its '*'.
    window.click(target->x, target->y);
    window.key("f");
    ASSERT_TRUE(window.wait_title(" *", false, 20s, &title))
        << "no unsaved change after clicking edge " << target->a << "-" << target->b
        << " and pressing F; title '" << title << "'\nstderr:\n"
        << viewer->err();
    EXPECT_EQ(title, kCubeTitle + " *");

    // Ctrl+S writes the flip to the opened file.
    window.key("ctrl+s");
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;
    EXPECT_TRUE(same_mesh(load(doc), expected)) << "saved after the flip of " << target->ops();
    if (target->a == 0 && target->b == 6) {
        EXPECT_TRUE(same_mesh(load(doc), load(source_dir() / "dae" / "cube" / "flip.dae")));
    }

    // Loop twice; P writes the 3D view the info panel leaves free (800 − 310 px wide). The
    // view stays where it was (Loop shrinks the cube: it looks smaller), as after an undo.
    window.move_to(780, 20);
    const fs::path before_loop = logs_ / "before_loop.png";
    ASSERT_TRUE(window.capture(before_loop));
    window.keys({"l", "l"});
    ASSERT_TRUE(window.wait_title("V 98 E 288 F 192 *", false, 60s, &title)) << title;
    const fs::path after_loop = logs_ / "after_loop.png";
    const auto width = [](const fs::path& png) {
        return silhouette(read_rgb(png), info_panel_pixels(800) + 10, 60).width;
    };
    ASSERT_TRUE(wait_until(
        [&] { return window.capture(after_loop) && width(after_loop) < 0.9 * width(before_loop); },
        20s, 200ms))
        << "the cube's silhouette after Loop is " << width(after_loop) << " px wide, before "
        << width(before_loop) << " px: the view was re-framed";
    const fs::path shot = screenshot(*viewer, window, 1);
    ASSERT_FALSE(shot.empty());
    const int free_width = 800 - info_panel_pixels(800);
    EXPECT_TRUE(looks_rendered(shot, free_width, 600));
    expect_golden(shot, "cube_flip_loop2");

    // The headless renderer draws the same picture at the free part's size. The viewer keeps
    // its camera through edits while `meshedit render` frames the final mesh, so Space (reset
    // camera: the same framing) first; the viewer shows the wireframe by default, `render` on
    // --wireframe, and a cube opens flat (under 500 faces), `render` on --flat.
    window.key("space");
    const fs::path framed = screenshot(*viewer, window, 2);
    ASSERT_FALSE(framed.empty());
    const fs::path headless = logs_ / "headless.png";
    const RunResult render = run_meshedit({"render", original.string(), "-o", headless.string(),
                                           "--size", std::to_string(free_width) + "x600", "--ops",
                                           target->ops() + ",loop:2", "--wireframe", "--flat"},
                                          120.0);
    ASSERT_EQ(render.exit_code, 0) << render.err;
    EXPECT_TRUE(images_match(framed, headless, out_dir(), "cube_flip_loop2_vs_headless"));

    // Undo both Loops, redo them (both redo keys), undo again: the flipped cube, which is
    // what is on disk (clean).
    window.keys({"ctrl+z", "ctrl+z"});
    ASSERT_TRUE(window.wait_title("V 8 E 18 F 12", false, 20s, &title)) << title;
    window.key("ctrl+y");
    ASSERT_TRUE(window.wait_title("V 26 E 72 F 48 *", false, 20s, &title)) << title;
    window.key("ctrl+shift+z");
    ASSERT_TRUE(window.wait_title("V 98 E 288 F 192 *", false, 20s, &title)) << title;
    window.keys({"ctrl+z", "ctrl+z"});
    ASSERT_TRUE(window.wait_title("V 8 E 18 F 12", false, 20s, &title)) << title;
    EXPECT_EQ(window.title(), kCubeTitle);
    const auto before_save = file_stamp(doc);
    window.key("ctrl+s");
    ASSERT_TRUE(wait_until([&] { return file_stamp(doc) != before_save; }, 20s))
        << "Ctrl+S did not rewrite " << doc;
    EXPECT_TRUE(same_mesh(load(doc), expected)) << "saved after undoing both Loops";

    // Undo the flip: the input cube, unsaved; save it.
    window.key("ctrl+z");
    ASSERT_TRUE(window.wait_title(" *", false, 20s, &title)) << title;
    window.key("ctrl+s");
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;
    EXPECT_TRUE(same_mesh(load(doc), input)) << "saved after undoing the flip";

    // Saved, so Ctrl+Q quits at once.
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

// A curve: every de Casteljau level (E) matches the headless golden of that level.
TEST_F(ViewerE2E, CurveLevels) {
    const fs::path doc = work_ / "curve6.bzc";
    fs::copy_file(source_dir() / "bez" / "curve6.bzc", doc);
    const BezierCurve curve = read_bzc(doc);
    const int width = 384;
    const int height = 288;
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    Camera camera;
    camera.frame_2d({0.0f, 0.0f}, {1.0f, 1.0f}, aspect);

    // The pointer rests on the paper corner farthest from every control point.
    glm::vec2 rest{0.0f};
    float rest_clearance = -1.0f;
    for (const Vec3& corner : {Vec3{0, 0, 0}, Vec3{1, 0, 0}, Vec3{1, 1, 0}, Vec3{0, 1, 0}}) {
        const glm::vec2 p = project(camera, aspect, corner, width, height);
        float clearance = 1e9f;
        for (const Vec3& c : curve.control_points) {
            clearance =
                std::min(clearance, glm::length(project(camera, aspect, c, width, height) - p));
        }
        if (clearance > rest_clearance) {
            rest_clearance = clearance;
            rest = p;
        }
    }
    ASSERT_GT(rest_clearance, 12.0f) << "every paper corner is within picking distance";

    auto viewer = start_viewer(doc, "384x288");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title("curve6.bzc — curve, 6 points", false, 20s, &title)) << title;
    // I hides the info panel, Space frames the whole window: the headless goldens' view.
    window.keys({"i", "space"});
    window.move_to(static_cast<int>(rest.x), static_cast<int>(rest.y));

    for (int k = 0; k <= 5; ++k) {
        const fs::path shot = screenshot(*viewer, window, static_cast<std::size_t>(k) + 1);
        ASSERT_FALSE(shot.empty());
        const std::string name = "curve6_level" + std::to_string(k);
        EXPECT_TRUE(images_match(shot, headless_golden_dir() / (name + ".png"), out_dir(),
                                 "viewer_" + name))
            << "level " << k;
        window.key("e");
    }
    // The last E went past the last level: refused, said on stderr; once more for luck.
    const std::string refusal = "already at the last level";
    ASSERT_TRUE(wait_until([&] { return count_of(viewer->err(), refusal) >= 1; }, 20s))
        << viewer->err();
    window.key("e");
    ASSERT_TRUE(wait_until([&] { return count_of(viewer->err(), refusal) >= 2; }, 20s))
        << viewer->err();
    EXPECT_TRUE(viewer->running());
    EXPECT_EQ(window.title(), "MeshEdit — curve6.bzc — curve, 6 points");

    // Nothing selected, nothing changed: Esc quits.
    window.key("Escape");
    expect_exit(*viewer, 0);
}

// A file that fails to open, through Ctrl+O and on the command line: an error, no crash.
TEST_F(ViewerE2E, BrokenFile) {
    const fs::path doc = work_ / "cube.dae";
    fs::copy_file(source_dir() / "dae" / "cube.dae", doc);
    const fs::path broken = work_ / "broken.dae";
    {
        std::ifstream in(doc, std::ios::binary);
        std::string text(700, '\0');
        in.read(text.data(), static_cast<std::streamsize>(text.size()));
        std::ofstream(broken, std::ios::binary) << text << "<<garbage";
    }

    {
        auto viewer = start_viewer(doc, "800x600");
        const ViewerWindow window(*viewer);
        ASSERT_TRUE(window.ok());
        std::string title;
        ASSERT_TRUE(window.wait_title(kCubeTitle, false, 20s, &title)) << title;
        window.move_to(780, 20);  // background: no hover highlight changes the picture

        ASSERT_NO_FATAL_FAILURE(open_through_prompt(window, broken));
        ASSERT_TRUE(wait_until(
            [&] { return viewer->err().find(broken.string()) != std::string::npos; }, 20s))
            << "no error naming " << broken << " on stderr:\n"
            << viewer->err();
        sleep_for(1s);
        EXPECT_TRUE(viewer->running()) << "the viewer died opening a broken file:\n"
                                       << viewer->err();
        EXPECT_EQ(window.title(), kCubeTitle) << "the cube must stay open";
        window.key("ctrl+q");
        expect_exit(*viewer, 0);
        EXPECT_NE(viewer->err().find("broken.dae"), std::string::npos) << viewer->err();
        EXPECT_NE(viewer->err().find("cube.dae stays open"), std::string::npos) << viewer->err();
    }

    // On the command line: the window opens with an empty document and the error.
    auto viewer = start_viewer(broken, "800x600");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    EXPECT_TRUE(window.wait_title("V 0 E 0 F 0", false, 20s, &title)) << title;
    ASSERT_TRUE(
        wait_until([&] { return viewer->err().find("broken.dae") != std::string::npos; }, 20s))
        << viewer->err();
    sleep_for(500ms);
    EXPECT_TRUE(viewer->running()) << viewer->err();
    // Nothing was open, so the message does not claim a document stays open.
    EXPECT_EQ(viewer->err().find("stays open"), std::string::npos) << viewer->err();
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

// Unsaved changes: the first Ctrl+Q is refused, the second quits without saving.
TEST_F(ViewerE2E, QuitProtection) {
    const fs::path original = source_dir() / "dae" / "cube.dae";
    const fs::path doc = work_ / "cube.dae";
    std::unique_ptr<BackgroundProcess> viewer;
    std::optional<ViewerWindow> opened;
    ASSERT_NO_FATAL_FAILURE(open_cube_and_flip(viewer, opened));
    const ViewerWindow& window = *opened;

    window.key("ctrl+q");
    ASSERT_TRUE(
        wait_until([&] { return viewer->err().find("unsaved changes") != std::string::npos; }, 20s))
        << "no refusal on stderr:\n"
        << viewer->err();
    sleep_for(300ms);
    EXPECT_TRUE(viewer->running()) << "quit with unsaved changes on the first Ctrl+Q";
    EXPECT_EQ(window.title(), kCubeTitle + " *");

    window.key("ctrl+q");
    expect_exit(*viewer, 0);
    EXPECT_TRUE(same_file_bytes(doc, original)) << "the file on disk changed";
    EXPECT_EQ(work_.entries(), std::vector<std::string>{"cube.dae"}) << "files left behind";
}

// The window as a person sees it: the render with the panels over it.
TEST_F(ViewerE2E, RealWindowShowsRenderAndPanels) {
    const fs::path doc = work_ / "cube.dae";
    fs::copy_file(source_dir() / "dae" / "cube.dae", doc);
    auto viewer = start_viewer(doc, "800x600");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title(kCubeTitle, false, 20s, &title)) << title;
    window.move_to(780, 20);  // background, away from the mesh: no hover highlight

    const fs::path png = logs_ / "window.png";
    RgbImage seen;
    const bool drawn = wait_until(
        [&] {
            if (!window.capture(png)) {
                return false;
            }
            seen = read_rgb(png);
            return seen.width == 800 && seen.height == 600 && distinct_colours(seen) >= 1000;
        },
        20s, 100ms);
    ASSERT_TRUE(drawn) << "the window shows " << seen.width << "x" << seen.height << " with "
                       << distinct_colours(seen) << " colours";
    // Compared with P (the part the panel leaves free, no panels): the same picture there.
    const int covered = info_panel_pixels(800);
    const fs::path shot = screenshot(*viewer, window, 1);
    ASSERT_FALSE(shot.empty());
    const RgbImage clean = read_rgb(shot);
    ASSERT_EQ(clean.width, 800 - covered);
    ASSERT_EQ(clean.height, 600);
    for (const auto& [x, y] : {std::pair{555, 300}, std::pair{700, 330}, std::pair{420, 250}}) {
        EXPECT_LE(channel_difference(seen, x, y, clean, x - covered, y), 8)
            << "the window at (" << x << ", " << y << ") differs from the screenshot";
    }
    // The model sits in the free part: its centre is not background, the panel's is.
    EXPECT_GT(channel_difference(seen, covered + (800 - covered) / 2, 300, seen, 795, 300), 30)
        << "the middle of the free part looks like the background";

    // I hides the panel: the top left brightens to the background it covered.
    const double panel_seen = mean_brightness(seen, 15, 40, 250, 120);
    window.key("i");
    const fs::path without = logs_ / "without_panel.png";
    double panel_hidden = panel_seen;
    ASSERT_TRUE(wait_until(
        [&] {
            if (!window.capture(without)) {
                return false;
            }
            panel_hidden = mean_brightness(read_rgb(without), 15, 40, 250, 120);
            return panel_hidden > panel_seen + 60.0;
        },
        20s, 100ms))
        << "no info panel in the window's top left (brightness " << panel_seen << " with it, "
        << panel_hidden << " without)";

    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

}  // namespace
}  // namespace meshedit::test::e2e
