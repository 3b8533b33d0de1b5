/// \file
/// End-to-end tests of teaching mode: Loop stepped one phase per Alt+L in the real window
/// ends where one press of L does.

#include "meshedit/core/fields.h"
#include "meshedit/files/files.h"
#include "support/mesh_compare.h"
#include "viewer_fixture.h"

namespace meshedit::test::e2e {
namespace {

// Four presses of Alt+L on the cube, saved: the same vertices at the same positions bit for
// bit, and the same triangles, as `meshedit convert --ops loop` (L's code). The split of
// phase 2 shows in the title's counts; phases 3 and 4 keep them, and Ctrl+S, handled after
// them, writes their result.
TEST_F(ViewerE2E, LoopSteppedFourTimesIsL) {
    const fs::path original = source_dir() / "dae" / "cube.dae";
    const fs::path doc = work_ / "cube.dae";
    fs::copy_file(original, doc);
    const fs::path expected_file = logs_ / "expected.dae";
    const RunResult convert =
        run_meshedit({"convert", original.string(), expected_file.string(), "--ops", "loop"});
    ASSERT_EQ(convert.exit_code, 0) << convert.err;
    const Mesh expected = load(expected_file);

    auto viewer = start_viewer(doc, "800x600");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title(kCubeTitle, false, 20s, &title)) << title;
    window.key("alt+l");  // 1: positions computed, nothing moved
    ASSERT_TRUE(window.wait_title(kCubeTitle + " *", false, 20s, &title)) << title;
    window.key("alt+l");  // 2: every edge split
    ASSERT_TRUE(window.wait_title("V 26 E 72 F 48 *", false, 20s, &title)) << title;
    window.keys({"alt+l", "alt+l", "ctrl+s"});  // 3: flips, 4: moves
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title << "\n" << viewer->err();

    const Mesh stepped = load(doc);
    ASSERT_EQ(stepped.n_vertices(), expected.n_vertices());
    for (Vertex v : expected.vertices()) {
        EXPECT_EQ(stepped.position(v), expected.position(v)) << "vertex " << v.idx();
    }
    EXPECT_EQ(canonical_faces(stepped), canonical_faces(expected));
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

// Pixels that differ by more than 40 in some channel.
std::size_t changed_pixels(const RgbImage& a, const RgbImage& b) {
    std::size_t n = 0;
    for (int y = 0; y < std::min(a.height, b.height); ++y) {
        for (int x = 0; x < std::min(a.width, b.width); ++x) {
            n += channel_difference(a, x, y, b, x, y) > 40;
        }
    }
    return n;
}

// Pixels whose red and blue differ by more than 40: tinted towards one end of the diverging
// map (the grey teapot, the grey-blue background and the grey panels are not).
std::size_t saturated_pixels(const RgbImage& image) {
    std::size_t n = 0;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const std::uint8_t* p = image.at(x, y);
            n += std::abs(int(p[0]) - int(p[2])) > 40;
        }
    }
    return n;
}

// Alt+F colours the teapot by Gaussian curvature (red knob and rims, blue saddles);
// Alt+Shift+F switches its colour map; stepping through every field comes back to the plain
// teapot, pixel for pixel in red and blue; 7 turns it into a mirror.
TEST_F(ViewerE2E, AltFColoursByCurvatureAndCyclesBackToPlain) {
    const fs::path doc = work_ / "teapot.dae";
    fs::copy_file(source_dir() / "dae" / "teapot.dae", doc);
    auto viewer = start_viewer(doc, "800x600");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title("teapot.dae", false, 20s, &title)) << title;
    const fs::path plain = screenshot(*viewer, window, 1);
    window.key("alt+f");
    const fs::path gauss = screenshot(*viewer, window, 2);
    window.key("alt+shift+f");  // the colour map: viridis instead of the diverging default
    const fs::path viridis = screenshot(*viewer, window, 3);
    window.keys({"alt+shift+f", "alt+shift+f", "alt+shift+f"});  // magma, diverging, default
    std::vector<std::string> rest(field_infos().size(), "alt+f");
    window.keys(rest);  // the other fields, then off
    const fs::path off = screenshot(*viewer, window, 4);
    window.key("7");  // the mirror
    const fs::path mirror = screenshot(*viewer, window, 5);
    ASSERT_FALSE(plain.empty() || gauss.empty() || viridis.empty() || off.empty() ||
                 mirror.empty());
    EXPECT_GT(changed_pixels(read_rgb(gauss), read_rgb(viridis)), 5000u) << "another colour map";
    EXPECT_GT(changed_pixels(read_rgb(off), read_rgb(mirror)), 5000u) << "mode 7 reflects";
    // The plain teapot's red: its open rims (boundary edges).
    const std::size_t rims = saturated_pixels(read_rgb(plain));
    const std::size_t coloured = saturated_pixels(read_rgb(gauss));
    std::cout << "saturated pixels: plain " << rims << ", gauss " << coloured << "\n";
    EXPECT_GT(coloured, 2 * rims + 300);
    EXPECT_EQ(saturated_pixels(read_rgb(off)), rims);
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

// Mode 8 from a shader folder; a broken edit and Ctrl+R: the error names the file and line on
// stderr and the picture stays; a working edit and Ctrl+R: the new picture.
TEST_F(ViewerE2E, CtrlRReloadsUserShadersAndKeepsTheOldOneOnAnError) {
    const fs::path doc = work_ / "cube.dae";
    fs::copy_file(source_dir() / "dae" / "cube.dae", doc);
    const fs::path shaders = work_ / "shaders";
    fs::create_directories(shaders);
    const std::string starter = read_file(source_dir() / "shaders/user/mesh8.frag");
    write_file(shaders / "mesh8.frag", starter);
    auto viewer = start_viewer(doc, "800x600", {"--shader-dir", shaders.string()});
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title(kCubeTitle, false, 20s, &title)) << title;
    window.key("8");
    const fs::path toon = screenshot(*viewer, window, 1);

    std::string broken = starter;
    broken.insert(broken.find("float band = ") + 13, "oops");
    write_file(shaders / "mesh8.frag", broken);
    window.key("ctrl+r");
    ASSERT_TRUE(wait_until(
        [&] { return viewer->err().find("does not compile") != std::string::npos; }, 20s))
        << viewer->err();
    EXPECT_NE(viewer->err().find((shaders / "mesh8.frag").string() + " does not compile: line 36"),
              std::string::npos)
        << viewer->err();
    const fs::path kept = screenshot(*viewer, window, 2);

    std::string red = starter;
    red.replace(red.find("vec3 color = u_base_color * band"), 32,
                "vec3 color = vec3(0.9, 0.1, 0.1) * band");
    write_file(shaders / "mesh8.frag", red);
    window.key("ctrl+r");
    const fs::path recompiled = screenshot(*viewer, window, 3);
    ASSERT_FALSE(toon.empty() || kept.empty() || recompiled.empty());
    EXPECT_EQ(changed_pixels(read_rgb(toon), read_rgb(kept)), 0u) << "the old shader stays";
    EXPECT_GT(changed_pixels(read_rgb(toon), read_rgb(recompiled)), 5000u) << "the red one draws";
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

}  // namespace
}  // namespace meshedit::test::e2e
