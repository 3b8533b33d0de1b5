// The editor's files: a broken file leaves the document as it was, opening clears history
// and selection, saving refuses what a format cannot hold.

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

// ---------------------------------------------------------------------------------- files

TEST(Editor, BrokenFileLeavesTheDocumentUntouched) {
    TempDir dir;
    const fs::path good = dir / "cube.dae";
    write_mesh(shapes::cube(), good);
    Editor ed;
    ed.open(good);
    ed.select(ElementRef::edge(Edge(2)));
    ed.press(key_of('K'), 0);
    const Mesh before = ed.mesh();
    const std::uint64_t revision = ed.document().revision;

    const fs::path bad = dir / "broken.dae";
    std::ofstream(bad) << "<COLLADA><this is not xml";
    EXPECT_THROW(ed.open(bad), IoError);
    EXPECT_THROW(ed.open(dir / "missing.obj"), IoError);
    EXPECT_THROW(ed.open(dir / "file.xyz"), IoError);
    std::ofstream(dir / "bad.bzc") << "1\n0 0\n";
    EXPECT_THROW(ed.open(dir / "bad.bzc"), IoError);
    EXPECT_TRUE(test::identical(ed.mesh(), before));
    EXPECT_EQ(ed.path(), good);
    EXPECT_EQ(ed.document().revision, revision);
    EXPECT_EQ(ed.history().undo_steps(), 1u);
    EXPECT_TRUE(ed.dirty());
    EXPECT_EQ(ed.selection().kind, Kind::Edge);
}

TEST(Editor, OpenClearsHistoryAndSelection) {
    TempDir dir;
    write_mesh(shapes::icosahedron(), dir / "ico.obj");
    Editor ed = editor_with(shapes::cube());
    ed.select(ElementRef::edge(Edge(0)));
    ed.press(key_of('K'), 0);
    const Outcome out = ed.open(dir / "ico.obj");
    EXPECT_EQ(out.message, "opened ico.obj: V 12 E 30 F 20");
    EXPECT_TRUE(out.changes & kDocument);
    EXPECT_EQ(ed.history().undo_steps(), 0u);
    EXPECT_TRUE(ed.selection().is_none());
    EXPECT_FALSE(ed.dirty());
    EXPECT_FALSE(ed.quit_armed());
    EXPECT_EQ(ed.mode(), Mode::Mesh);
}

TEST(Editor, SaveRefusals) {
    Editor ed = editor_with(shapes::cube());
    EXPECT_EQ(ed.title(), "untitled — V 8 E 18 F 12");
    Outcome out = ed.save();
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message, "no file name: use Ctrl+Shift+S");
    EXPECT_TRUE(ed.save_as("/no/such/folder/x.obj").refused);
    EXPECT_TRUE(ed.path().empty()) << "a failed save as keeps the old path";
    out = ed.save_as("cube.bzc");
    EXPECT_TRUE(out.refused);
    EXPECT_NE(out.message.find(".obj"), std::string::npos) << out.message;
}

}  // namespace
}  // namespace meshedit::viewer
