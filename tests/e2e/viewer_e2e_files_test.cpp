/// \file
/// End-to-end tests of what a new user trips on first: opening another file over unsaved
/// work, and course models whose data is Z-up though they declare Y_UP.

#include "meshedit/core/shapes.h"
#include "meshedit/files/files.h"
#include "viewer_fixture.h"

namespace meshedit::test::e2e {
namespace {

// Ctrl+O over unsaved work is refused once with the reason; the edit stays and can still be
// undone; an open right after the refusal opens the other file, and the first is never
// written.
TEST_F(ViewerE2E, OpeningOverUnsavedWorkAsksFirst) {
    const fs::path original = source_dir() / "dae" / "cube.dae";
    const fs::path doc = work_ / "cube.dae";
    const fs::path other = work_ / "ico.dae";
    fs::copy_file(source_dir() / "dae" / "icosahedron.dae", other);
    std::unique_ptr<BackgroundProcess> viewer;
    std::optional<ViewerWindow> opened;
    ASSERT_NO_FATAL_FAILURE(open_cube_and_flip(viewer, opened));
    const ViewerWindow& window = *opened;
    std::string title;

    ASSERT_NO_FATAL_FAILURE(open_through_prompt(window, other));
    const std::string refusal = "unsaved changes to cube.dae: open again to discard them";
    ASSERT_TRUE(wait_until([&] { return count_of(viewer->err(), refusal) == 1; }, 20s))
        << "no refusal on stderr:\n"
        << viewer->err();
    sleep_for(300ms);
    EXPECT_EQ(window.title(), kCubeTitle + " *") << "the edited cube must stay open";

    // The edit is still there: undo takes it back, redo brings it again.
    window.key("ctrl+z");
    ASSERT_TRUE(window.wait_title(" *", true, 20s, &title)) << title;
    window.key("ctrl+y");
    ASSERT_TRUE(window.wait_title(" *", false, 20s, &title)) << title;

    // Changed since the question (the redo), so asked again; then a second open in a row
    // discards the edit.
    ASSERT_NO_FATAL_FAILURE(open_through_prompt(window, other));
    ASSERT_TRUE(wait_until([&] { return count_of(viewer->err(), refusal) == 2; }, 20s))
        << viewer->err();
    EXPECT_EQ(window.title(), kCubeTitle + " *");
    ASSERT_NO_FATAL_FAILURE(open_through_prompt(window, other));
    ASSERT_TRUE(window.wait_title("MeshEdit — ico.dae — V 12 E 30 F 20", false, 20s, &title))
        << title << "\n"
        << viewer->err();
    EXPECT_TRUE(same_file_bytes(doc, original)) << "the cube on disk changed";
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

/// The silhouette's bounding box in a screenshot: pixels that differ from the background
/// (the gradient is constant along a row, so the row's last pixel stands for it).
struct Extent {
    int width = 0;
    int height = 0;
};
Extent silhouette(const RgbImage& image) {
    int x0 = image.width, y0 = image.height, x1 = -1, y1 = -1;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width - 3; ++x) {
            if (channel_difference(image, x, y, image, image.width - 1, y) > 40) {
                x0 = std::min(x0, x);
                x1 = std::max(x1, x);
                y0 = std::min(y0, y);
                y1 = std::max(y1, y);
            }
        }
    }
    return x1 < 0 ? Extent{} : Extent{x1 - x0 + 1, y1 - y0 + 1};
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
