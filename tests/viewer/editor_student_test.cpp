// `--student` without a window: the editor runs the seeded-bug libraries of tests/student and
// the correct solution behind F, S, L, Q and E, in forked children.

#include <string>

#include "editor_test_util.h"
#include "meshedit/core/build.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/io/io.h"

namespace meshedit::viewer {
namespace {

fs::path library(const std::string& name) {
    return fs::path(STUDENT_LIBS) / (name + ".so");
}

Mesh cube() {
    return read_mesh(fs::path(MESHEDIT_SOURCE_DIR) / "dae" / "cube.dae").mesh;
}

// An editor on the cube under `lib`, `edge` (an interior edge) selected.
Editor student_editor(const std::string& lib, Edge edge) {
    Editor ed = editor_with(cube());
    const Outcome loaded = ed.load_student(library(lib));
    EXPECT_FALSE(loaded.refused) << loaded.message;
    ed.select(ElementRef::edge(edge));
    return ed;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// The first edge of the cube the reference flips.
Edge flippable(const Mesh& mesh) {
    for (const Edge e : mesh.edges()) {
        if (is_flip_ok(mesh, e)) {
            return e;
        }
    }
    ADD_FAILURE() << "no flippable edge";
    return {};
}

// The cube under `lib`, F pressed on its first flippable edge.
struct Flipped {
    Mesh input = cube();
    Edge e = flippable(input);
    Editor ed;
    std::uint64_t revision_before = 0;
    Outcome out;
};

Flipped flip_under(const std::string& lib) {
    Flipped f;
    f.ed = student_editor(lib, f.e);
    f.revision_before = f.ed.document().revision;
    f.out = f.ed.press(key_of('F'), kNoMods);
    return f;
}

TEST(EditorStudent, CorrectFlipGoesInAsOneUndoStepLikeTheReference) {
    auto [input, e, ed, revision, out] = flip_under("student_solution");
    ASSERT_FALSE(out.refused) << out.message;
    EXPECT_TRUE(contains(out.message, "your flip_edge matches the reference")) << out.message;
    EXPECT_EQ(ed.student_comparison(), nullptr);
    EXPECT_EQ(ed.history().undo_steps(), 1u);
    Mesh expected = input;
    ASSERT_TRUE(flip(expected, e));
    std::string why;
    EXPECT_TRUE(bitwise_equal(ed.mesh(), expected, &why)) << why;
    ed.run({Command::Undo});
    EXPECT_TRUE(bitwise_equal(ed.mesh(), input, &why)) << why;
}

// A flip that leaves a face's halfedge outside its loop: the side by side, the broken
// invariant named, the culprit selected in the student's half and its counterpart in the
// reference's; Esc steps back to the input bit for bit.
TEST(EditorStudent, SeededFlipBugShowsTheSideBySideNamingTheElement) {
    auto [input, e, ed, revision, out] = flip_under("bug_flip_face_anchor");
    ASSERT_FALSE(out.refused) << out.message;
    const StudentComparison* c = ed.student_comparison();
    ASSERT_NE(c, nullptr) << out.message;
    EXPECT_EQ(c->task, "flip_edge");
    EXPECT_FALSE(c->invariant.empty()) << c->difference;
    EXPECT_TRUE(contains(out.message, "invariant " + c->invariant)) << out.message;
    EXPECT_TRUE(contains(out.message, "flip_edge on edge " + std::to_string(e.idx())))
        << out.message;
    EXPECT_NE(out.changes & kResetCamera, 0u);
    // Both results, side by side: twice the cube's vertices, the reference's on the right.
    EXPECT_EQ(ed.mesh().n_vertices(), 2 * input.n_vertices());
    EXPECT_EQ(c->reference_from, input.n_vertices());
    ASSERT_TRUE(is_live(ed.mesh(), c->yours));
    ASSERT_TRUE(is_live(ed.mesh(), c->reference));
    EXPECT_EQ(ed.selection(), c->yours);
    ASSERT_EQ(ed.also_selected().size(), 1u);
    EXPECT_EQ(ed.also_selected()[0], c->reference);
    double left = -1e9, right = 1e9;
    for (const Vertex v : ed.mesh().vertices()) {
        const double x = ed.mesh().position(v).x;
        if (v.idx() < c->reference_from) {
            left = std::max(left, x);
        } else {
            right = std::min(right, x);
        }
    }
    EXPECT_LT(left, right) << "the reference's result is not to the right of the student's";
    OverlayBatch marks;
    add_comparison_marks(ed.mesh(), *c, marks);
    EXPECT_EQ(marks.lines.size(), 24u);  // a box around each
    // Another F and saving are refused on the side by side; Esc steps back, redo shows it
    // again.
    EXPECT_TRUE(ed.press(key_of('F'), kNoMods).refused);
    TempDir dir;
    EXPECT_TRUE(ed.save_as(dir / "side_by_side.obj").refused);
    EXPECT_FALSE(fs::exists(dir / "side_by_side.obj"));
    const Outcome back = ed.press(Key::Escape, kNoMods);
    EXPECT_FALSE(back.refused) << back.message;
    EXPECT_EQ(ed.student_comparison(), nullptr);
    std::string why;
    EXPECT_TRUE(bitwise_equal(ed.mesh(), input, &why)) << why;
    EXPECT_FALSE(ed.dirty());
    ed.run({Command::Redo});
    ASSERT_NE(ed.student_comparison(), nullptr);
    EXPECT_EQ(ed.mesh().n_vertices(), 2 * input.n_vertices());
}

// A valid result that differs (the split's new vertex off the midpoint): no invariant, the
// differing vertex framed in both halves.
TEST(EditorStudent, SplitOffTheMidpointNamesTheVertex) {
    const Mesh input = cube();
    Editor ed = student_editor("bug_split_midpoint", Edge(0));
    const Outcome out = ed.press(key_of('S'), kNoMods);
    ASSERT_FALSE(out.refused) << out.message;
    const StudentComparison* c = ed.student_comparison();
    ASSERT_NE(c, nullptr) << out.message;
    EXPECT_TRUE(c->invariant.empty()) << c->invariant;
    EXPECT_TRUE(contains(c->difference, "the reference puts it at")) << c->difference;
    EXPECT_EQ(c->yours.kind, ElementRef::Kind::Vertex);
    EXPECT_EQ(c->reference.kind, ElementRef::Kind::Vertex);
    EXPECT_LT(c->yours.index, c->reference_from);
    EXPECT_GE(c->reference.index, c->reference_from);
}

// A crash in the student's flip: refused, naming the function, the edge and the signal; the
// document is untouched, bit for bit, with no undo step.
TEST(EditorStudent, CrashingFlipLeavesTheDocumentAsItWas) {
    auto [input, e, ed, revision, out] = flip_under("bug_flip_crash");
    EXPECT_TRUE(out.refused);
    EXPECT_TRUE(contains(out.message, "flip_edge on edge " + std::to_string(e.idx())))
        << out.message;
    EXPECT_TRUE(contains(out.message, "crashed (SIG")) << out.message;
    std::string why;
    EXPECT_TRUE(bitwise_equal(ed.mesh(), input, &why)) << why;
    EXPECT_EQ(ed.document().revision, revision);
    EXPECT_EQ(ed.history().undo_steps(), 0u);
    EXPECT_EQ(ed.student_comparison(), nullptr);
}

// An endless loop in upsample is stopped at the time limit and named; the mesh stays.
TEST(EditorStudent, EndlessLoopTimesOutAndLeavesTheDocument) {
    Editor ed = editor_with(cube());
    ASSERT_FALSE(ed.load_student(library("bug_loop_endless"), {1.0, 1.0}).refused);
    const Outcome out = ed.press(key_of('L'), kNoMods);
    EXPECT_TRUE(out.refused);
    EXPECT_TRUE(contains(out.message, "upsample on the mesh: your code timed out after 1 s"))
        << out.message;
    std::string why;
    EXPECT_TRUE(bitwise_equal(ed.mesh(), cube(), &why)) << why;
    EXPECT_EQ(ed.history().undo_steps(), 0u);
}

// A split that forgets a twin cannot even be written back: the student's own structure is
// drawn (its faces walked with bounds), the halfedge named and framed on both sides.
TEST(EditorStudent, SplitWithAnUnsetTwinIsDrawnFromTheStudentsMesh) {
    Editor ed = student_editor("bug_split_twin_not_set", Edge(0));
    const Outcome out = ed.press(key_of('S'), kNoMods);
    ASSERT_FALSE(out.refused) << out.message;
    const StudentComparison* c = ed.student_comparison();
    ASSERT_NE(c, nullptr) << out.message;
    EXPECT_EQ(c->invariant, "twin");
    EXPECT_TRUE(contains(out.message, "invariant twin: halfedge")) << out.message;
    EXPECT_TRUE(is_live(ed.mesh(), c->yours)) << to_string(c->yours);
    EXPECT_TRUE(is_live(ed.mesh(), c->reference)) << to_string(c->reference);
    EXPECT_FALSE(validate(ed.mesh()).has_value());  // what the viewer holds is a valid mesh
}

// The template as handed out (its flip_edge refuses everything) loads, and F shows what is
// left to do: the cube unflipped beside the reference's flip.
TEST(EditorStudent, TemplateAsHandedOutShowsWhatIsLeftToDo) {
    auto [input, e, ed, revision, out] = flip_under("student_template");
    ASSERT_FALSE(out.refused) << out.message;
    ASSERT_NE(ed.student_comparison(), nullptr) << out.message;
    EXPECT_TRUE(contains(out.message, "yours (left) is not the reference's (right)"))
        << out.message;
    EXPECT_TRUE(ed.student_comparison()->invariant.empty());
}

// A library that crashes while it loads is refused; the keys then run the reference.
TEST(EditorStudent, LibraryCrashingOnLoadIsRefused) {
    Editor ed = editor_with(cube());
    const Outcome loaded = ed.load_student(library("crash_on_load"));
    EXPECT_TRUE(loaded.refused);
    EXPECT_TRUE(contains(loaded.message, "crashed")) << loaded.message;
    EXPECT_FALSE(ed.student_mode());
    ed.select(ElementRef::edge(flippable(ed.mesh())));
    const Outcome out = ed.press(key_of('F'), kNoMods);
    EXPECT_FALSE(out.refused) << out.message;
    EXPECT_FALSE(contains(out.message, "your")) << out.message;
}

TEST(EditorStudent, LoopByTheSolutionMatchesAndByAWrongWeightDiffers) {
    Editor good = student_editor("student_solution", Edge(0));
    const Outcome same = good.press(key_of('L'), kNoMods);
    ASSERT_FALSE(same.refused) << same.message;
    EXPECT_TRUE(contains(same.message, "your upsample matches the reference")) << same.message;
    EXPECT_EQ(good.mesh().n_faces(), 48u);

    // A tetrahedron: every vertex of valence 3.
    PolygonSoup soup;
    soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    soup.add_face({0, 2, 1});
    soup.add_face({0, 1, 3});
    soup.add_face({0, 3, 2});
    soup.add_face({1, 2, 3});
    Editor bad = editor_with(build_mesh(soup));
    ASSERT_FALSE(bad.load_student(library("bug_loop_valence3_weight")).refused);
    const Outcome differs = bad.press(key_of('L'), kNoMods);
    ASSERT_FALSE(differs.refused) << differs.message;
    ASSERT_NE(bad.student_comparison(), nullptr) << differs.message;
    EXPECT_TRUE(contains(differs.message, "upsample on the mesh")) << differs.message;
}

TEST(EditorStudent, ReversedNormalsAreNamedAndTheVertexSelected) {
    Editor ed = student_editor("bug_normals_reversed", Edge(0));
    ed.select_none();
    const Mesh input = ed.mesh();
    const Outcome out = ed.press(key_of('Q'), kNoMods);
    EXPECT_TRUE(contains(out.message, "is reversed")) << out.message;
    const StudentComparison* c = ed.student_comparison();
    ASSERT_NE(c, nullptr) << out.message;
    EXPECT_EQ(ed.selection().kind, ElementRef::Kind::Vertex);
    EXPECT_EQ(ed.selection(), c->yours);
    EXPECT_EQ(c->reference.index, c->yours.index + c->reference_from);
    // The mesh twice, each vertex with its normal: the student's reversed.
    ASSERT_EQ(c->yours_normals.size(), input.vertices_size());
    ASSERT_EQ(c->reference_normals.size(), input.vertices_size());
    EXPECT_EQ(ed.mesh().n_vertices(), 2 * input.n_vertices());
    const std::uint32_t v = c->yours.index;
    EXPECT_NEAR(dot(c->yours_normals[v], c->reference_normals[v]), -1.0, 1e-9);
    OverlayBatch marks;
    add_comparison_marks(ed.mesh(), *c, marks);
    EXPECT_EQ(marks.lines.size(), 2 * input.n_vertices() + 24);  // the normals, two boxes
    ed.press(Key::Escape, kNoMods);
    std::string why;
    EXPECT_TRUE(bitwise_equal(ed.mesh(), input, &why)) << why;

    Editor good = student_editor("student_solution", Edge(0));
    const Outcome fine = good.press(key_of('Q'), kNoMods);
    EXPECT_TRUE(contains(fine.message, "matches the reference at every vertex")) << fine.message;
}

// + in Surface mode checks evaluate_patch at every point of the new grid, the density
// changing either way.
TEST(EditorStudent, PatchWithUAndVSwappedIsNamedAtTheNewDensity) {
    for (const char* lib : {"bug_patch_uv_swapped", "student_solution"}) {
        Editor ed;
        ed.open(fs::path(MESHEDIT_SOURCE_DIR) / "bez" / "wavy_cube.bez");
        ASSERT_EQ(ed.mode(), Mode::Surface);
        ASSERT_FALSE(ed.load_student(library(lib)).refused);
        const int before = ed.document().density;
        const Outcome out = ed.run({Command::DensityUp});
        EXPECT_FALSE(out.refused) << out.message;
        EXPECT_GT(ed.document().density, before);
        EXPECT_TRUE(contains(out.message, std::string(lib) == "student_solution"
                                              ? "your evaluate_patch matches the reference"
                                              : "your evaluate_patch: patch "))
            << lib << ": " << out.message;
    }
}

TEST(EditorStudent, WrongDeCasteljauStepKeepsTheLevel) {
    TempDir dir;
    const fs::path file = dir / "c.bzc";
    write_bzc(BezierCurve{{{0.1, 0.2, 0}, {0.3, 0.9, 0}, {0.7, 0.1, 0}, {0.9, 0.8, 0}}}, file);
    for (const char* lib : {"bug_lerp_swapped", "student_solution"}) {
        Editor ed;
        ed.open(file);
        ASSERT_FALSE(ed.load_student(library(lib)).refused);
        ed.view().level = 0;
        ed.set_t(0.3);  // at 0.5 swapped weights give the same points
        const Outcome out = ed.press(key_of('E'), kNoMods);
        if (std::string(lib) == "student_solution") {
            EXPECT_FALSE(out.refused) << out.message;
            EXPECT_EQ(ed.view().level, 1);
        } else {
            EXPECT_TRUE(out.refused);
            EXPECT_TRUE(contains(out.message, "evaluate_step from level 0")) << out.message;
            EXPECT_EQ(ed.view().level, 0);
        }
    }
}

}  // namespace
}  // namespace meshedit::viewer
