/// \file
/// End-to-end tests of teaching mode: Loop stepped one phase per Alt+L in the real window
/// ends where one press of L does.

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

}  // namespace
}  // namespace meshedit::test::e2e
