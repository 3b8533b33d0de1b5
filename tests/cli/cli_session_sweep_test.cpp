// A random 200-command viewer session (the undo sweep's: picks, every edit key, drags,
// interactive edits, undo and redo), exported as the viewer exports it and replayed by the
// `meshedit` binary: the file it writes is the file the viewer saves, byte for byte.

#include <gtest/gtest.h>

#include "meshedit/files/files.h"
#include "meshedit/io/io.h"
#include "meshedit/ops/ops.h"
#include "run.h"
#include "viewer/undo_sweep.h"

namespace meshedit::test {
namespace {

TEST(CliSession, RandomViewerSessionReplaysThroughTheCliByteForByte) {
    TempDir tmp;
    // The sweep starts from this torus in memory; the file holds the same mesh.
    write_mesh(shapes::torus(6, 4), tmp / "torus.dae");
    viewer::Sweep sweep(7u);
    sweep.run(200);
    ASSERT_FALSE(::testing::Test::HasFatalFailure());
    ASSERT_GT(sweep.edits(), 50u);
    ASSERT_GT(sweep.editor().document().session.size(), 12u);  // 17: undo takes steps back
    const std::vector<std::string>& session = sweep.editor().document().session;
    write_file(tmp / "session.ops", ops::session_text({"a random session"}, session));
    write_mesh(sweep.editor().mesh(), tmp / "viewer.dae");  // what Ctrl+S writes

    std::string at = "@";
    at += (tmp / "session.ops").string();
    const RunResult r = run_meshedit(
        {"convert", (tmp / "torus.dae").string(), (tmp / "replayed.dae").string(), "--ops", at});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(read_file(tmp / "replayed.dae"), read_file(tmp / "viewer.dae"))
        << session.size() << " steps";
}

}  // namespace
}  // namespace meshedit::test
