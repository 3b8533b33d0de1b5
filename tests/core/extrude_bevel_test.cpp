// inset_face, extrude_face, bevel_vertex and bevel_edge. Each case draws the input and the
// result; expected meshes are written by hand, by position (new corners are computed from the
// documented rules: a fraction of the way to the centre or along an edge).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string_view>

#include "core/op_test_util.h"
#include "meshedit/core/local_ops.h"

namespace meshedit {
namespace {

Mesh unit_square() {
    return test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}});
}

// ----------------------------------------------------------------- inset and extrude

// The square inset by half: a ring of four quads around a square half its size.
//   3 --------- 2        3 --------- 2
//   |           |        | 7 ----- 6 |
//   |           |   =>   | |       | |
//   |           |        | 4 ----- 5 |
//   0 --------- 1        0 --------- 1
TEST(Inset, SquareByHalf) {
    Mesh mesh = unit_square();
    const Face f(0);
    const OpResult<Face> r = inset_face(mesh, f, 0.5);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(*r, f);
    EXPECT_EQ(mesh.valence(f), 4u);
    const Mesh expected = test::mesh_from_faces(
        {{0, 0, 0},
         {1, 0, 0},
         {1, 1, 0},
         {0, 1, 0},
         {0.25, 0.25, 0},
         {0.75, 0.25, 0},
         {0.75, 0.75, 0},
         {0.25, 0.75, 0}},
        {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// The top of the cube extruded by 1 along its normal (+z): a closed mesh with a box on top.
TEST(Extrude, CubeTopByOne) {
    Mesh mesh = test::quad_cube();
    const Face top = test::face_with(mesh, {4, 5, 6, 7});
    const OpResult<Face> r = extrude_face(mesh, top, 1.0, 0.0);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.n_vertices(), 12u);
    EXPECT_EQ(mesh.n_edges(), 20u);
    EXPECT_EQ(mesh.n_faces(), 10u);
    EXPECT_EQ(test::euler(mesh), 2);
    test::Indexed expected = test::indexed(test::quad_cube());
    for (std::uint32_t i = 4; i < 8; ++i) {
        Vec3 p = expected.positions[i];
        p.z = 2;
        expected.add_vertex(p);
    }
    expected.remove({4, 5, 6, 7});
    expected.add({4, 5, 9, 8});
    expected.add({5, 6, 10, 9});
    expected.add({6, 7, 11, 10});
    expected.add({7, 4, 8, 11});
    expected.add({8, 9, 10, 11});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// A lone triangle, extruded and shrunk: the outer triangle's sides stay on the boundary.
TEST(Extrude, TriangleOnTheBoundaryShrinks) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {3, 0, 0}, {0, 3, 0}}, {{0, 1, 2}});
    ASSERT_TRUE(extrude_face(mesh, Face(0), 2.0, 0.5));
    ASSERT_VALID(mesh);
    EXPECT_EQ(test::boundary_loops(mesh), 1u);
    const Mesh expected = test::mesh_from_faces(
        {{0, 0, 0}, {3, 0, 0}, {0, 3, 0}, {0.5, 0.5, 2}, {2, 0.5, 2}, {0.5, 2, 2}},
        {{0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}, {3, 4, 5}});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

TEST(Extrude, Refusals) {
    Mesh mesh = unit_square();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    test::expect_refused_by(
        mesh, [](Mesh& m) { return extrude_face(m, Face(0), 1.0, 1.0); },
        "cannot extrude: shrink must be below 1 (1 is a point)");
    test::expect_refused_by(
        mesh, [nan](Mesh& m) { return extrude_face(m, Face(0), nan, 0.0); },
        "cannot extrude: the amounts must be finite numbers");
    test::expect_refused_by(
        mesh, [](Mesh& m) { return inset_face(m, Face(0), 2.0); },
        "cannot inset: shrink must be below 1 (1 is a point)");
    // Finite but absurd: corners whose squared length (so every normal and area) overflows.
    test::expect_refused_by(
        mesh, [](Mesh& m) { return extrude_face(m, Face(0), 1e308, 0.0); },
        "cannot extrude: the amounts put corners beyond the range of numbers");
    test::expect_refused_by(
        mesh, [](Mesh& m) { return inset_face(m, Face(0), -1e300); },
        "cannot inset: the amount puts corners beyond the range of numbers");
    ASSERT_TRUE(extrude_face(mesh, Face(0), 1e100, 0.0)) << "large, but its squares fit";
    ASSERT_VALID(mesh);
    Mesh flat = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}});
    test::expect_refused_by(
        flat, [](Mesh& m) { return extrude_face(m, Face(0), 1.0, 0.0); },
        "cannot extrude: the face has no area, so no normal");
    ASSERT_TRUE(inset_face(flat, Face(0), 0.0)) << "no height, no normal needed";
}

// ----------------------------------------------------------------- bevel

// Cube corner 0 at t = 1/4: a triangle cuts the corner off; its three quads become
// pentagons.
TEST(BevelVertex, CubeCorner) {
    Mesh mesh = test::quad_cube();
    const OpResult<Face> r = bevel_vertex(mesh, Vertex(0), 0.25);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.valence(*r), 3u);
    EXPECT_EQ(mesh.n_vertices(), 10u);
    EXPECT_EQ(mesh.n_edges(), 15u);
    EXPECT_EQ(mesh.n_faces(), 7u);
    // Corners a quarter of the way from (-1,-1,-1) to 1, 3 and 4.
    const Vec3 on1{-0.5, -1, -1}, on3{-1, -0.5, -1}, on4{-1, -1, -0.5};
    test::Indexed expected = test::indexed(test::quad_cube());
    expected.positions[0] = on1;
    const std::uint32_t c3 = expected.add_vertex(on3);
    const std::uint32_t c4 = expected.add_vertex(on4);
    expected.remove({0, 3, 2, 1});
    expected.remove({0, 1, 5, 4});
    expected.remove({3, 0, 4, 7});
    expected.add({c3, 3, 2, 1, 0});
    expected.add({0, 1, 5, 4, c4});
    expected.add({3, c3, c4, 4, 7});
    expected.add({0, c4, c3});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// Square corner 0 (a boundary vertex of valence 3) at t = 1/4: a triangle whose side
// (0,0.25)-(0.25,0) is on the boundary.
//   3 ----- 2        3 ------- 2
//   |     / |        |       / |
//   |   /   |   =>   w0-- w2   |
//   | /     |          \  |    |
//   0 ----- 1            w1 -- 1
TEST(BevelVertex, BoundaryCorner) {
    Mesh mesh = test::two_triangles();
    ASSERT_TRUE(bevel_vertex(mesh, Vertex(0), 0.25));
    ASSERT_VALID(mesh);
    EXPECT_EQ(test::boundary_loops(mesh), 1u);
    const Mesh expected = test::mesh_from_faces(
        {{0, 0.25, 0}, {0.25, 0, 0}, {0.25, 0.25, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
        {{1, 3, 4, 2}, {2, 4, 5, 0}, {0, 1, 2}});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// The diagonal 0-2 of the square at t = 1/4: a quad B = (P1, P2, P4, P3) between the
// triangles (P2, 1, P4) and (P3, 3, P1); P1 and P2 are a quarter of the way from 0 to 3 and
// to 1, P4 and P3 from 2 to 1 and to 3. B has a side on the boundary at each end.
//   3 ----- 2        3 ---P3-- 2
//   |     / |        |    ` .  P4
//   |   /   |   =>  P1   B   ` |
//   | /     |         ` .      |
//   0 ----- 1            P2 -- 1
TEST(BevelEdge, SquareDiagonal) {
    Mesh mesh = test::two_triangles();
    const OpResult<Face> r = bevel_edge(mesh, mesh.find_edge(Vertex(0), Vertex(2)), 0.25);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.valence(*r), 4u);
    const Mesh expected = test::mesh_from_faces(
        {{0, 0.25, 0}, {0.25, 0, 0}, {1, 0.75, 0}, {0.75, 1, 0}, {1, 0, 0}, {0, 1, 0}},
        {{1, 4, 2}, {3, 5, 0}, {0, 1, 2, 3}});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// A cube edge: its two ends have three edges each, so the new face has four corners; the
// two quads beside the edge stay quads, the two at its ends become pentagons.
TEST(BevelEdge, CubeEdgeCounts) {
    Mesh mesh = test::quad_cube();
    const OpResult<Face> r = bevel_edge(mesh, mesh.find_edge(Vertex(0), Vertex(1)), 0.1);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.valence(*r), 4u);
    EXPECT_EQ(mesh.n_vertices(), 10u);
    EXPECT_EQ(mesh.n_edges(), 15u);
    EXPECT_EQ(mesh.n_faces(), 7u);
    EXPECT_EQ(test::euler(mesh), 2);
}

TEST(Bevel, Refusals) {
    Mesh square = unit_square();
    test::expect_refused_by(
        square, [](Mesh& m) { return bevel_vertex(m, Vertex(0), 0.1); },
        "cannot bevel: the new face would have fewer than 3 corners");
    test::expect_refused_by(
        square, [](Mesh& m) { return bevel_edge(m, m.find_edge(Vertex(0), Vertex(1)), 0.1); },
        "cannot bevel: the new face would have fewer than 3 corners");
    Mesh cube = test::quad_cube();
    for (const double t : {-0.1, 1.0, std::numeric_limits<double>::infinity()}) {
        test::expect_refused_by(
            cube, [t](Mesh& m) { return bevel_vertex(m, Vertex(0), t); },
            "cannot bevel: the amount must be at least 0 and below 1");
    }
}

}  // namespace
}  // namespace meshedit
