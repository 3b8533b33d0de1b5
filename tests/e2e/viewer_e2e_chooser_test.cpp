/// \file
/// End-to-end test of the file chooser (issue 40, item 2) on a document big enough that
/// frames are slow under Xvfb: an absolute path typed over the suggested name, a relative
/// path after Ctrl+A, and a name with five Backspaces sent within one frame — each saved
/// where it was typed, no other file written. Once, Backspaces pressed faster than frames
/// counted once a frame and a file was saved as "bunny_l2.ofbunny_300k.off".

#include "meshedit/core/shapes.h"
#include "viewer_fixture.h"

namespace meshedit::test::e2e {
namespace {

constexpr int kWidth = 1000;
constexpr int kHeight = 700;

std::vector<std::string> names_in(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder)) {
        names.push_back(entry.path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

using ChooserE2E = ViewerE2E;

TEST_F(ChooserE2E, TypedPathsSaveWhereTypedOnASlowDocument) {
    const Mesh torus = shapes::torus(512, 320);  // 327,680 triangles
    const fs::path docs = work_ / "docs";
    const fs::path abs = work_ / "abs";
    fs::create_directories(docs);
    fs::create_directories(abs / "rel");
    const fs::path doc = docs / "torus.ply";
    write_mesh(torus, doc);

    auto viewer = start_viewer(doc, std::to_string(kWidth) + "x" + std::to_string(kHeight));
    const ViewerWindow window(*viewer);
    ASSERT_TRUE(window.ok());
    std::string title;
    ASSERT_TRUE(window.wait_title("F 327680", false, 60s, &title)) << title << viewer->err();

    // An absolute path typed straight away replaces the suggested name ("torus.ply",
    // selected), never lands after the folder.
    ASSERT_NO_FATAL_FAILURE(show_chooser(window, "ctrl+shift+s"));
    window.type((abs / "one.ply").string());
    window.key("Return");
    ASSERT_TRUE(window.wait_title("one.ply", false, 30s, &title)) << title << viewer->err();

    // A relative path after Ctrl+A: relative to the listed folder, the document's (abs).
    ASSERT_NO_FATAL_FAILURE(show_chooser(window, "ctrl+shift+s"));
    window.key("ctrl+a");
    window.type("rel/two.ply");
    window.key("Return");
    ASSERT_TRUE(window.wait_title("two.ply", false, 30s, &title)) << title << viewer->err();

    // Five Backspaces a millisecond apart, within one frame of the slow document: each one
    // counts.
    ASSERT_NO_FATAL_FAILURE(show_chooser(window, "ctrl+shift+s"));
    window.type("threeXXXXX");
    window.keys({"BackSpace", "BackSpace", "BackSpace", "BackSpace", "BackSpace"}, 1);
    window.type(".ply");
    sleep_for(1500ms);
    ASSERT_TRUE(window.capture(out_dir() / "chooser_backspaces.png"));  // looked at
    window.key("Return");
    ASSERT_TRUE(window.wait_title("three.ply", false, 30s, &title))
        << title << "\n"
        << viewer->err() << "\nfiles in rel: " << testing::PrintToString(names_in(abs / "rel"));

    EXPECT_EQ(names_in(abs), (std::vector<std::string>{"one.ply", "rel"}));
    EXPECT_EQ(names_in(abs / "rel"), (std::vector<std::string>{"three.ply", "two.ply"}));
    EXPECT_EQ(names_in(docs), std::vector<std::string>{"torus.ply"});
    EXPECT_TRUE(same_mesh(load(abs / "rel" / "three.ply"), load(doc)));
    window.key("ctrl+q");
    expect_exit(*viewer, 0);
}

}  // namespace
}  // namespace meshedit::test::e2e
