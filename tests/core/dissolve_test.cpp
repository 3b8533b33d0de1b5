// make_boundary, fill_hole, dissolve_edge and dissolve_vertex. Each case draws the input and
// builds the expected mesh by editing the input's face list by hand (faces removed or merged,
// vertices erased); refusals leave the mesh bit for bit.
//
// grid(3,3) below: vertex (i, j) is 4j + i, and cell (i, j) is cut by the diagonal from its
// (i, j) corner into (4j+i, 4j+i+1, 4j+i+5) and (4j+i, 4j+i+5, 4j+i+4):
//
//   12 - 13 - 14 - 15
//    | /  | /  | /  |
//    8 -- 9 - 10 - 11
//    | /  | /  | /  |
//    4 -- 5 -- 6 -- 7
//    | /  | /  | /  |
//    0 -- 1 -- 2 -- 3

#include <gtest/gtest.h>

#include <cstdint>
#include <string_view>

#include "core/op_test_util.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

using test::Indexed;

// Garbage-collects (so that positions and faces compare with a built mesh) and checks.
void collect_and_validate(Mesh& mesh) {
    ASSERT_VALID(mesh);
    mesh.garbage_collection();
    ASSERT_VALID(mesh);
}

// ----------------------------------------------------------------- make_boundary

// The middle cell's lower triangle (5,6,10) becomes a hole of three sides; nothing else goes.
TEST(MakeBoundary, InteriorTriangleLeavesAHole) {
    Mesh mesh = shapes::grid(3, 3);
    Indexed expected = test::indexed(mesh);
    expected.remove({5, 6, 10});
    const std::size_t e = mesh.n_edges();
    ASSERT_TRUE(is_make_boundary_ok(mesh, test::face_with(mesh, {5, 6, 10})));
    const OpResult<Halfedge> r = make_boundary(mesh, test::face_with(mesh, {5, 6, 10}));
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_TRUE(mesh.is_boundary(*r));
    EXPECT_EQ(mesh.n_edges(), e);
    EXPECT_EQ(test::boundary_loops(mesh), 2u);
    std::size_t sides = 0;
    for ([[maybe_unused]] const Halfedge h : mesh.loop(*r)) {
        ++sides;
    }
    EXPECT_EQ(sides, 3u);
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// (1,2,6) has the rim side 1-2: that side goes and the hole is part of the outer boundary.
TEST(MakeBoundary, RimTriangleJoinsTheOuterBoundary) {
    Mesh mesh = shapes::grid(3, 3);
    Indexed expected = test::indexed(mesh);
    expected.remove({1, 2, 6});
    const std::size_t e = mesh.n_edges();
    ASSERT_TRUE(make_boundary(mesh, test::face_with(mesh, {1, 2, 6})));
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.n_edges(), e - 1);
    EXPECT_EQ(test::boundary_loops(mesh), 1u);
    EXPECT_TRUE(mesh.is_boundary(Vertex(6)));
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// The corner triangle (2,3,7) holds vertex 3 alone: 3 and its two edges go with it.
TEST(MakeBoundary, EarLosesItsCorner) {
    Mesh mesh = shapes::grid(3, 3);
    Indexed expected = test::indexed(mesh);
    expected.remove({2, 3, 7});
    expected.erase_vertex(3);
    ASSERT_TRUE(make_boundary(mesh, test::face_with(mesh, {2, 3, 7})));
    ASSERT_VALID(mesh);
    EXPECT_TRUE(mesh.is_deleted(Vertex(3)));
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// The middle of three quads touches the rim on two separate sides: both go, and the strip
// falls into two quads with a boundary each.
//   4 --- 5 --- 6 --- 7        4 --- 5     6 --- 7
//   |     |     |     |   =>   |     |     |     |
//   0 --- 1 --- 2 --- 3        0 --- 1     2 --- 3
TEST(MakeBoundary, QuadStripFallsApart) {
    Mesh mesh = test::quad_strip(3);
    Indexed expected = test::indexed(mesh);
    expected.remove({1, 2, 6, 5});
    ASSERT_TRUE(make_boundary(mesh, Face(1)));
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.n_edges(), 8u);
    EXPECT_EQ(test::boundary_loops(mesh), 2u);
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

TEST(MakeBoundary, LoneTriangleLeavesNothing) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    const OpResult<Halfedge> r = make_boundary(mesh, Face(0));
    ASSERT_TRUE(r) << r.reason();
    EXPECT_FALSE(r.value().is_valid());
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.n_vertices(), 0u);
    EXPECT_EQ(mesh.n_edges(), 0u);
    EXPECT_EQ(mesh.n_faces(), 0u);
}

// After a hole at (10,11,15), vertex 10 is on the boundary; (5,6,10) touches that hole only
// at 10, so removing it would put 10 on two holes.
TEST(MakeBoundary, RefusesACornerOnTwoHoles) {
    Mesh mesh = shapes::grid(3, 3);
    ASSERT_TRUE(make_boundary(mesh, test::face_with(mesh, {10, 11, 15})));
    const Face f = test::face_with(mesh, {5, 6, 10});
    test::expect_refused_by(
        mesh, [f](Mesh& m) { return make_boundary(m, f); },
        "cannot make boundary: a corner would touch two holes");
}

TEST(MakeBoundary, RefusesADeletedFace) {
    Mesh mesh = shapes::grid(3, 3);
    const Face f = test::face_with(mesh, {5, 6, 10});
    ASSERT_TRUE(make_boundary(mesh, f));
    test::expect_refused_by(
        mesh, [f](Mesh& m) { return make_boundary(m, f); },
        "cannot make boundary: the face is deleted");
}

// ----------------------------------------------------------------- fill_hole

TEST(FillHole, RefillsWhatMakeBoundaryLeft) {
    Mesh mesh = shapes::grid(3, 3);
    const Mesh input = mesh;
    const OpResult<Halfedge> hole = make_boundary(mesh, test::face_with(mesh, {5, 6, 10}));
    ASSERT_TRUE(hole);
    const OpResult<Face> r = fill_hole(mesh, *hole);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.halfedge(*r), *hole);
    EXPECT_EQ(test::boundary_loops(mesh), 1u);
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, input));
}

// The rim of a six-triangle fan becomes a hexagon: the disk closes into a sphere (χ = 2).
TEST(FillHole, RimOfADisk) {
    Mesh mesh = shapes::disk(6);
    Indexed expected = test::indexed(mesh);
    expected.add({6, 5, 4, 3, 2, 1});
    const Halfedge rim = Mesh::twin(mesh.find_halfedge(Vertex(1), Vertex(2)));
    ASSERT_TRUE(fill_hole(mesh, rim));
    ASSERT_VALID(mesh);
    EXPECT_EQ(test::euler(mesh), 2);
    EXPECT_EQ(test::boundary_loops(mesh), 0u);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

TEST(FillHole, Refusals) {
    Mesh mesh = shapes::grid(3, 3);
    const Halfedge inside = mesh.find_halfedge(Vertex(5), Vertex(6));
    test::expect_refused_by(
        mesh, [inside](Mesh& m) { return fill_hole(m, inside); },
        "cannot fill: not a boundary edge");
}

// ----------------------------------------------------------------- dissolve_edge

// The diagonal goes and the square is one quad.
TEST(DissolveEdge, TwoTrianglesBecomeAQuad) {
    Mesh mesh = test::two_triangles();
    const Edge e = mesh.find_edge(Vertex(0), Vertex(2));
    ASSERT_TRUE(is_dissolve_edge_ok(mesh, e));
    const Face kept = mesh.face(Mesh::halfedge(e, 0));
    const OpResult<Face> r = dissolve_edge(mesh, e);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(*r, kept);
    EXPECT_EQ(mesh.valence(*r), 4u);
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(
        mesh, test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}})));
}

// A quad and a triangle across 1-2 become a pentagon.
//   3 ----- 2             3 ----- 2
//   |       | \           |         \ (one face)
//   |  quad |  4    =>    |           4     (0,1,4,2,3)
//   |       | /           |         /
//   0 ----- 1             0 ----- 1
TEST(DissolveEdge, QuadAndTriangleBecomeAPentagon) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}},
                                      {{0, 1, 2, 3}, {1, 4, 2}});
    ASSERT_TRUE(dissolve_edge(mesh, mesh.find_edge(Vertex(1), Vertex(2))));
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(
        mesh, test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}},
                                    {{0, 1, 4, 2, 3}})));
}

// On the rim the one face joins the hole, as make_boundary.
TEST(DissolveEdge, RimEdgeMakesItsFaceAHole) {
    Mesh mesh = shapes::grid(3, 3);
    Indexed expected = test::indexed(mesh);
    expected.remove({1, 2, 6});
    const OpResult<Face> r = dissolve_edge(mesh, mesh.find_edge(Vertex(1), Vertex(2)));
    ASSERT_TRUE(r) << r.reason();
    EXPECT_FALSE(r.value().is_valid());
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// F = (0,1,2,3) and G = (2,1,0,4) share both edges at vertex 1: merged across 0-1 they
// would visit 2 twice.
TEST(DissolveEdge, RefusesFacesThatShareAnotherCorner) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {0.5, 0.5, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 0}},
                                      {{0, 1, 2, 3}, {2, 1, 0, 4}});
    const Edge e = mesh.find_edge(Vertex(0), Vertex(1));
    test::expect_refused_by(
        mesh, [e](Mesh& m) { return dissolve_edge(m, e); },
        "cannot dissolve: the merged face would visit a vertex twice");
}

// ----------------------------------------------------------------- dissolve_vertex

// The centre of a six-triangle fan goes; its faces become one hexagon.
TEST(DissolveVertex, InteriorFanBecomesOnePolygon) {
    Mesh mesh = test::one_ring(6);
    Indexed expected = test::indexed(mesh);
    expected.faces = {{1, 2, 3, 4, 5, 6}};
    expected.erase_vertex(0);
    ASSERT_TRUE(is_dissolve_vertex_ok(mesh, Vertex(0)));
    const OpResult<Face> r = dissolve_vertex(mesh, Vertex(0));
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(mesh.valence(*r), 6u);
    EXPECT_TRUE(mesh.is_deleted(Vertex(0)));
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// Corner 0 of the square goes; the boundary is kept by a new side 3-1 (0-3 turned).
//   3 ----- 2        3 ----- 2
//   |     / |          \     |
//   |   /   |   =>       \   |      (0,1,2), (0,2,3) -> (1,2,3)
//   | /     |              \ |
//   0 ----- 1                1
TEST(DissolveVertex, BoundaryCornerKeepsTheHole) {
    Mesh mesh = test::two_triangles();
    Indexed expected = test::indexed(mesh);
    expected.faces = {{1, 2, 3}};
    expected.erase_vertex(0);
    const OpResult<Face> r = dissolve_vertex(mesh, Vertex(0));
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(test::boundary_loops(mesh), 1u);
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// Rim vertex 1 between two quads: one pentagon, the rim runs 0 -> 2 directly.
//   3 ----- 4 ----- 5        3 ----- 4 ----- 5
//   |       |       |        |               |
//   |       |       |   =>   |               |     (0,2,5,4,3)
//   0 ----- 1 ----- 2        0 ------------- 2
TEST(DissolveVertex, RimVertexBetweenTwoQuads) {
    Mesh mesh = test::quad_strip(2);
    Indexed expected = test::indexed(mesh);
    expected.faces = {{0, 2, 5, 4, 3}};
    expected.erase_vertex(1);
    ASSERT_TRUE(dissolve_vertex(mesh, Vertex(1)));
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// Vertex 1 of valence 2 between F = (0,1,2,3) and G = (2,1,0,4), which share both its
// edges: without it they are one quad.
TEST(DissolveVertex, ValenceTwoVertexBetweenTwoFaces) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {0.5, 0.5, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 0}},
                                      {{0, 1, 2, 3}, {2, 1, 0, 4}});
    Indexed expected = test::indexed(mesh);
    expected.faces = {{2, 3, 0, 4}};
    expected.erase_vertex(1);
    ASSERT_TRUE(dissolve_vertex(mesh, Vertex(1)));
    collect_and_validate(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

TEST(DissolveVertex, Refusals) {
    {  // a corner of a lone triangle: two corners would be left
        Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
        test::expect_refused_by(
            mesh, [](Mesh& m) { return dissolve_vertex(m, Vertex(0)); },
            "cannot dissolve: the merged face would have fewer than 3 corners");
    }
    {  // faces (0,1,4,2), (0,2,5,3), (0,3,4,1) around 0: the first and last share 4, which
       // the merged face (1,4,2,5,3,4) would visit twice
        Mesh mesh = test::mesh_from_faces(
            {{0, 0, 0}, {1, 0, 0}, {-0.5, 0.9, 0}, {-0.5, -0.9, 0}, {2, 0, 0}, {-1, 0, 0}},
            {{0, 1, 4, 2}, {0, 2, 5, 3}, {0, 3, 4, 1}});
        ASSERT_VALID(mesh);
        test::expect_refused_by(
            mesh, [](Mesh& m) { return dissolve_vertex(m, Vertex(0)); },
            "cannot dissolve: the merged face would visit a vertex twice");
    }
    {  // rim vertex 0 of (0,1,2), (0,2,3) beside (1,3,2): the closing edge 1-3 exists
        Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}},
                                          {{0, 1, 2}, {0, 2, 3}, {1, 3, 2}});
        ASSERT_VALID(mesh);
        test::expect_refused_by(
            mesh, [](Mesh& m) { return dissolve_vertex(m, Vertex(0)); },
            "cannot dissolve: the new edge already exists");
    }
    {  // an isolated vertex (3, in no face)
        Mesh mesh =
            test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}}, {{0, 1, 2}});
        ASSERT_TRUE(mesh.is_isolated(Vertex(3)));
        test::expect_refused_by(
            mesh, [](Mesh& m) { return dissolve_vertex(m, Vertex(3)); },
            "cannot dissolve: the vertex has no edges");
    }
}

}  // namespace
}  // namespace meshedit
