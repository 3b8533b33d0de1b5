// The Problems panel's list (Alt+V, editor_problems.cpp): a file the loader repaired opens
// with its cuts listed first; a click's element exists; an edit makes the list stale; a clean
// mesh has none.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "meshedit/core/shapes.h"
#include "support/fixtures.h"
#include "viewer/editor_test_util.h"

namespace meshedit::viewer {
namespace {

namespace fs = std::filesystem;

TEST(EditorProblems, ALoadThatCutAnEdgeOpensWithItsProblemsListed) {
    TempDir dir;
    const fs::path file = dir / "fin.obj";
    // Three triangles on the edge 1-2: the loader cuts it apart.
    std::ofstream(file) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
                           "f 1 2 3\nf 2 1 4\nf 1 2 5\n";
    Editor ed;
    ASSERT_FALSE(ed.open(file).refused);
    EXPECT_TRUE(ed.load_repaired());
    const ProblemReport* report = ed.problems();
    ASSERT_NE(report, nullptr) << "found on open, as the load repaired something";
    ASSERT_FALSE(report->problems.empty());
    const Problem& first = report->problems.front();
    EXPECT_EQ(first.kind, ProblemKind::LoadCut);
    EXPECT_NE(first.text.find("cut apart on load"), std::string::npos) << first.text;
    EXPECT_TRUE(is_live(ed.mesh(), first.where));
    for (const Problem& p : report->problems) {
        EXPECT_TRUE(p.where.is_none() || is_live(ed.mesh(), p.where)) << p.text;
    }
    // An edit: the list is of another mesh now, and the load's cuts are no longer known.
    ed.select(ElementRef::face(Face(0)));
    ASSERT_FALSE(ed.press(key_of('P'), kShift).refused);  // poke
    EXPECT_EQ(ed.problems(), nullptr);
    EXPECT_FALSE(ed.load_repaired());
    const Outcome again = ed.press(key_of('V'), kAlt);
    EXPECT_EQ(again.message.rfind("problems: ", 0), 0u) << again.message;
    ASSERT_NE(ed.problems(), nullptr);
    EXPECT_EQ(ed.problems()->counts[static_cast<std::size_t>(ProblemKind::LoadCut)], 0u);
    EXPECT_GT(ed.problems()->counts[static_cast<std::size_t>(ProblemKind::Hole)], 0u);
    // Undo goes back to the file as loaded: its cuts count again.
    ed.press(key_of('Z'), kCtrl);
    EXPECT_TRUE(ed.load_repaired());
}

TEST(EditorProblems, ACleanMeshHasNoneAndAltVSaysSo) {
    Editor ed = editor_with(shapes::icosphere(2));
    EXPECT_EQ(ed.problems(), nullptr);
    EXPECT_FALSE(ed.load_repaired());
    const Outcome out = ed.press(key_of('V'), kAlt);
    EXPECT_EQ(out.message, "problems: no problems");
    ASSERT_NE(ed.problems(), nullptr);
    EXPECT_TRUE(ed.problems()->empty());
    EXPECT_FALSE(ed.dirty());
}

}  // namespace
}  // namespace meshedit::viewer
