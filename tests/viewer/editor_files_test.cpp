// The editor's files: a broken file leaves the document as it was, opening clears history
// and selection, saving refuses what a format cannot hold.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
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
    EXPECT_TRUE(ed.open(bad).refused) << "unsaved changes: refused once before reading";
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

// Local edits leave tombstones; saving collects them first, as an undo step of its own and a
// `compact` in the session, so the file and the info panel number elements alike.
TEST(Editor, SavingCollectsTheTombstonesOfLocalEditsAsAnUndoStep) {
    TempDir dir;
    const Mesh ico = shapes::icosphere(1);
    Editor ed = editor_with(ico);
    ed.select(ElementRef::edge(Edge(17)));
    ASSERT_FALSE(ed.press(key_of('C'), 0).refused);
    ASSERT_TRUE(ed.mesh().has_garbage());
    const Mesh collapsed = ed.mesh();
    const Outcome out = ed.save_as(dir / "ico.obj");
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_FALSE(ed.mesh().has_garbage());
    EXPECT_FALSE(ed.dirty());
    EXPECT_EQ(ed.document().session.back(), "compact");
    EXPECT_EQ(ed.history().undo_steps(), 2u);
    Mesh compacted = collapsed;
    compacted.garbage_collection();
    EXPECT_TRUE(test::identical(ed.mesh(), compacted));
    EXPECT_TRUE(test::same_faces_by_position(read_mesh(dir / "ico.obj").mesh, compacted, 1e-6));
    ASSERT_FALSE(ed.run({Command::Undo}).refused);  // the renumbering
    EXPECT_TRUE(test::identical(ed.mesh(), collapsed));
    ASSERT_FALSE(ed.run({Command::Undo}).refused);  // the collapse
    EXPECT_TRUE(test::identical(ed.mesh(), ico));
}

TEST(Editor, OpenClearsHistoryAndSelection) {
    TempDir dir;
    write_mesh(shapes::icosahedron(), dir / "ico.obj");
    Editor ed = editor_with(shapes::cube());
    ed.select(ElementRef::edge(Edge(0)));
    ed.press(key_of('K'), 0);
    EXPECT_TRUE(ed.open(dir / "ico.obj").refused);
    const Outcome out = ed.open(dir / "ico.obj");
    EXPECT_EQ(out.message, "opened ico.obj: V 12 E 30 F 20");
    EXPECT_TRUE(out.changes & kDocument);
    EXPECT_EQ(ed.history().undo_steps(), 0u);
    EXPECT_TRUE(ed.selection().is_none());
    EXPECT_FALSE(ed.dirty());
    EXPECT_FALSE(ed.quit_armed());
    EXPECT_EQ(ed.mode(), Mode::Mesh);
}

// Opening over unsaved work is guarded as quitting is: refused once with the reason, nothing
// read and nothing lost (undo still works); the same open again goes through. Any other
// command in between, or another edit, disarms it.
TEST(Editor, OpenOverUnsavedChangesIsRefusedOnce) {
    TempDir dir;
    write_mesh(shapes::cube(), dir / "a.obj");
    write_mesh(shapes::icosahedron(), dir / "b.obj");
    Editor ed;
    ed.open(dir / "a.obj");
    ed.select(ElementRef::edge(Edge(3)));
    ASSERT_FALSE(ed.press(key_of('S'), 0).refused);
    const Mesh edited = ed.mesh();
    Outcome out = ed.open(dir / "b.obj");
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message,
              "unsaved changes to a.obj: open again to discard them, or Ctrl+S to save first");
    EXPECT_TRUE(test::identical(ed.mesh(), edited));
    EXPECT_EQ(ed.history().undo_steps(), 1u);
    // Another command in between disarms the guard.
    ed.press(key_of('W'), 0);
    EXPECT_TRUE(ed.open(dir / "b.obj").refused);
    out = ed.open(dir / "b.obj");
    EXPECT_FALSE(out.refused) << out.message;
    EXPECT_EQ(ed.mesh().n_faces(), 20u);
    // A clean document opens at once.
    EXPECT_FALSE(ed.open(dir / "a.obj").refused);
    // The Open chooser has said what is lost: its open goes through at the first try.
    ed.select(ElementRef::edge(Edge(3)));
    ASSERT_FALSE(ed.press(key_of('S'), 0).refused);
    out = ed.open(dir / "b.obj", true);
    EXPECT_FALSE(out.refused) << out.message;
    EXPECT_EQ(ed.mesh().n_faces(), 20u);
    EXPECT_FALSE(ed.dirty());
}

// A format that cannot hold the document is named before anything is lost: Ctrl+S to OBJ
// with creases is refused once with what would go, and the next Ctrl+S saves and says it.
TEST(Editor, SavingToAFormatThatLosesSomethingAsksOnce) {
    TempDir dir;
    Editor ed = editor_with(shapes::cube());
    ed.select(ElementRef::edge(Edge(0)));
    ed.press(key_of('K'), 0);
    Outcome out = ed.save_as(dir / "c.obj");
    EXPECT_TRUE(out.refused);
    EXPECT_EQ(out.message,
              "saving as .obj loses 1 crease mark (OBJ has no crease edges): save again to save "
              "anyway, or save as .dae to keep everything");
    EXPECT_FALSE(fs::exists(dir / "c.obj"));
    out = ed.save_as(dir / "c.obj");
    EXPECT_FALSE(out.refused) << out.message;
    EXPECT_EQ(out.message, "saved c.obj (not kept: 1 crease mark (OBJ has no crease edges))");
    EXPECT_FALSE(ed.dirty());
    // COLLADA keeps creases: no question.
    EXPECT_FALSE(ed.save_as(dir / "c.dae").refused);
    // glTF stores triangles and floats.
    Editor quads = editor_with(shapes::quad_sphere(1));
    out = quads.save_as(dir / "q.glb");
    EXPECT_TRUE(out.refused);
    EXPECT_NE(out.message.find("polygons (glTF stores triangles: each is fanned)"),
              std::string::npos)
        << out.message;
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

// Each file opens with its own up axis (issue 40): a tower standing along Z gets a hint, Y
// stands it up and is remembered for that file's content; the next file (a cube) opens +Y
// as declared; the tower opens standing again; Y back forgets it.
TEST(Editor, UpAxisIsPerFileAndRemembered) {
    TempDir dir;
    const char* old_config = std::getenv("XDG_CONFIG_HOME");
    const std::string saved = old_config != nullptr ? old_config : "";
    ::setenv("XDG_CONFIG_HOME", (dir / "config").c_str(), 1);
    const fs::path tower = dir / "tower.obj";
    std::ofstream(tower) << "v 0 0 0\nv 1 0 0\nv 1 0.2 0\nv 0 0 3\nf 1 2 3\nf 1 3 4\n";
    const fs::path cube = dir / "cube.obj";
    std::ofstream(cube) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\n"
                           "f 2 3 4\n";
    Editor ed;
    Outcome out = ed.open(tower);
    EXPECT_NE(out.message.find("it stands along Z, not up: if it lies on its side, Y stands it up"),
              std::string::npos)
        << out.message;
    EXPECT_EQ(ed.view().up, UpAxis::Y);
    ed.press(key_of('Y'), 0);
    EXPECT_EQ(ed.view().up, UpAxis::Z);
    out = ed.open(cube);
    EXPECT_EQ(ed.view().up, UpAxis::Y) << "the tower's choice carried over";
    EXPECT_EQ(out.message.find("stands along Z"), std::string::npos) << out.message;
    out = ed.open(tower);
    EXPECT_EQ(ed.view().up, UpAxis::Z) << "the tower's choice was forgotten";
    EXPECT_EQ(out.message.find("stands along Z"), std::string::npos) << out.message;
    ed.press(key_of('Y'), 0);
    ed.open(cube);
    ed.open(tower);
    EXPECT_EQ(ed.view().up, UpAxis::Y);
    if (saved.empty()) {
        ::unsetenv("XDG_CONFIG_HOME");
    } else {
        ::setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
    }
}

}  // namespace
// A file whose faces share no vertices (a soup, or Blender's PLY split at every seam) opens
// with a hint naming the repair (issue 40's new-user pass: Wuson.ply looked whole but was
// 3,732 parts); Alt+Shift+R merges it into one closed part; a closed file gets no hint.
TEST(Editor, UnweldedFileHintsAtRepair) {
    TempDir dir;
    const fs::path soup = dir / "soup.obj";
    std::ofstream(soup) << "v 0 0 0\nv 0 1 0\nv 1 0 0\nv 0 0 0\nv 1 0 0\nv 0 0 1\n"
                           "v 0 0 0\nv 0 0 1\nv 0 1 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
                           "f 1 2 3\nf 4 5 6\nf 7 8 9\nf 10 11 12\n";
    Editor ed;
    Outcome out = ed.open(soup);
    EXPECT_NE(
        out.message.find("12 of its 12 edges are borders: if its faces should join, "
                         "Alt+Shift+R repairs it (merges vertices by distance, orients faces)"),
        std::string::npos)
        << out.message;
    ed.press(key_of('R'), kAlt | kShift);
    EXPECT_EQ(ed.document().mesh.n_vertices(), 4u);
    EXPECT_EQ(ed.document().mesh.n_edges(), 6u);
    EXPECT_VALID(ed.document().mesh);
    const fs::path closed = dir / "closed.obj";
    std::ofstream(closed) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\n"
                             "f 1 4 3\nf 2 3 4\n";
    EXPECT_TRUE(ed.open(closed).refused) << "the repaired soup is unsaved";
    out = ed.open(closed);
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(out.message.find("borders"), std::string::npos) << out.message;
}

}  // namespace meshedit::viewer
