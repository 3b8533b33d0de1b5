/// \file
/// End-to-end tests of what a new user trips on first: opening another file over unsaved
/// work, and course models whose data is Z-up though they declare Y_UP.

#include "meshedit/core/shapes.h"
#include "meshedit/files/files.h"
#include "view_pixels.h"
#include "viewer_fixture.h"

namespace meshedit::test::e2e {
namespace {

// Ctrl+O over unsaved work: the chooser says, above its buttons, that Open discards the
// changes (orange text under the help line); Cancel keeps the edit, which can still be undone
// and redone; Open at the first try then opens the other file (a second Ctrl+O with the path
// typed again, as the old refusal asked, was where a new user gave up), and the first is
// never written.
TEST_F(ViewerE2E, OpeningOverUnsavedWorkSaysWhatItDiscards) {
    const fs::path original = source_dir() / "dae" / "cube.dae";
    const fs::path doc = work_ / "cube.dae";
    const fs::path other = work_ / "ico.dae";
    fs::copy_file(source_dir() / "dae" / "icosahedron.dae", other);
    std::unique_ptr<BackgroundProcess> viewer;
    std::optional<ViewerWindow> opened;
    ASSERT_NO_FATAL_FAILURE(open_cube_and_flip(viewer, opened));
    const ViewerWindow& window = *opened;
    std::string title;

    ASSERT_NO_FATAL_FAILURE(show_chooser(window, "ctrl+o"));
    sleep_for(300ms);
    const fs::path shot = logs_ / "open_warning.png";
    ASSERT_TRUE(window.capture(shot));
    const RgbImage shown = read_rgb(shot);
    std::size_t orange = 0;  // the warning's (1, 0.7, 0.3) text
    for (int y = 0; y < shown.height; ++y) {
        for (int x = 0; x < shown.width; ++x) {
            const std::uint8_t* p = shown.at(x, y);
            orange += p[0] > 200 && p[1] > 120 && p[1] < 200 && p[2] < 110 ? 1 : 0;
        }
    }
    EXPECT_GT(orange, 100u) << "no warning in the chooser";
    window.key("Escape");
    sleep_for(300ms);
    EXPECT_EQ(window.title(), kCubeTitle + " *") << "the edited cube must stay open";

    // The edit is still there: undo takes it back, redo brings it again.
    window.key("ctrl+z");
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;
    window.key("ctrl+y");
    ASSERT_TRUE(window.wait_title(" *", false, 20s, &title)) << title;

    ASSERT_NO_FATAL_FAILURE(open_through_prompt(window, other));
    ASSERT_TRUE(window.wait_title("MeshEdit — ico.dae — V 12 E 30 F 20", false, 20s, &title))
        << title << "\n"
        << viewer->err();
    EXPECT_TRUE(same_file_bytes(doc, original)) << "the cube on disk changed";
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

// A session, recorded as a person works: click an edge, F, S, L, undo, E (the new vertex's
// edge), C; Ctrl+S saves, Ctrl+Shift+E exports the session, and `meshedit convert` replays it
// from the original file to the same bytes as the saved one.
TEST_F(ViewerE2E, ExportedSessionReplaysToTheSavedFile) {
    const fs::path original = source_dir() / "dae" / "cube.dae";
    const fs::path doc = work_ / "cube.dae";
    std::unique_ptr<BackgroundProcess> viewer;
    std::optional<ViewerWindow> opened;
    ASSERT_NO_FATAL_FAILURE(open_cube_and_flip(viewer, opened));
    const ViewerWindow& window = *opened;
    std::string title;
    window.key("s");  // splits the flipped edge, which stays selected
    ASSERT_TRUE(window.wait_title("V 9 E 21 F 14 *", false, 20s, &title)) << title;
    window.key("l");
    ASSERT_TRUE(window.wait_title("V 30 E 84 F 56 *", false, 60s, &title)) << title;
    window.key("ctrl+z");
    ASSERT_TRUE(window.wait_title("V 9 E 21 F 14 *", false, 20s, &title)) << title;
    window.keys({"e", "c"});  // the new vertex's edge, collapsed
    ASSERT_TRUE(window.wait_title("V 8 E 18 F 12 *", false, 20s, &title)) << title << "\n"
                                                                          << viewer->err();
    window.key("ctrl+s");
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;

    // The prompt suggests the document's name with .ops: Return alone takes it (typing over
    // it raced the text field's focus on a loaded machine).
    const fs::path session = work_ / "cube.ops";
    ASSERT_NO_FATAL_FAILURE(answer_prompt(window, "ctrl+shift+e", std::nullopt));
    ASSERT_TRUE(wait_until([&] { return fs::exists(session); }, 20s)) << viewer->err();
    const std::string text = read_file(session);
    std::cout << "session:\n" << text;
    EXPECT_EQ(count_of(text, "\nloop"), 0u) << "the undone Loop is not in the session";
    EXPECT_NE(text.find("# input-fnv1a64: " + content_hash(read_file(original))),
              std::string::npos);

    const fs::path replayed = work_ / "replayed.dae";
    const RunResult convert = run_meshedit(
        {"convert", original.string(), replayed.string(), "--ops", "@" + session.string()});
    ASSERT_EQ(convert.exit_code, 0) << convert.err;
    EXPECT_EQ(convert.err.find("another file"), std::string::npos) << convert.err;
    EXPECT_TRUE(same_file_bytes(replayed, doc)) << "the replay differs from the saved file";
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

// A tower whose data stands along +Z but whose file says Y_UP (as the CS184 course's models
// do) opens lying down; Y makes +Z up and it stands; Y again lays it down.
TEST_F(ViewerE2E, UpAxisKeyStandsAZUpModelUp) {
    Mesh tower = shapes::cube();  // [-1, 1]³ stretched to 2 × 2 × 8 along z
    for (Vertex v : tower.vertices()) {
        tower.position(v).z *= 4.0;
    }
    const fs::path doc = work_ / "tower.dae";
    write_mesh(tower, doc);
    ASSERT_NE(read_file(doc).find("<up_axis>Y_UP</up_axis>"), std::string::npos);

    auto viewer = start_viewer(doc, "800x600");
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title("tower.dae", false, 20s, &title)) << title;
    window.move_to(795, 5);  // background: no hover highlight

    const Extent lying = silhouette(read_rgb(screenshot(*viewer, window, 1)));
    window.key("y");
    sleep_for(500ms);
    const Extent standing = silhouette(read_rgb(screenshot(*viewer, window, 2)));
    window.key("y");
    sleep_for(500ms);
    const Extent again = silhouette(read_rgb(screenshot(*viewer, window, 3)));

    // Lying (+Y up): the 8-long z axis runs across the screen, foreshortened by the 30°
    // azimuth; standing (+Z up): it runs up the screen.
    EXPECT_GT(lying.width, lying.height) << lying.width << " × " << lying.height;
    EXPECT_GT(standing.height, 2 * standing.width) << standing.width << " × " << standing.height;
    EXPECT_EQ(again.width, lying.width);
    EXPECT_EQ(again.height, lying.height);
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

}  // namespace
}  // namespace meshedit::test::e2e
