// Every whole-mesh operation stops within the memory budget: refused before it starts when
// its estimate is over, stopped as it grows when the estimate was wrong, and either way the
// input is left as it was and the message names the budget.

#include <gtest/gtest.h>

#include <string>

#include "meshedit/core/budget.h"
#include "meshedit/core/build.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/shapes.h"
#include "meshedit/ops/ops.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

// Sets a budget for one test, below the 64 MiB floor, and restores the default after it.
class SmallBudget {
public:
    explicit SmallBudget(std::size_t bytes) { set_memory_budget_without_floor(bytes); }
    ~SmallBudget() { set_memory_budget(0); }
    SmallBudget(const SmallBudget&) = delete;
    SmallBudget& operator=(const SmallBudget&) = delete;
};

// Runs `steps` on a copy of `mesh` and returns the message of the refusal; the copy must be
// exactly the input afterwards.
std::string refusal_of(const Mesh& mesh, const std::string& steps) {
    Mesh work = mesh;
    std::string message;
    try {
        ops::apply_steps(work, ops::parse(steps));
        ADD_FAILURE() << steps << " ran within the budget";
    } catch (const std::exception& e) {
        message = e.what();
    }
    EXPECT_TRUE(test::identical(work, mesh)) << steps << " changed the input";
    return message;
}

Mesh from_faces(const std::vector<Vec3>& points,
                const std::vector<std::vector<std::uint32_t>>& faces) {
    PolygonSoup soup;
    soup.positions = points;
    for (const auto& corners : faces) {
        soup.indices.insert(soup.indices.end(), corners.begin(), corners.end());
        soup.face_offsets.push_back(static_cast<std::uint32_t>(soup.indices.size()));
    }
    return build_mesh(soup);
}

TEST(Budget, SubdivisionPastTheBudgetIsRefusedBeforeItStarts) {
    const SmallBudget budget(std::size_t{1} << 20);
    const Mesh torus = shapes::torus(48, 24);
    for (const char* steps : {"loop:2", "catmull_clark:2", "linear:2"}) {
        const std::string why = refusal_of(torus, steps);
        EXPECT_NE(why.find("over the budget of 1.0 MB"), std::string::npos) << steps << ": " << why;
    }
}

TEST(Budget, SimplifyPastTheBudgetIsRefusedBeforeItStarts) {
    const SmallBudget budget(std::size_t{1} << 20);
    const Mesh torus = shapes::torus(128, 64);  // 16,384 faces: 1.6 MB of quadrics and queue
    const std::string why = refusal_of(torus, "simplify:0.5");
    EXPECT_NE(why.find("cannot simplify: the quadrics and the queue of 16384 faces"),
              std::string::npos)
        << why;
    EXPECT_NE(why.find("over the budget of 1.0 MB"), std::string::npos) << why;
}

TEST(Budget, RemeshOfANeedleIsEstimatedFromItsEdgesNotItsArea) {
    // A 100 x 100 grid of side 0.01 and one needle 100 long beside it: the area says a few
    // thousand triangles at the mean edge length, the needle's edges say tens of millions.
    const SmallBudget budget(std::size_t{256} << 20);
    Mesh grid = shapes::grid(100, 100);
    std::vector<Vec3> points;
    std::vector<std::vector<std::uint32_t>> faces;
    for (Vertex v : grid.vertices()) {
        points.push_back(grid.position(v));
    }
    for (Face f : grid.faces()) {
        std::vector<std::uint32_t> corners;
        for (Vertex v : grid.vertices(f)) {
            corners.push_back(v.idx());
        }
        faces.push_back(corners);
    }
    const auto n = static_cast<std::uint32_t>(points.size());
    points.insert(points.end(), {{5, 0, 0}, {105, 0, 0}, {5, 1e-9, 0}});
    faces.push_back({n, n + 1, n + 2});
    Mesh mesh = from_faces(points, faces);
    const std::string why = refusal_of(mesh, "remesh");
    EXPECT_NE(why.find("cannot remesh: an edge length of"), std::string::npos) << why;
    EXPECT_NE(why.find("over the budget of 268.4 MB"), std::string::npos) << why;
}

TEST(Budget, RemeshThatOutgrowsItsEstimateStopsAsItGrows) {
    // Three corners on a line: no area, and the projection onto a segment folds the surface,
    // so the splits go on past the edges' estimate (435,812 faces at length 0.01 unguarded).
    const SmallBudget budget(std::size_t{8} << 20);
    const Mesh line = from_faces({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}});
    RemeshOptions options;
    options.target_length = 0.01;
    ASSERT_EQ(check_remesh(line, options), "");  // the estimate passes: 22,500 triangles
    Mesh work = line;
    try {
        remesh(work, options);
        FAIL() << "remeshing ran within 8 MB";
    } catch (const BudgetError& e) {
        const std::string why = e.what();
        EXPECT_NE(why.find("cannot remesh: stopped at "), std::string::npos) << why;
        EXPECT_NE(why.find("over the budget of 8.4 MB"), std::string::npos) << why;
    }
    EXPECT_TRUE(test::identical(work, line));
}

TEST(Budget, PhasesOfAPhasedLoopArePlannedAsLevelsNotOneLevelEach) {
    // A viewer session of two phased Loops and a Loop: three levels, not nine (nine levels
    // of the icosahedron would be 5 million faces, over 8 MB).
    const SmallBudget budget(std::size_t{8} << 20);
    Mesh mesh = shapes::icosahedron();
    ops::apply_steps(mesh, ops::parse("loop_step:4,loop_step:4,loop"));
    EXPECT_EQ(mesh.n_faces(), 20u * 4 * 4 * 4);
    // A level grows the mesh at its split (phase 2), wherever a list starts in the phases.
    Mesh half = shapes::icosahedron();
    ops::apply_steps(half, ops::parse("loop_step:1"));
    ops::apply_steps(half, ops::parse("loop_step:3,loop_step:1,loop_step:3,loop:2"));
    EXPECT_EQ(half.n_faces(), 20u * 4 * 4 * 4 * 4);
    // Still refused when the levels are too many, naming the first step past the budget.
    const std::string why = refusal_of(shapes::icosahedron(), "loop_step:4,loop:9");
    EXPECT_EQ(why.rfind("loop:9 refused: cannot subdivide: level", 0), 0u) << why;
}

TEST(Budget, AnOpsListIsCheckedBeforeItIsParsed) {
    // 60,000 session lines of 9 bytes: about 150 bytes a step once parsed, 9 MB in all.
    std::string session = "# a long session\n";
    for (int i = 0; i < 60000; ++i) {
        session += "flip:0-1\n";
    }
    EXPECT_GT(ops::parse_cost(session), 60000.0 * 120);
    EXPECT_EQ(ops::parse_session(session).size(), 60000u);  // the default budget: fine
    const SmallBudget budget(std::size_t{4} << 20);
    try {
        ops::parse_session(session);
        FAIL() << "a session of 60,000 steps parsed within 4 MB";
    } catch (const BudgetError& e) {
        const std::string why = e.what();
        EXPECT_EQ(why.rfind("parsing a session of 540017 characters would need about", 0), 0u)
            << why;
        EXPECT_NE(why.find("over the budget of 4.2 MB"), std::string::npos) << why;
    }
    // The same steps as one comma list.
    std::string list = "flip:0-1";
    for (int i = 1; i < 60000; ++i) {
        list += ",flip:0-1";
    }
    EXPECT_THROW(ops::parse(list), BudgetError);
    EXPECT_EQ(ops::parse("flip:0-1,loop").size(), 2u);  // a short list still parses
}

}  // namespace
}  // namespace meshedit
