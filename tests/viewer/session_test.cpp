// The session: every edit the viewer makes is recorded as steps of the edit language, undo
// and redo keep the record in step with the mesh, and the record replays to the same mesh bit
// for bit: through ops::apply_steps after a random 1,000-command sweep, and through an
// exported file after a scripted one.

#include <gtest/gtest.h>

#include "editor_test_util.h"
#include "meshedit/core/shapes.h"
#include "meshedit/files/files.h"
#include "meshedit/io/io.h"
#include "meshedit/ops/ops.h"
#include "support/mesh_compare.h"
#include "viewer/undo_sweep.h"

namespace meshedit::viewer {
namespace {

Mesh replayed(Mesh start, const std::vector<std::string>& session) {
    std::vector<ops::Step> steps;
    for (const std::string& text : session) {
        steps.push_back(ops::parse_step(text));
    }
    ops::apply_steps(start, steps);
    return start;
}

TEST(Session, RandomSweepReplaysBitForBit) {
    Sweep sweep(20240611u);  // the undo sweep's sequence: its counts are checked there too
    sweep.run(1000);
    ASSERT_FALSE(::testing::Test::HasFatalFailure());
    ASSERT_GT(sweep.drags(), 20u);
    ASSERT_GT(sweep.modals(), 10u);
    const std::vector<std::string>& session = sweep.editor().document().session;
    EXPECT_GT(session.size(), 100u);
    EXPECT_TRUE(test::identical(replayed(shapes::torus(6, 4), session), sweep.editor().mesh()));
    // Undone to the start and redone to the end: the same record.
    sweep.unwind_and_replay();
    EXPECT_EQ(sweep.editor().document().session, session);
}

TEST(Session, ExportedFileReplaysAndUndoTakesStepsBack) {
    TempDir dir;
    write_mesh(shapes::cube(), dir / "cube.dae");
    Editor ed;
    ASSERT_FALSE(ed.open(dir / "cube.dae").refused);
    const Mesh& m = ed.mesh();
    ed.select(ElementRef::edge(edge_of(m, 0, 6)));
    ASSERT_FALSE(ed.run(edit("flip")).refused);
    ed.select(ElementRef::edge(edge_of(m, 1, 3)));
    ASSERT_FALSE(ed.run(edit("collapse")).refused);  // deletes: tombstones, indices stay
    ed.select(ElementRef::vertex(Vertex(2)));
    ASSERT_TRUE(ed.begin_drag());
    ed.drag_to({0.5, 2.0, -0.25});
    ed.drag_to({0.75, 2.0, -0.25});
    ed.end_drag();
    ASSERT_FALSE(ed.run(edit("loop")).refused);
    EXPECT_EQ(ed.document().session, (std::vector<std::string>{"flip:0-6", "collapse:3-1",
                                                               "move:v2:0.75,2,-0.25", "loop"}));
    // Undo takes the last edit's steps back; redo brings them again.
    ASSERT_FALSE(ed.run({Command::Undo}).refused);
    EXPECT_EQ(ed.document().session.size(), 3u);
    ASSERT_FALSE(ed.run({Command::Redo}).refused);
    EXPECT_EQ(ed.document().session.back(), "loop");

    const Outcome out = ed.export_session(dir / "cube.ops");
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_EQ(out.message,
              "exported 4 steps to cube.ops (meshedit convert IN OUT --ops @cube.ops replays "
              "them)");
    const std::string text = read_file(dir / "cube.ops");
    EXPECT_EQ(ops::session_header_value(text, "input"), (dir / "cube.dae").string());
    EXPECT_EQ(ops::session_header_value(text, "input-fnv1a64"),
              content_hash(read_file(dir / "cube.dae")));
    Mesh replay = read_mesh(dir / "cube.dae").mesh;
    ops::apply_steps(replay, ops::parse_session(text));
    EXPECT_TRUE(test::identical(replay, ed.mesh()));
}

TEST(Session, ModalEditsAreRecordedAndCurvesRefuseToExport) {
    Editor ed = editor_with(shapes::quad_sphere(1));
    ed.select(ElementRef::face(Face(0)));
    ASSERT_FALSE(ed.begin_modal(Modal::Extrude).refused);
    ed.modal_type('0');
    ed.modal_type('.');
    ed.modal_type('5');
    ASSERT_FALSE(ed.confirm_modal().refused);
    ed.select(ElementRef::vertex(Vertex(1)));
    ASSERT_FALSE(ed.begin_modal(Modal::Scale).refused);
    ed.modal_type('2');
    ASSERT_FALSE(ed.confirm_modal().refused);  // one vertex: scaling about itself moves nothing
    ed.select(ElementRef::face(Face(2)));
    ASSERT_FALSE(ed.begin_modal(Modal::Move).refused);
    ed.modal_type('1');
    ASSERT_FALSE(ed.confirm_modal().refused);
    const std::vector<std::string>& session = ed.document().session;
    ASSERT_EQ(session.size(), 5u);  // extrude, then face 2's four corners moved by 1 along X
    EXPECT_EQ(session[0], "extrude:f0:0.5,0");
    EXPECT_EQ(session[1].rfind("move:v", 0), 0u);
    EXPECT_TRUE(test::identical(replayed(shapes::quad_sphere(1), session), ed.mesh()));

    Document curve;
    curve.mode = Mode::Curve;
    ed.set_document(std::move(curve));
    const Outcome refused = ed.export_session(fs::path("/nonexistent") / "c.ops");
    EXPECT_TRUE(refused.refused);
    EXPECT_EQ(refused.message, "sessions record the edits of mesh files, not of a curve");
}

}  // namespace
}  // namespace meshedit::viewer
