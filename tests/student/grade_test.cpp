// `meshedit grade` on the student libraries tests/student/CMakeLists.txt builds: the reference
// solution scores 100%, the template runs without a crash, and every seeded mistake is caught
// in its own task, named by what the grader says about it.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "run.h"

namespace meshedit::test {
namespace {

std::string library(const std::string& name) {
    return std::string(STUDENT_LIBS) + "/" + name + ".so";
}

std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
    std::vector<std::string> out;
    for (const std::string& line : split_lines(text)) {
        if (line.rfind(prefix, 0) == 0) {
            out.push_back(line);
        }
    }
    return out;
}

TEST(Grade, TheSolutionScoresEverything) {
    const RunResult r = run_meshedit({"grade", library("student_solution")}, 120);
    EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
    EXPECT_TRUE(lines_starting(r.out, "FAIL").empty()) << r.out;
    EXPECT_NE(r.out.find("total           60.0/60.0 points (100.0%)"), std::string::npos) << r.out;
    // Every task ran cases: the battery covers the six.
    for (const char* task : {"evaluate_step", "evaluate_patch", "vertex_normal", "flip_edge",
                             "split_edge", "upsample"}) {
        EXPECT_GE(lines_starting(r.out, std::string("PASS ") + task + " on ").size(), 6u) << task;
    }
}

TEST(Grade, TheTemplateRunsAndScoresLittle) {
    const RunResult r = run_meshedit({"grade", library("student_template")}, 120);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    EXPECT_EQ(r.out.find("crashed"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("timed out"), std::string::npos) << r.out;
    // Only the cases where doing nothing is right pass: the refusals, and no points from one.
    for (const std::string& line : lines_starting(r.out, "PASS")) {
        EXPECT_TRUE(line.find("must be refused") != std::string::npos ||
                    line.find("a single point") != std::string::npos)
            << line;
    }
    EXPECT_NE(r.out.find("returned 0 points for 4, expected 3"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("FAIL split_edge on cube.dae edge 0 (0-4): differs from the reference"),
              std::string::npos)
        << r.out;
}

struct Bug {
    const char* library;  // tests/student/libs/bug_<library>.so
    const char* task;     // the only task that may fail
    const char* says;     // what some FAIL line of that task must contain
};

// One row per BUG_* of tests/student/solution (and CMakeLists.txt's list).
const Bug kBugs[] = {
    {"step_one_too_many", "evaluate_step", "returned 4 points for 4, expected 3"},
    {"step_one_too_few", "evaluate_step", "returned 2 points for 4, expected 3"},
    {"lerp_swapped", "evaluate_step", "expected (0.16, 0.41) = (1-t)·P0 + t·P1"},
    {"patch_uv_swapped", "evaluate_patch", "S(0.3, 0.7) is"},
    {"normals_not_area_weighted", "vertex_normal", "(area-weighted, unit length)"},
    {"normals_not_normalized", "vertex_normal", "is not unit length"},
    {"normals_reversed", "vertex_normal", "is reversed"},
    {"normals_boundary_face_used", "vertex_normal",
     "bowl.dae (boundary), every vertex: vertex 121"},
    {"flip_boundary_not_refused", "flip_edge", "boundary: must be refused: "},
    {"flip_existing_edge_not_refused", "flip_edge", "must be refused: invariant multi-edge"},
    {"flip_vertex_anchor", "flip_edge", "invariant vertex-anchor"},
    {"flip_face_anchor", "flip_edge", "invariant face-anchor"},
    {"flip_crash", "flip_edge", "flip_edge on cube.dae edge 7 (7-1): crashed (SIGSEGV)"},
    {"split_twin_not_set", "split_edge", "invariant twin: "},
    {"split_edge_halfedge_unset", "split_edge", "invariant edge: "},
    {"split_face_not_updated", "split_edge", "invariant next-face"},
    {"split_midpoint", "split_edge", "the reference puts it at"},
    {"split_returns_old_vertex", "split_edge", "not the new vertex"},
    {"split_boundary_face_used", "split_edge", "boundary: differs from the reference"},
    {"loop_valence3_weight", "upsample", "tetrahedron (valence 3): vertex 0 is at"},
    {"loop_boundary_ignored", "upsample", "bowl.dae (boundary): vertex 121 is at"},
    {"loop_crease_ignored", "upsample", "creased.dae (creases): vertex 0 is at"},
    {"loop_updated_positions", "upsample", "upsample on cube.dae: vertex"},
    {"loop_edges_not_marked_new", "upsample", "upsample on cube.dae: differs from the reference"},
    {"loop_edge_weights_swapped", "upsample", "upsample on cube.dae: vertex 8 is at"},
    {"loop_endless", "upsample", "timed out after 1 s"},
};

// gtest names the case by the library; this is what it prints of one.
void PrintTo(const Bug& bug, std::ostream* out) {
    *out << bug.library;
}

class SeededBug : public testing::TestWithParam<Bug> {};

TEST_P(SeededBug, IsCaughtInItsTaskAndNamed) {
    const Bug& bug = GetParam();
    std::vector<std::string> args{"grade", library(std::string("bug_") + bug.library)};
    if (std::string(bug.library) == "loop_endless") {
        // Every case waits out its time limit.
        args.insert(args.end(), {"--task", "upsample", "--timeout", "1"});
    }
    const RunResult r = run_meshedit(args, 300);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    const std::vector<std::string> fails = lines_starting(r.out, "FAIL");
    ASSERT_FALSE(fails.empty()) << bug.library << " was not caught:\n" << r.out;
    bool named = false;
    for (const std::string& line : fails) {
        EXPECT_EQ(line.rfind(std::string("FAIL ") + bug.task + " on ", 0), 0u)
            << "a mistake in " << bug.task << " failed another task: " << line;
        named = named || line.find(bug.says) != std::string::npos;
    }
    EXPECT_TRUE(named) << "no FAIL line says '" << bug.says << "':\n" << r.out;
}

INSTANTIATE_TEST_SUITE_P(Grade, SeededBug, testing::ValuesIn(kBugs),
                         [](const testing::TestParamInfo<Bug>& param) {
                             return std::string(param.param.library);
                         });

TEST(Grade, WritesGradescopeResults) {
    TempDir dir;
    const RunResult r = run_meshedit(
        {"grade", library("bug_split_midpoint"), "--gradescope", (dir / "results.json").string()},
        120);
    EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
    std::ifstream in(dir / "results.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    double sum = 0.0, most = 0.0;
    bool failed_split = false;
    for (const auto& t : j.at("tests")) {
        ASSERT_TRUE(t.contains("name") && t.contains("score") && t.contains("max_score") &&
                    t.contains("output") && t.contains("visibility"))
            << t.dump();
        EXPECT_EQ(t.at("visibility"), "visible");
        sum += t.at("score").get<double>();
        most += t.at("max_score").get<double>();
        if (t.at("score").get<double>() == 0.0) {
            EXPECT_EQ(t.at("name").get<std::string>().rfind("split_edge on ", 0), 0u);
            EXPECT_NE(t.at("output").get<std::string>().find("the reference puts it at"),
                      std::string::npos);
            failed_split = true;
        }
    }
    EXPECT_TRUE(failed_split);
    EXPECT_NEAR(most, 60.0, 1e-9);
    EXPECT_NEAR(j.at("score").get<double>(), sum, 1e-9);
    EXPECT_LT(sum, 60.0);
    EXPECT_GT(sum, 50.0 - 1e-9);  // only the split task lost points
}

TEST(Grade, AddsTheTeachersCasesAndHidesSome) {
    TempDir cases, out;
    std::filesystem::copy_file(repo_root() / "dae" / "cube.dae", cases / "cube.dae");
    std::filesystem::copy_file(repo_root() / "dae" / "icosahedron.dae", cases / "ico.hidden.dae");
    std::ofstream(cases / "cube.ops") << "# a session\nflip:0-6\nsplit:0-1, split:4-5\n";
    const auto grade = [&](const std::string& lib) {
        return run_meshedit({"grade", library(lib), "--cases", cases.path().string(),
                             "--gradescope", (out / "results.json").string()},
                            120);
    };
    const RunResult good = grade("student_solution");
    EXPECT_EQ(good.exit_code, 0) << good.out << good.err;
    EXPECT_NE(good.out.find("PASS flip_edge on cube.ops session"), std::string::npos) << good.out;
    EXPECT_NE(good.out.find("PASS upsample on ico.hidden.dae"), std::string::npos) << good.out;
    std::ifstream in(out / "results.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    int hidden = 0;
    for (const auto& t : j.at("tests")) {
        const std::string name = t.at("name");
        const bool secret = name.find("ico.hidden.dae") != std::string::npos;
        EXPECT_EQ(t.at("visibility"), secret ? "after_published" : "visible") << name;
        hidden += secret ? 1 : 0;
    }
    EXPECT_EQ(hidden, 4);  // normals, flip, split, Loop

    const RunResult bad = grade("bug_split_midpoint");
    EXPECT_NE(bad.out.find("FAIL flip_edge on cube.ops session: step 2 split:0-1: vertex"),
              std::string::npos)
        << bad.out;

    std::ofstream(cases / "bad.ops") << "flip:0-6\ncollapse:0-1\n";
    const RunResult refused = grade("student_solution");
    EXPECT_EQ(refused.exit_code, 2);
    EXPECT_NE(refused.err.find("bad.ops:2: 'collapse:0-1' is not flip:A-B or split:A-B"),
              std::string::npos)
        << refused.err;
}

TEST(Grade, HasHelp) {
    const RunResult r = run_meshedit({"grade", "--help"});
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("usage: meshedit grade"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--gradescope OUT.json"), std::string::npos) << r.out;
}

TEST(Grade, RefusesAPolygonMeshAmongTheCases) {
    TempDir cases;
    std::filesystem::copy_file(repo_root() / "dae" / "quadcube.dae", cases / "quads.dae");
    const RunResult r =
        run_meshedit({"grade", library("student_solution"), "--cases", cases.path().string()});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("quads.dae: not a triangle mesh"), std::string::npos) << r.err;
}

TEST(Grade, RefusesWhatIsNotAStudentLibrary) {
    TempDir dir;
    std::ofstream(dir / "junk.so") << "not a library";
    const RunResult junk = run_meshedit({"grade", (dir / "junk.so").string()});
    EXPECT_EQ(junk.exit_code, 2);
    EXPECT_NE(junk.err.find("cannot load"), std::string::npos) << junk.err;
    const RunResult crash = run_meshedit({"grade", library("crash_on_load")});
    EXPECT_EQ(crash.exit_code, 2);
    EXPECT_NE(crash.err.find("crash_on_load.so: loading it crashed (SIGSEGV)"), std::string::npos)
        << crash.err;
    const RunResult task = run_meshedit({"grade", library("student_solution"), "--task", "flip"});
    EXPECT_EQ(task.exit_code, 2);
    EXPECT_NE(task.err.find("--task flip: not a task"), std::string::npos) << task.err;
}

}  // namespace
}  // namespace meshedit::test
