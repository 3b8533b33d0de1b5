// `--ops @FILE`: a session file (what the viewer's Ctrl+Shift+E exports, or one written by
// hand) replays exactly as the same steps given as a list; its header is skipped; a file
// recorded on another input is replayed with a note; a bad line is named.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "meshedit/files/files.h"
#include "meshedit/io/io.h"
#include "run.h"
#include "support/mesh_compare.h"

namespace meshedit::test {
namespace {

// "@PATH", built piecewise: `"@" + std::string` trips a GCC 12 -Wrestrict false positive.
std::string at(const std::filesystem::path& path) {
    std::string arg = "@";
    arg += path.string();
    return arg;
}

// A session of one flip recorded on a file of fingerprint `hash`.
std::string header_line(const std::string& hash) {
    std::string text = "# input-fnv1a64: ";
    text += hash;
    text += "\nflip:0-6\n";
    return text;
}

std::string cube() {
    return (repo_root() / "dae/cube.dae").string();
}

TEST(CliSession, SessionFileEqualsTheOpsList) {
    TempDir tmp;
    // One step a line, a comma list on a line, comments, blank lines and CRLF ends.
    write_file(tmp / "s.ops",
               "# MeshEdit session: 5 steps\r\n# input: dae/cube.dae\r\n\r\nflip:0-6\r\n"
               "split:0-1, move:v8:0.25,-1,0.5\r\n  # a note\r\ncollapse:1-3\r\ncompact\r\n");
    const RunResult file =
        run_meshedit({"convert", cube(), (tmp / "file.dae").string(), "--ops", at(tmp / "s.ops")});
    ASSERT_EQ(file.exit_code, 0) << file.err;
    EXPECT_EQ(file.err.find("note"), std::string::npos) << "no hash in the header, no note";
    const RunResult list =
        run_meshedit({"convert", cube(), (tmp / "list.dae").string(), "--ops",
                      "flip:0-6,split:0-1,move:v8:0.25,-1,0.5,collapse:1-3,compact"});
    ASSERT_EQ(list.exit_code, 0) << list.err;
    EXPECT_TRUE(identical(read_mesh(tmp / "file.dae").mesh, read_mesh(tmp / "list.dae").mesh));
    EXPECT_EQ(read_mesh(tmp / "file.dae").mesh.position(Vertex(7)), Vec3(0.25, -1, 0.5))
        << "v8 is v7 after the collapse deleted v3 and compact renumbered";
}

TEST(CliSession, AnotherInputGetsANoteAndABadLineItsNumber) {
    TempDir tmp;
    write_file(tmp / "s.ops", header_line(content_hash("not the cube")));
    const RunResult r =
        run_meshedit({"convert", cube(), (tmp / "a.dae").string(), "--ops", at(tmp / "s.ops")});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("s.ops was recorded on another file (fnv1a64 "), std::string::npos)
        << r.err;
    write_file(tmp / "same.ops", header_line(content_hash(read_file(cube()))));
    const RunResult same =
        run_meshedit({"convert", cube(), (tmp / "b.dae").string(), "--ops", at(tmp / "same.ops")});
    ASSERT_EQ(same.exit_code, 0) << same.err;
    EXPECT_EQ(same.err.find("another file"), std::string::npos) << same.err;

    write_file(tmp / "bad.ops", "# header\nflip:0-6\n\nflop:1-2\n");
    const RunResult bad =
        run_meshedit({"convert", cube(), (tmp / "c.dae").string(), "--ops", at(tmp / "bad.ops")});
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("bad.ops: line 4: unknown op 'flop:1-2'"), std::string::npos) << bad.err;
    EXPECT_FALSE(std::filesystem::exists(tmp / "c.dae"));
    const RunResult missing = run_meshedit(
        {"convert", cube(), (tmp / "d.dae").string(), "--ops", at(tmp / "absent.ops")});
    EXPECT_EQ(missing.exit_code, 2);
    EXPECT_NE(missing.err.find("absent.ops: no such file"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace meshedit::test
