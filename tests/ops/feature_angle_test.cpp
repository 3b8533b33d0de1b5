// Sharp edges found by their dihedral angle: crease_by_angle() marks exactly the cube's 12
// edges and nothing of a flat grid; a bad angle is refused with the mesh untouched; remesh and
// simplify with a feature angle keep every vertex of a cube on its faces and every crease
// vertex exactly on the cube's edges.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "meshedit/core/attributes.h"
#include "meshedit/core/normals.h"
#include "meshedit/core/remesh.h"
#include "meshedit/core/shapes.h"
#include "meshedit/core/simplify.h"
#include "meshedit/core/validate.h"
#include "meshedit/ops/ops.h"
#include "support/fixtures.h"
#include "support/mesh_compare.h"

namespace meshedit {
namespace {

// How many of p's coordinates are at ±s: 1 on a face of the cube [-s, s]³, 2 on an edge,
// 3 at a corner.
int cube_sides(const Vec3& p, double s, double tolerance) {
    int n = 0;
    for (double c : {p.x, p.y, p.z}) {
        n += std::abs(std::abs(c) - s) <= tolerance;
    }
    return n;
}

// Every vertex on a face of [-s, s]³; every vertex on two crease edges or more exactly on an
// edge of the cube (to 1e-9); the 8 corners kept.
void expect_on_cube(const Mesh& mesh, double s) {
    const auto crease = mesh.get_property<Edge, std::uint8_t>(kCreaseProperty);
    ASSERT_TRUE(crease);
    int corners = 0;
    for (Vertex v : mesh.vertices()) {
        const Vec3& p = mesh.position(v);
        const double largest = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        EXPECT_NEAR(largest, s, 1e-12) << "vertex " << v.idx() << " left the cube's faces";
        int crease_edges = 0;
        for (Edge e : mesh.edges(v)) {
            crease_edges += crease[e] != 0;
        }
        if (crease_edges >= 2) {
            EXPECT_GE(cube_sides(p, s, 1e-9), 2)
                << "crease vertex " << v.idx() << " at (" << p.x << ", " << p.y << ", " << p.z
                << ") left the cube's edges";
        }
        corners += cube_sides(p, s, 1e-12) == 3;
    }
    EXPECT_EQ(corners, 8);
}

TEST(CreaseByAngle, TheCubesTwelveEdgesAt60AndNoneAt100) {
    for (Mesh cube : {shapes::cube(), test::quad_cube()}) {
        Mesh none = cube;
        EXPECT_EQ(crease_by_angle(none, 100.0), 0u);
        EXPECT_FALSE((none.get_property<Edge, std::uint8_t>(kCreaseProperty)))
            << "nothing marked: no crease property added";
        EXPECT_TRUE(test::identical(none, cube));
        EXPECT_EQ(crease_by_angle(cube, 60.0), 12u);
        EXPECT_VALID(cube);
        EXPECT_EQ(test::crease_count(cube), 12u);
        const auto crease = cube.get_property<Edge, std::uint8_t>(kCreaseProperty);
        for (Edge e : cube.edges()) {
            const Vec3 d = cube.position(cube.vertex(e, 1)) - cube.position(cube.vertex(e, 0));
            const int axes = (d.x != 0) + (d.y != 0) + (d.z != 0);
            EXPECT_EQ(crease[e] != 0, axes == 1) << "edge " << e.idx();
        }
        // Again: they are creases already, so nothing new is marked.
        EXPECT_EQ(crease_by_angle(cube, 60.0), 0u);
        EXPECT_EQ(test::crease_count(cube), 12u);
    }
}

TEST(CreaseByAngle, ExistingCreasesStayAndAFlatGridGetsNone) {
    Mesh grid = shapes::grid(6, 5);
    EXPECT_EQ(crease_by_angle(grid, 0.0), 0u);
    EXPECT_EQ(crease_by_angle(grid, 30.0), 0u);
    EXPECT_VALID(grid);
    EXPECT_EQ(test::crease_count(grid), 0u);
    // A crease the user marked by hand stays (Mark Sharp adds, never clears).
    auto crease = grid.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    const Edge inner = *std::find_if(grid.edges().begin(), grid.edges().end(),
                                     [&](Edge e) { return !grid.is_boundary(e); });
    crease[inner] = 1;
    EXPECT_EQ(crease_by_angle(grid, 10.0), 0u);
    EXPECT_EQ(test::crease_count(grid), 1u);
}

TEST(CreaseByAngle, BadAnglesAreRefusedAndTheMeshIsUntouched) {
    EXPECT_EQ(check_crease_by_angle(std::numeric_limits<double>::quiet_NaN()),
              "cannot mark creases by angle: the angle must be from 0 to 180 degrees, not nan");
    EXPECT_EQ(check_crease_by_angle(-1.0),
              "cannot mark creases by angle: the angle must be from 0 to 180 degrees, not -1");
    EXPECT_EQ(check_crease_by_angle(180.5),
              "cannot mark creases by angle: the angle must be from 0 to 180 degrees, not 180.5");
    EXPECT_EQ(check_crease_by_angle(0.0), "");
    EXPECT_EQ(check_crease_by_angle(180.0), "");
    for (const char* list : {"crease_by_angle:nan", "crease_by_angle:-1", "crease_by_angle:181",
                             "remesh:0,3,-5", "simplify:0.5,inf,200", "remesh:0,3,nan"}) {
        Mesh cube = shapes::cube();
        const Mesh before = cube;
        try {
            ops::apply_steps(cube, ops::parse(list), {});
            ADD_FAILURE() << list << " ran";
        } catch (const ops::OpError& e) {
            EXPECT_TRUE(e.refused()) << e.what();
            EXPECT_NE(std::string(e.what()).find("180 degrees"), std::string::npos) << e.what();
        }
        EXPECT_TRUE(test::identical(cube, before)) << list;
        EXPECT_VALID(cube);
    }
}

TEST(CreaseByAngle, TheVerbSaysHowManyItMarked) {
    Mesh cube = shapes::cube();
    const std::vector<ops::Step> steps = ops::parse("crease_by_angle:60");
    const ops::StepsRun run = ops::run_steps(cube, steps, ops::OnRefusal::Stop);
    EXPECT_EQ(test::crease_count(cube), 12u);
    EXPECT_EQ(run.last_message, "marked 12 edges sharper than 60° as creases");
    EXPECT_EQ(ops::parse("crease_by_angle")[0].amounts[0], 30.0);  // Blender's default
}

// The feature angle is the third amount of simplify and remesh; left out it is off and the
// step's text is as before; with no error bound it is written after `inf`, which parses back.
TEST(FeatureAngle, IsTheThirdAmountOfSimplifyAndRemesh) {
    const Mesh cube = shapes::cube();
    EXPECT_EQ(ops::make_step("remesh", cube, {}, std::array{0.0, 3.0, kNoFeatureAngle}).text,
              "remesh:0,3");
    EXPECT_EQ(ops::make_step("remesh", cube, {}, std::array{0.0, 3.0, 40.0}).text, "remesh:0,3,40");
    const ops::Step simplify = ops::make_step(
        "simplify", cube, {}, std::array{0.5, std::numeric_limits<double>::infinity(), 40.0});
    EXPECT_EQ(simplify.text, "simplify:0.5,inf,40");
    const std::vector<ops::Step> steps = ops::parse(simplify.text + ",remesh:0.2,2,30,flip:0-6");
    ASSERT_EQ(steps.size(), 3u);
    EXPECT_TRUE(std::isinf(steps[0].amounts[1]));
    EXPECT_EQ(steps[0].amounts[2], 40.0);
    EXPECT_EQ(steps[1].amounts[2], 30.0);
    EXPECT_EQ(ops::parse("simplify:0.5")[0].amounts[2], kNoFeatureAngle);
}

// The triangulated cube (12 triangles, no crease marks) remeshed with a feature angle: its
// edges are found, split along themselves and never smoothed, so the cube stays a cube.
TEST(FeatureAngle, RemeshKeepsTheCubesEdgesStraight) {
    Mesh cube = shapes::cube();
    RemeshOptions options;
    options.target_length = 0.3;
    options.feature_angle_deg = 60.0;
    ASSERT_EQ(check_remesh(cube, options), "");
    const RemeshReport report = remesh(cube, options);
    EXPECT_VALID(cube);
    EXPECT_EQ(report.creases_marked, 12u);
    EXPECT_GT(cube.n_faces(), 300u);
    expect_on_cube(cube, 1.0);
    RemeshOptions bad = options;
    bad.feature_angle_deg = -1.0;
    EXPECT_EQ(check_remesh(cube, bad),
              "cannot remesh: the feature angle must be from 0 to 180 degrees (infinity: off), "
              "not -1");
}

// A cube of 768 flat triangles simplified to 5% with no error bound: with the feature angle
// every crease vertex stays exactly on the cube's edges (collapses along a crease keep an
// end, across one keep the crease end).
TEST(FeatureAngle, SimplifyKeepsTheCubesEdgesStraight) {
    Mesh cube = test::flat_sided_cube();
    ASSERT_EQ(cube.n_faces(), 768u);
    SimplifyOptions options;
    options.target_faces = 40;
    options.feature_angle_deg = 60.0;
    ASSERT_EQ(check_simplify(cube, options), "");
    const SimplifyReport report = simplify(cube, options);
    EXPECT_VALID(cube);
    EXPECT_EQ(report.creases_marked, 12u * 8u);
    EXPECT_LE(cube.n_faces(), 120u) << report.refused_crease << " crease refusals";
    expect_on_cube(cube, 1.0 / std::sqrt(3.0));
    SimplifyOptions bad = options;
    bad.target_faces = 10;
    bad.feature_angle_deg = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(check_simplify(cube, bad),
              "cannot simplify: the feature angle must be from 0 to 180 degrees (infinity: off), "
              "not nan");
}

}  // namespace
}  // namespace meshedit
