// Edge flip, as specified in docs/spec.md §3: (a,b,c),(c,b,d) -> (a,d,c),(a,b,d). Each case
// draws the two triangles before and after, builds the expected mesh from the input's face
// list edited by hand, and compares by position.

#include <gtest/gtest.h>

#include "core/op_test_util.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

using test::Indexed;

// Runs a flip that must succeed and checks the returned handle.
void expect_flip(Mesh& mesh, std::uint32_t b, std::uint32_t c, std::uint32_t a, std::uint32_t d) {
    const Edge e = mesh.find_edge(Vertex(b), Vertex(c));
    ASSERT_TRUE(e.is_valid());
    EXPECT_TRUE(is_flip_ok(mesh, e));
    const OpResult<Edge> r = flip(mesh, e);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(*r, e) << "flip returns the same edge";
    EXPECT_EQ(test::endpoints(mesh, e), std::make_pair(std::min(a, d), std::max(a, d)));
}

// Two triangles, flipped across the square:
//   3 ----- 2        3 ----- 2
//   |     / |        | \     |
//   |   /   |   =>   |   \   |
//   | /     |        |     \ |
//   0 ----- 1        0 ----- 1
TEST(Flip, TwoTriangles) {
    Mesh mesh = test::two_triangles();
    expect_flip(mesh, 0, 2, 3, 1);
    const Mesh expected =
        test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 3}, {1, 2, 3}});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// Flipping twice restores the faces (the edge ends where it started, reversed).
TEST(Flip, TwiceIsIdentityOnFaces) {
    Mesh mesh = shapes::icosahedron();
    const Mesh before = mesh;
    const Edge e(7);
    ASSERT_TRUE(flip(mesh, e));
    ASSERT_TRUE(flip(mesh, e));
    ASSERT_VALID(mesh);
    EXPECT_TRUE(test::same_faces_by_position(mesh, before));
}

// Cube side -x, seen from outside: its diagonal 0-6 becomes 2-4.
//   6 ----- 4        6 ----- 4
//   | \     |        |     / |
//   |   \   |   =>   |   /   |
//   |     \ |        | /     |
//   2 ----- 0        2 ----- 0
TEST(Flip, CubeSideDiagonal) {
    Mesh mesh = shapes::cube();
    Indexed expected = test::indexed(mesh);
    expected.remove({0, 4, 6});
    expected.remove({0, 6, 2});
    expected.add({0, 4, 2});
    expected.add({4, 6, 2});
    expect_flip(mesh, 0, 6, 2, 4);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// Cube edge 0-4 between side -x (0,4,6) and side -y (0,5,4): the new edge 5-6 bends over
// the cube's edge.
//        6                 6
//      /   \             / | \   (0,4,6) above,
//     0 --- 4     =>    0  |  4   (0,5,4) below
//      \   /             \ | /
//        5                 5
TEST(Flip, CubeEdgeAcrossSides) {
    Mesh mesh = shapes::cube();
    Indexed expected = test::indexed(mesh);
    expected.remove({0, 4, 6});
    expected.remove({0, 5, 4});
    expected.add({0, 5, 6});
    expected.add({5, 4, 6});
    expect_flip(mesh, 0, 4, 6, 5);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// Icosahedron edge 0-1 between (0,5,1) and (0,1,7):
//        5                 5
//      /   \             / | \   (0,5,1) above,
//     1 --- 0     =>    1  |  0   (0,1,7) below
//      \   /             \ | /
//        7                 7
TEST(Flip, Icosahedron) {
    Mesh mesh = shapes::icosahedron();
    Indexed expected = test::indexed(mesh);
    expected.remove({0, 5, 1});
    expected.remove({0, 1, 7});
    expected.add({5, 1, 7});
    expected.add({5, 7, 0});
    expect_flip(mesh, 0, 1, 5, 7);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// torus(4,4), vertex (i,j) = 4i + j: the diagonal of cell (0,0) turns the other way.
//   1 ----- 5        1 ----- 5
//   |     / |        | \     |
//   |   /   |   =>   |   \   |
//   | /     |        |     \ |
//   0 ----- 4        0 ----- 4
TEST(Flip, Torus) {
    Mesh mesh = shapes::torus(4, 4);
    Indexed expected = test::indexed(mesh);
    expected.remove({0, 4, 5});
    expected.remove({0, 5, 1});
    expected.add({0, 4, 1});
    expected.add({4, 5, 1});
    expect_flip(mesh, 0, 5, 1, 4);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
    EXPECT_EQ(test::euler(mesh), 0);
}

// grid(2,2), vertex (i,j) = 3j + i. Interior edge 1-4 between (0,1,4) and (1,5,4):
//   6 --- 7 --- 8        6 --- 7 --- 8
//   |   / |   / |        |   / |   / |
//   | /   | /   |        | /   | /   |
//   3 --- 4 --- 5   =>   3 --- 4 --- 5
//   |   / |   / |        |   /   _/  |
//   | /   | /   |        | / __/     |
//   0 --- 1 --- 2        0 --- 1 --- 2      (new edge 0-5)
TEST(Flip, GridInteriorEdge) {
    Mesh mesh = shapes::grid(2, 2);
    Indexed expected = test::indexed(mesh);
    expected.remove({0, 1, 4});
    expected.remove({1, 5, 4});
    expected.add({0, 1, 5});
    expected.add({0, 5, 4});
    expect_flip(mesh, 1, 4, 0, 5);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// grid(2,2): the diagonal 0-4 of the first cell becomes 1-3.
TEST(Flip, GridDiagonal) {
    Mesh mesh = shapes::grid(2, 2);
    Indexed expected = test::indexed(mesh);
    expected.remove({0, 1, 4});
    expected.remove({0, 4, 3});
    expected.add({0, 1, 3});
    expected.add({1, 4, 3});
    expect_flip(mesh, 0, 4, 3, 1);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// ----------------------------------------------------------------- polygons

// A quad Q beside a triangle T across 0-3 (Scotty3D's rule): the edge turns to join the
// corners after its ends, 1 (after 0 in Q) and 4 (after 3 in T); each face keeps its sides.
//        3 ----- 2              3 ----- 2
//      / |       |            /         |
//     4 T|   Q   |     =>    4     Q    |      Q: (0,1,2,3) -> (1,2,3,4)
//      \ |       |            \ ` - . _ |      T: (0,3,4)   -> (0,1,4)
//        0 ----- 1              0 ----- 1
TEST(Flip, QuadBesideTriangle) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0.5, 0}},
                                      {{0, 1, 2, 3}, {0, 3, 4}});
    Indexed expected = test::indexed(mesh);
    expected.remove({0, 1, 2, 3});
    expected.remove({0, 3, 4});
    expected.add({1, 2, 3, 4});
    expected.add({0, 1, 4});
    expect_flip(mesh, 0, 3, 1, 4);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// Two quads side by side: the middle edge 1-4 turns into the diagonal 2-3.
//   3 ----- 4 ----- 5        3 ----- 4 ----- 5
//   |       |       |        | ` .           |
//   |       |       |   =>   |     ` .       |     (0,1,4,3) -> (0,1,2,3)
//   |       |       |        |         ` .   |     (1,2,5,4) -> (2,5,4,3)
//   0 ----- 1 ----- 2        0 ----- 1 ----- 2
TEST(Flip, TwoQuads) {
    Mesh mesh = test::quad_strip(2);
    Indexed expected = test::indexed(mesh);
    expected.remove({0, 1, 4, 3});
    expected.remove({1, 2, 5, 4});
    expected.add({0, 1, 2, 3});
    expected.add({2, 5, 4, 3});
    expect_flip(mesh, 1, 4, 2, 3);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
    // The next flip turns it on: 2-3 becomes 0-5 (after 2 comes 5 in one quad, after 3
    // comes 0 in the other), and the third brings the edge back between 1 and 4.
    const Edge e = mesh.find_edge(Vertex(2), Vertex(3));
    ASSERT_TRUE(flip(mesh, e));
    ASSERT_VALID(mesh);
    EXPECT_EQ(test::endpoints(mesh, e), std::make_pair(0u, 5u));
    ASSERT_TRUE(flip(mesh, e));
    ASSERT_VALID(mesh);
    EXPECT_EQ(test::endpoints(mesh, e), std::make_pair(1u, 4u));
}

// ----------------------------------------------------------------- refusals

// Asserts that flipping `e` is refused with `reason` and leaves the mesh bit for bit.
void expect_refused(Mesh& mesh, Edge e, std::string_view reason) {
    const Mesh before = mesh;
    EXPECT_FALSE(is_flip_ok(mesh, e));
    EXPECT_EQ(is_flip_ok(mesh, e).reason(), reason);
    const OpResult<Edge> r = flip(mesh, e);
    EXPECT_FALSE(r);
    EXPECT_EQ(r.reason(), reason);
    EXPECT_TRUE(test::identical(mesh, before));
}

// grid(2,2): the bottom edge 0-1 has only the face (0,1,4).
TEST(Flip, RefusesBoundaryEdge) {
    Mesh mesh = shapes::grid(2, 2);
    expect_refused(mesh, mesh.find_edge(Vertex(0), Vertex(1)), "cannot flip: boundary edge");
}

// A face that would gain a corner it already has: faces F = (0,1,2,3) and G = (2,1,0,4)
// share the two edges at vertex 1, which has valence 2. Flipping 0-1 would join 2 to 4, and G
// already holds 2.
//   3 ----- 2
//   |   F / |
//   |   1   4      F = (0,1,2,3), G = (2,1,0,4)
//   | / G   |
//   0 ------'
TEST(Flip, RefusesWhenAFaceWouldVisitAVertexTwice) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {0.5, 0.5, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 0}},
                                      {{0, 1, 2, 3}, {2, 1, 0, 4}});
    ASSERT_VALID(mesh);
    expect_refused(mesh, mesh.find_edge(Vertex(0), Vertex(1)),
                   "cannot flip: a face would visit a vertex twice");
    expect_refused(mesh, mesh.find_edge(Vertex(1), Vertex(2)),
                   "cannot flip: a face would visit a vertex twice");
}

// Every edge of a tetrahedron: the opposite corners are already joined.
TEST(Flip, RefusesExistingEdgeOnTetrahedron) {
    Mesh mesh = shapes::tetrahedron();
    for (Edge e : mesh.edges()) {
        expect_refused(mesh, e, "cannot flip: the new edge already exists");
    }
}

// Centre 0 of valence 3 inside a triangle 1-2-3: flipping a spoke would double a rim edge.
//          3
//        / | \   spokes 0-1, 0-2, 0-3; flipping 0-1 in (0,1,2), (0,3,1)
//       /  0  \  would join 2 and 3
//      / /   \ \ again
//     1 ------- 2
TEST(Flip, RefusesExistingEdgeAtValenceThree) {
    Mesh mesh = test::one_ring(3);
    expect_refused(mesh, mesh.find_edge(Vertex(0), Vertex(1)),
                   "cannot flip: the new edge already exists");
}

// Two triangles (0,1,2) and (0,2,1) glued along all three edges: a == d.
TEST(Flip, RefusesPillow) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}});
    for (Edge e : mesh.edges()) {
        expect_refused(mesh, e, "cannot flip: the new edge already exists");
    }
}

TEST(Flip, RefusesDeletedEdge) {
    Mesh mesh = shapes::grid(2, 2);
    const Edge e = mesh.find_edge(Vertex(1), Vertex(4));
    ASSERT_TRUE(collapse(mesh, e));
    expect_refused(mesh, e, "cannot flip: the edge is deleted");
}

}  // namespace
}  // namespace meshedit
