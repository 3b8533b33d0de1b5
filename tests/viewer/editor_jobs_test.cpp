// Whole-mesh operations in the background (issue 40): the same result and undo step as in
// place, a cancel that leaves the document bit for bit, and a document closed to edits while
// the worker runs.

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "meshedit/core/shapes.h"
#include "meshedit/io/io.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"
#include "viewer/editor_test_util.h"

namespace meshedit::viewer {
namespace {

Editor background_editor(Mesh mesh) {
    Editor ed = editor_with(std::move(mesh));
    ed.set_background(true);
    return ed;
}

// Each whole-mesh key gives, through the worker, exactly what it gives in place: mesh,
// message, session steps (the `compact` after it included), one undo step.
TEST(EditorJobs, BackgroundEqualsInPlace) {
    struct Case {
        Mesh mesh;
        Key key;
        unsigned mods;
    };
    const Case cases[] = {{shapes::icosphere(4), key_of('D'), kNoMods},
                          {shapes::icosphere(3), key_of('L'), kNoMods},
                          {test::quad_cube(), key_of('C'), kShift},
                          {shapes::icosphere(3), key_of('R'), kShift}};
    for (const Case& c : cases) {
        Editor here = editor_with(c.mesh);
        const Outcome in_place = here.press(c.key, c.mods);
        ASSERT_FALSE(in_place.refused) << in_place.message;

        Editor ed = background_editor(c.mesh);
        const Outcome started = ed.press(c.key, c.mods);
        ASSERT_FALSE(started.refused) << started.message;
        EXPECT_NE(started.changes & kJobStarted, 0u);
        EXPECT_TRUE(ed.busy());
        EXPECT_TRUE(test::identical(ed.mesh(), c.mesh)) << "the document waits for the result";
        const std::optional<Outcome> done = ed.wait_job();
        ASSERT_TRUE(done.has_value());
        EXPECT_FALSE(ed.busy());
        EXPECT_FALSE(done->refused) << done->message;
        EXPECT_EQ(done->message, in_place.message);
        EXPECT_EQ(done->changes, in_place.changes);
        EXPECT_EQ(ed.document().session, here.document().session);
        EXPECT_TRUE(test::identical(ed.mesh(), here.mesh())) << in_place.message;
        EXPECT_FALSE(validate(ed.mesh()).has_value());
        EXPECT_TRUE(ed.dirty());
        ed.run({Command::Undo});
        EXPECT_TRUE(test::identical(ed.mesh(), c.mesh));
        EXPECT_FALSE(ed.dirty());
        ed.run({Command::Redo});
        EXPECT_TRUE(test::identical(ed.mesh(), here.mesh()));
    }
}

// Esc stops the operation at its next progress report; nothing changed: the mesh bit for
// bit, no undo step, not dirty, the session as it was.
TEST(EditorJobs, EscCancelsAndLeavesTheDocument) {
    const Mesh ball = shapes::icosphere(6);  // 81,920 triangles: simplify reports 10 times
    Editor ed = background_editor(ball);
    ed.select(ElementRef{ElementRef::Kind::Vertex, 7});
    ASSERT_NE(ed.press(key_of('D'), kNoMods).changes & kJobStarted, 0u);
    const Outcome esc = ed.run({Command::Escape});
    EXPECT_FALSE(esc.refused);
    EXPECT_NE(esc.message.find("cancelling simplify"), std::string::npos) << esc.message;
    const std::optional<Outcome> done = ed.wait_job();
    ASSERT_TRUE(done.has_value());
    EXPECT_EQ(done->message, "simplify cancelled: nothing changed");
    std::string why;
    EXPECT_TRUE(bitwise_equal(ed.mesh(), ball, &why)) << why;
    EXPECT_FALSE(ed.dirty());
    EXPECT_EQ(ed.history().undo_steps(), 0u);
    EXPECT_TRUE(ed.document().session.empty());
    EXPECT_EQ(ed.selection(), (ElementRef{ElementRef::Kind::Vertex, 7}));
    // Nothing is left running: the next D runs to the end.
    ASSERT_NE(ed.press(key_of('D'), kNoMods).changes & kJobStarted, 0u);
    const std::optional<Outcome> second = ed.wait_job();
    ASSERT_TRUE(second.has_value());
    EXPECT_EQ(ed.mesh().n_faces(), ball.n_faces() / 2) << second->message;
}

// While the worker runs, the document takes no edit, selection, undo or file command (each
// refused with the reason); what only changes the view runs.
TEST(EditorJobs, BusyDocumentRefusesEditsButNotTheView) {
    const Mesh ball = shapes::icosphere(5);
    Editor ed = background_editor(ball);
    ed.run({Command::SelectAll});
    ed.run({Command::SelectNone});
    ASSERT_NE(ed.press(key_of('L'), kNoMods).changes & kJobStarted, 0u);
    const std::string why = "loop is running: wait for it, or press Esc to cancel it";
    for (const Action a :
         {edit("flip"), Action{Command::Undo}, Action{Command::Redo}, Action{Command::SelectAll},
          Action{Command::Save}, Action{Command::Open}, edit("simplify")}) {
        const Outcome out = ed.run(a);
        EXPECT_TRUE(out.refused) << static_cast<int>(a.command);
        EXPECT_EQ(out.message, why);
    }
    EXPECT_TRUE(ed.select(ElementRef{ElementRef::Kind::Face, 3}).refused);
    EXPECT_TRUE(ed.select_elements({ElementRef{ElementRef::Kind::Face, 3}}, false, "box").refused);
    EXPECT_FALSE(ed.begin_drag());
    EXPECT_TRUE(ed.save_as("/nonexistent/x.obj").refused);
    EXPECT_TRUE(ed.selection().is_none());

    const bool help = ed.view().show_help;
    EXPECT_FALSE(ed.run({Command::ToggleHelp}).refused);
    EXPECT_NE(ed.view().show_help, help);
    EXPECT_FALSE(ed.run({Command::ToggleWireframe}).refused);

    ASSERT_TRUE(ed.wait_job().has_value());
    EXPECT_EQ(ed.mesh().n_faces(), 4 * ball.n_faces());
    EXPECT_FALSE(ed.run(edit("flip")).message.empty());  // runs (or says why) again
}

// Quitting while an operation runs cancels it first; the document was never changed, so the
// quit is not held back by unsaved changes.
TEST(EditorJobs, QuitCancelsTheOperation) {
    Editor ed = background_editor(shapes::icosphere(6));
    ASSERT_NE(ed.press(key_of('D'), kNoMods).changes & kJobStarted, 0u);
    const Outcome out = ed.run({Command::Quit});
    EXPECT_NE(out.changes & kQuit, 0u) << out.message;
    EXPECT_FALSE(ed.busy());
}

// A refused operation is refused at once, on the UI thread: no worker starts.
TEST(EditorJobs, RefusalIsImmediate) {
    Editor ed = background_editor(test::quad_cube());
    const Outcome out = ed.press(key_of('D'), kNoMods);
    EXPECT_TRUE(out.refused);
    EXPECT_FALSE(ed.busy());
    EXPECT_NE(out.message.find("6 of the 6 faces are polygons"), std::string::npos);
}

std::string bytes_of(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Opening reads the file on the worker: the same document, message and title as an open in
// place; a file that cannot be read says the same and leaves the document.
TEST(EditorJobs, OpenReadsInTheBackground) {
    TempDir dir;
    const fs::path file = dir / "ball.obj";
    write_mesh(shapes::icosphere(3), file);

    Editor here;
    const Outcome in_place = here.open(file);
    ASSERT_FALSE(in_place.refused) << in_place.message;

    Editor ed = background_editor(test::quad_cube());
    const Outcome started = ed.open(file);
    EXPECT_NE(started.changes & kJobStarted, 0u) << started.message;
    EXPECT_EQ(ed.job_progress()->verb, "open ball.obj");
    EXPECT_LT(ed.job_progress()->fraction, 0.0) << "reading does not say how far it is";
    EXPECT_EQ(ed.mesh().n_faces(), 6u) << "the old document stays until the file is read";
    const std::optional<Outcome> done = ed.wait_job();
    ASSERT_TRUE(done.has_value());
    EXPECT_EQ(done->message, in_place.message);
    EXPECT_EQ(done->changes, in_place.changes);
    EXPECT_EQ(ed.title(), here.title());
    EXPECT_TRUE(test::identical(ed.mesh(), here.mesh()));

    const fs::path missing = dir / "no_such.obj";
    ASSERT_NE(ed.open(missing).changes & kJobStarted, 0u);
    const std::optional<Outcome> failed = ed.wait_job();
    ASSERT_TRUE(failed.has_value());
    EXPECT_TRUE(failed->refused);
    EXPECT_NE(failed->message.find("no_such.obj"), std::string::npos) << failed->message;
    EXPECT_NE(failed->message.find("ball.obj stays open"), std::string::npos) << failed->message;
    EXPECT_TRUE(test::identical(ed.mesh(), here.mesh()));
}

// Saving writes on the worker: the same bytes as a save in place; the document is saved (no
// '*', the new path) once the file is written, not before; Esc cannot stop a save halfway.
TEST(EditorJobs, SaveWritesInTheBackground) {
    TempDir dir;
    Editor here = editor_with(shapes::icosphere(2));
    ASSERT_FALSE(here.press(key_of('L'), kNoMods).refused);
    ASSERT_FALSE(here.save_as(dir / "here.ply").refused);

    Editor ed = background_editor(shapes::icosphere(2));
    ASSERT_NE(ed.press(key_of('L'), kNoMods).changes & kJobStarted, 0u);
    ASSERT_TRUE(ed.wait_job().has_value());
    const fs::path file = dir / "there.ply";
    const Outcome started = ed.save_as(file);
    ASSERT_NE(started.changes & kJobStarted, 0u) << started.message;
    EXPECT_TRUE(ed.dirty());
    const Outcome esc = ed.run({Command::Escape});
    EXPECT_EQ(esc.message, "save there.ply cannot stop halfway: it ends in a moment");
    const std::optional<Outcome> done = ed.wait_job();
    ASSERT_TRUE(done.has_value());
    EXPECT_EQ(done->message, "saved there.ply");
    EXPECT_FALSE(ed.dirty());
    EXPECT_EQ(ed.path(), file);
    EXPECT_EQ(bytes_of(file), bytes_of(dir / "here.ply"));
}

}  // namespace
}  // namespace meshedit::viewer
