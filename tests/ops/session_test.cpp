// What the viewer records and `--ops @FILE` replays: move puts a vertex at exact doubles,
// compact renumbers as a written file does, and a session file's text parses line by line
// (header comments skipped, errors named by line).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"
#include "meshedit/ops/ops.h"
#include "support/mesh_compare.h"

namespace meshedit::ops {
namespace {

TEST(OpsSession, MoveSetsExactDoublesAndRefusesNonFinite) {
    Mesh mesh = shapes::cube();
    const double third = 1.0 / 3.0;
    const double at[] = {third, -1e-300, 2.5};
    const Step written = make_step("move", mesh, ElementRef::vertex(Vertex(4)), at);
    EXPECT_EQ(written.text, "move:v4:0.3333333333333333,-1e-300,2.5");
    const std::vector<Step> steps = parse(written.text);
    ASSERT_EQ(steps.size(), 1u);
    run_step(mesh, steps[0]);
    EXPECT_EQ(mesh.position(Vertex(4)), Vec3(third, -1e-300, 2.5));
    EXPECT_VALID(mesh);
    const Mesh before = mesh;
    const Step nan = make_step("move", mesh, ElementRef::vertex(Vertex(4)),
                               std::vector<double>{0.0, std::nan(""), 0.0});
    EXPECT_EQ(nan.verb->check(mesh, nan), "cannot move: the position must be finite");
    const Step huge = parse("move:v4:1e300,0,0")[0];
    EXPECT_EQ(huge.verb->check(mesh, huge),
              "cannot move: the position is beyond the range of numbers (its square overflows)");
    EXPECT_TRUE(test::identical(mesh, before));
    EXPECT_THROW(run_step(mesh, parse("move:v99:0,0,0")[0]), OpError);
}

TEST(OpsSession, CompactRenumbersAsAWrittenFileDoes) {
    Mesh mesh = shapes::grid(3, 3);
    ASSERT_TRUE(collapse(mesh, mesh.find_edge(Vertex(5), Vertex(6))));
    Mesh expected = mesh;
    expected.garbage_collection();
    const StepResult r = run_step(mesh, parse("compact")[0]);
    EXPECT_TRUE(r.renumbers);
    EXPECT_EQ(r.message, "renumbered densely: V 15 E 30 F 16");
    EXPECT_FALSE(mesh.has_garbage());
    EXPECT_TRUE(test::identical(mesh, expected));
    EXPECT_EQ(run_step(mesh, parse("compact")[0]).message,
              "nothing to renumber (no deleted elements)");
}

TEST(OpsSession, SessionTextRoundTripsAndNamesBadLines) {
    const std::string text = session_text({"MeshEdit session: 3 steps", "input-fnv1a64: 0123abcd"},
                                          {"flip:0-6", "move:v2:0.5,-1,2", "loop"});
    EXPECT_EQ(text,
              "# MeshEdit session: 3 steps\n# input-fnv1a64: 0123abcd\nflip:0-6\n"
              "move:v2:0.5,-1,2\nloop\n");
    const std::vector<Step> steps = parse_session(text);
    ASSERT_EQ(steps.size(), 3u);
    EXPECT_EQ(steps[1].text, "move:v2:0.5,-1,2");
    EXPECT_EQ(session_header_value(text, "input-fnv1a64"), "0123abcd");
    EXPECT_EQ(session_header_value(text, "input"), std::nullopt);
    EXPECT_EQ(session_header_value("flip:0-6\n# input-fnv1a64: 12\n", "input-fnv1a64"),
              std::nullopt)
        << "the header ends at the first step";
    // Hand-written: comma lists, blank lines, CRLF, indented comments.
    EXPECT_EQ(parse_session("\r\nflip:0-6, split:0-1\r\n   # why\r\nloop:2\r\n").size(), 3u);
    EXPECT_TRUE(parse_session("# only a header\n").empty());
    // Old Mac line endings (a lone CR): each line still one line, not one long comment.
    const std::string mac = "# MeshEdit session\r# input-fnv1a64: 12\rflip:0-6\rloop\r";
    ASSERT_EQ(parse_session(mac).size(), 2u);
    EXPECT_EQ(parse_session(mac)[1].text, "loop");
    EXPECT_EQ(session_header_value(mac, "input-fnv1a64"), "12");
    try {
        parse_session("# h\rflip:0-6\r\rflop:1-2\r");
        ADD_FAILURE() << "parsed";
    } catch (const SyntaxError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("line 4: unknown op", 0), 0u) << e.what();
    }
    try {
        parse_session("# h\nflip:0-6\n\nflop:1-2\n");
        ADD_FAILURE() << "parsed";
    } catch (const SyntaxError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("line 4: unknown op 'flop:1-2'", 0), 0u) << e.what();
    }
}

}  // namespace
}  // namespace meshedit::ops
