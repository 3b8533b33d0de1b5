/// \file
/// End-to-end tests of `--student`: a seeded-bug library's F shows the side by side with the
/// differing element framed; a crashing library leaves the viewer running.

#include "viewer_fixture.h"

namespace meshedit::test::e2e {
namespace {

fs::path student_library(const std::string& name) {
    return fs::path(MESHEDIT_BUILD_DIR) / "tests" / "student" / "libs" / (name + ".so");
}

// Pixels of the side by side's frames (magenta: red and blue high, green low) in the left
// and the right half of `image`.
std::pair<int, int> frame_pixels(const RgbImage& image) {
    int left = 0, right = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.at(x, y);
            if (p[0] > 180 && p[2] > 180 && p[1] < 90) {
                (x < image.width / 2 ? left : right) += 1;
            }
        }
    }
    return {left, right};
}

class StudentE2E : public ViewerE2E {
protected:
    // The cube under `lib`, its chosen edge clicked; F not pressed yet.
    void open_cube(const std::string& lib) {
        const fs::path doc = work_ / "cube.dae";
        fs::copy_file(source_dir() / "dae" / "cube.dae", doc);
        std::string candidates;
        target_ = flip_target(load(doc), 800, 600, candidates);
        ASSERT_TRUE(target_) << candidates;
        ASSERT_TRUE(fs::exists(student_library(lib))) << student_library(lib);
        viewer_ = start_viewer(doc, "800x600", {"--student", student_library(lib).string()});
        window_.emplace(*viewer_);
        ASSERT_TRUE(window_->ok());
        std::string title;
        ASSERT_TRUE(window_->wait_title(kCubeTitle, false, 20s, &title)) << title << "\n"
                                                                         << viewer_->err();
        window_->click(target_->x, target_->y);
    }

    // The title is the cube's as opened, no '*'; Ctrl+Q then quits at once with status 0.
    void expect_cube_unchanged_and_quit() {
        std::string title;
        EXPECT_TRUE(window_->wait_title(kCubeTitle, false, 20s, &title)) << title;
        EXPECT_EQ(title.find('*'), std::string::npos) << title;
        window_->key("ctrl+q");
        expect_exit(*viewer_, 0);
    }

    std::optional<EdgeTarget> target_;
    std::unique_ptr<BackgroundProcess> viewer_;
    std::optional<ViewerWindow> window_;
};

// F on a known edge with a flip that leaves a face's halfedge outside its loop: both results
// side by side (the title counts both cubes), a magenta frame around the first differing
// element in each half, none before; Esc steps back to the cube.
TEST_F(StudentE2E, SeededFlipBugShowsTheSideBySideFramed) {
    ASSERT_NO_FATAL_FAILURE(open_cube("bug_flip_face_anchor"));
    const fs::path before = screenshot(*viewer_, *window_, 1);
    ASSERT_FALSE(before.empty());
    const auto [left0, right0] = frame_pixels(read_rgb(before));
    EXPECT_EQ(left0 + right0, 0) << "magenta before any F: " << before;

    window_->key("f");
    std::string title;
    ASSERT_TRUE(window_->wait_title("V 16 E 36 F 24 *", false, 20s, &title)) << title << "\n"
                                                                             << viewer_->err();
    const fs::path shot = screenshot(*viewer_, *window_, 2);
    ASSERT_FALSE(shot.empty());
    fs::copy_file(shot, out_dir() / "student_side_by_side.png",
                  fs::copy_options::overwrite_existing);
    // The whole window too (panels, status line, labels), for a reader of a failure.
    EXPECT_TRUE(window_->capture(out_dir() / "student_side_by_side_window.png"));
    const RgbImage image = read_rgb(shot);
    EXPECT_TRUE(looks_rendered(shot, image.width, image.height));
    const auto [left, right] = frame_pixels(image);
    // A box is a dozen lines 3 pixels wide; the captions and the label are a few hundred.
    EXPECT_GT(left, 400) << shot;
    EXPECT_GT(right, 400) << shot;

    window_->key("Escape");
    expect_cube_unchanged_and_quit();
}

// A student flip that dereferences a null pointer: the viewer says so, naming the function
// and the edge, keeps the cube as it was (no '*' in the title), and goes on answering: a
// screenshot, then Ctrl+Q quits cleanly.
TEST_F(StudentE2E, CrashingStudentCodeLeavesTheViewerRunning) {
    ASSERT_NO_FATAL_FAILURE(open_cube("bug_flip_crash"));
    window_->key("f");
    ASSERT_TRUE(
        wait_until([&] { return viewer_->err().find("crashed") != std::string::npos; }, 20s))
        << viewer_->err();
    const std::string err = viewer_->err();
    EXPECT_NE(err.find("flip_edge on edge"), std::string::npos) << err;
    EXPECT_NE(err.find("nothing changed"), std::string::npos) << err;
    EXPECT_TRUE(viewer_->running());
    EXPECT_TRUE(window_->capture(out_dir() / "student_crash_window.png"));
    const fs::path shot = screenshot(*viewer_, *window_, 1);
    ASSERT_FALSE(shot.empty());
    EXPECT_TRUE(looks_rendered(shot, read_rgb(shot).width, read_rgb(shot).height));
    expect_cube_unchanged_and_quit();
}

// A library whose initialiser crashes is not loaded; the viewer starts and F flips with
// MeshEdit's own operation.
TEST_F(StudentE2E, LibraryCrashingOnLoadLeavesTheViewerRunning) {
    ASSERT_NO_FATAL_FAILURE(open_cube("crash_on_load"));
    EXPECT_NE(viewer_->err().find("not loaded: loading it crashed"), std::string::npos)
        << viewer_->err();
    window_->key("f");
    std::string title;
    EXPECT_TRUE(window_->wait_title(kCubeTitle + " *", false, 20s, &title)) << title << "\n"
                                                                            << viewer_->err();
    window_->keys({"ctrl+q", "ctrl+q"});
    expect_exit(*viewer_, 0);
}

}  // namespace
}  // namespace meshedit::test::e2e
