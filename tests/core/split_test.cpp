// Edge split at the midpoint (docs/spec.md §3): an interior edge's two triangles become four, a
// boundary edge's one triangle becomes two and the boundary gains the new vertex m. The
// expected meshes append m's position to the input's list and replace the faces by hand.

#include <gtest/gtest.h>

#include <cstdint>

#include "core/op_test_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

using test::Indexed;

// Splits the edge b-c, which must succeed, and checks the documented halfedge of m and its
// valence (`valence`, or 3 on the boundary and 4 inside between triangles):
// interior edge: halfedge(m) = halfedge(e, 0), from m towards its old head; boundary edge:
// the boundary halfedge along the old edge, from m towards the old boundary halfedge's head.
Vertex expect_split(Mesh& mesh, std::uint32_t b, std::uint32_t c, std::size_t valence = 0) {
    const Edge e = mesh.find_edge(Vertex(b), Vertex(c));
    EXPECT_TRUE(e.is_valid());
    const bool boundary = mesh.is_boundary(e);
    const unsigned i = mesh.is_boundary(Mesh::halfedge(e, 1)) ? 1 : 0;
    const Vertex head = mesh.to_vertex(Mesh::halfedge(e, i));
    EXPECT_TRUE(is_split_ok(mesh, e));
    const OpResult<Vertex> r = split(mesh, e);
    EXPECT_TRUE(r) << r.reason();
    if (!r) {
        return Vertex();
    }
    EXPECT_VALID(mesh);
    const Vertex m = *r;
    const Halfedge h = mesh.halfedge(m);
    EXPECT_EQ(h, Mesh::halfedge(e, i));
    EXPECT_EQ(Mesh::edge(h), e) << "e is kept as one half";
    EXPECT_EQ(mesh.to_vertex(h), head);
    EXPECT_EQ(mesh.is_boundary(h), boundary);
    EXPECT_EQ(mesh.is_boundary(m), boundary);
    EXPECT_EQ(mesh.valence(m), valence != 0 ? valence : boundary ? 3u : 4u);
    return m;
}

// Two triangles; the diagonal 0-2 gets m = 4 at the centre:
//   3 ----- 2        3 ----- 2
//   |     / |        | \   / |
//   |   /   |   =>   |   4   |
//   | /     |        | /   \ |
//   0 ----- 1        0 ----- 1
TEST(Split, TwoTriangles) {
    Mesh mesh = test::two_triangles();
    const Vertex m = expect_split(mesh, 0, 2);
    EXPECT_EQ(m, Vertex(4));
    const Mesh expected =
        test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0}},
                              {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// Cube side -x: the diagonal 0-6 gets m = 8 at (-1, 0, 0), the side's centre.
//   6 ----- 4        6 ----- 4
//   | \     |        | \   / |
//   |   \   |   =>   |   8   |
//   |     \ |        | /   \ |
//   2 ----- 0        2 ----- 0
TEST(Split, CubeSideDiagonal) {
    Mesh mesh = shapes::cube();
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex({-1, 0, 0});
    expected.remove({0, 4, 6});
    expected.remove({0, 6, 2});
    expected.add({0, 4, m});
    expected.add({4, 6, m});
    expected.add({6, 2, m});
    expected.add({2, 0, m});
    EXPECT_EQ(expect_split(mesh, 0, 6), Vertex(m));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// Icosahedron edge 0-1 between (0,5,1) and (0,1,7); m = 12 is the chord midpoint (not
// projected to the sphere).
//        5                 5
//      /   \             / | \   (0,5,1) above,
//     1 --- 0     =>    1--12--0   (0,1,7) below
//      \   /             \ | /
//        7                 7
TEST(Split, Icosahedron) {
    Mesh mesh = shapes::icosahedron();
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex(test::midpoint(mesh, 0, 1));
    expected.remove({0, 5, 1});
    expected.remove({0, 1, 7});
    expected.add({0, 5, m});
    expected.add({5, 1, m});
    expected.add({1, 7, m});
    expected.add({7, 0, m});
    EXPECT_EQ(expect_split(mesh, 0, 1), Vertex(m));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// torus(4,4), vertex (i,j) = 4i + j: the diagonal 0-5 of cell (0,0) gets m = 16.
//   1 ----- 5        1 ----- 5
//   |     / |        | \   / |
//   |   /   |   =>   |   16  |
//   | /     |        | /   \ |
//   0 ----- 4        0 ----- 4
TEST(Split, Torus) {
    Mesh mesh = shapes::torus(4, 4);
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex(test::midpoint(mesh, 0, 5));
    expected.remove({0, 4, 5});
    expected.remove({0, 5, 1});
    expected.add({0, 4, m});
    expected.add({4, 5, m});
    expected.add({5, 1, m});
    expected.add({1, 0, m});
    EXPECT_EQ(expect_split(mesh, 0, 5), Vertex(m));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
    EXPECT_EQ(test::euler(mesh), 0);
}

// grid(2,2), vertex (i,j) = 3j + i. Interior edge 1-4 gets m = 9 at (0.5, 0.25):
//   3 --- 4 --- 5        3 --- 4 --- 5
//   |   / |   / |        |   / | \   |
//   | /   | /   |   =>   | /   9   \ |
//   0 --- 1 --- 2        0 --- 1 --- 2     (plus 0-9 and 9-5)
TEST(Split, GridInteriorEdge) {
    Mesh mesh = shapes::grid(2, 2);
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex({0.5, 0.25, 0});
    expected.remove({0, 1, 4});
    expected.remove({1, 5, 4});
    expected.add({0, 1, m});
    expected.add({0, m, 4});
    expected.add({1, 5, m});
    expected.add({m, 5, 4});
    EXPECT_EQ(expect_split(mesh, 1, 4), Vertex(m));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// grid(2,2): the bottom boundary edge 0-1 of (0,1,4) gets m = 9 at (0.25, 0); the boundary
// runs 1 -> 9 -> 0, so halfedge(m) is the boundary halfedge m -> 0.
//   3 --- 4          3 --- 4
//   |   / |          |  _/|/|
//   | /   |    =>    | /  / |
//   0 --- 1          0-9--- 1      (faces (0,9,4) and (9,1,4))
TEST(Split, GridBoundaryEdge) {
    Mesh mesh = shapes::grid(2, 2);
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex({0.25, 0, 0});
    expected.remove({0, 1, 4});
    expected.add({0, m, 4});
    expected.add({m, 1, 4});
    const Vertex v = expect_split(mesh, 0, 1);
    ASSERT_EQ(v, Vertex(m));
    EXPECT_EQ(mesh.to_vertex(mesh.halfedge(v)), Vertex(0));
    EXPECT_EQ(mesh.to_vertex(mesh.next(mesh.halfedge(v))), Vertex(3)) << "boundary continues";
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// grid(2,2): the top boundary edge 7-8 of (4,8,7), whose interior halfedge runs the other
// way (8 -> 7): halfedge(m) is the boundary halfedge m -> 8.
//   6 -- 7 -- 8        6 -- 7 -m- 8
//   |  / |  / |   =>   |  / |  /  |     (faces (4,8,m) and (4,m,7))
//   3 -- 4 -- 5        3 -- 4 --- 5
TEST(Split, GridTopBoundaryEdge) {
    Mesh mesh = shapes::grid(2, 2);
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex({0.75, 1, 0});
    expected.remove({4, 8, 7});
    expected.add({4, 8, m});
    expected.add({4, m, 7});
    const Vertex v = expect_split(mesh, 7, 8);
    ASSERT_EQ(v, Vertex(m));
    EXPECT_EQ(mesh.to_vertex(mesh.halfedge(v)), Vertex(8));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// Every boundary edge of a grid, one at a time, from both sides of the anchor rule.
TEST(Split, EveryGridBoundaryEdge) {
    const Mesh input = shapes::grid(3, 2);
    for (Edge e : input.edges()) {
        if (!input.is_boundary(e)) {
            continue;
        }
        Mesh mesh = input;
        const auto [b, c] = test::endpoints(mesh, e);
        expect_split(mesh, b, c);
        EXPECT_EQ(mesh.n_faces(), input.n_faces() + 1);
    }
}

// Both halves of a crease edge stay creases; the two new spokes do not.
TEST(Split, KeepsCrease) {
    Mesh mesh = shapes::cube();
    auto crease = mesh.add_property<Edge, std::uint8_t>(kCreaseProperty, 0);
    const Edge e = mesh.find_edge(Vertex(0), Vertex(1));
    crease[e] = 1;
    const Vertex m = expect_split(mesh, 0, 1);
    int creased = 0;
    for (Edge s : mesh.edges(m)) {
        creased += crease[s];
    }
    EXPECT_EQ(creased, 2);
    EXPECT_EQ(crease[mesh.find_edge(m, Vertex(0))], 1);
    EXPECT_EQ(crease[mesh.find_edge(m, Vertex(1))], 1);
}

// ----------------------------------------------------------------- polygons

// A quad Q beside a triangle T across 0-3: T is divided as ever (m joined to 4), Q only
// gains m as a fifth corner.
//        3 ----- 2              3 ----- 2
//      / |       |            / |       |
//     4 T|   Q   |     =>    4 -5   Q   |     Q: (0,1,2,3) -> (0,1,2,3,5)
//      \ |       |            \ |       |     T: (0,3,4)   -> (5,3,4), (0,5,4)
//        0 ----- 1              0 ----- 1
TEST(Split, QuadBesideTriangle) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0.5, 0}},
                                      {{0, 1, 2, 3}, {0, 3, 4}});
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex({0, 0.5, 0});
    expected.remove({0, 1, 2, 3});
    expected.remove({0, 3, 4});
    expected.add({0, 1, 2, 3, m});
    expected.add({m, 3, 4});
    expected.add({0, m, 4});
    const std::size_t edges = mesh.n_edges();
    const Vertex v = expect_split(mesh, 0, 3, 3);
    EXPECT_EQ(v, Vertex(m));
    EXPECT_EQ(mesh.n_edges(), edges + 2);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// A boundary side of a quad: the quad gains m, the boundary loop too; nothing is divided.
TEST(Split, BoundarySideOfAQuad) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {-1, 0.5, 0}},
                                      {{0, 1, 2, 3}, {0, 3, 4}});
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex({0.5, 0, 0});
    expected.remove({0, 1, 2, 3});
    expected.add({0, m, 1, 2, 3});
    EXPECT_EQ(expect_split(mesh, 0, 1, 2), Vertex(m));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// ----------------------------------------------------------------- refusals

void expect_refused(Mesh& mesh, Edge e, std::string_view reason) {
    const Mesh before = mesh;
    EXPECT_EQ(is_split_ok(mesh, e).reason(), reason);
    const OpResult<Vertex> r = split(mesh, e);
    EXPECT_FALSE(r);
    EXPECT_EQ(r.reason(), reason);
    EXPECT_TRUE(test::identical(mesh, before));
}

// Two triangles (0,1,2) and (0,2,1) glued along all three edges: the spokes from m to the
// opposite corners would be one and the same pair of vertices.
TEST(Split, RefusesPillow) {
    Mesh mesh = test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}});
    ASSERT_VALID(mesh);
    for (Edge e : mesh.edges()) {
        expect_refused(mesh, e, "cannot split: the new edges would coincide");
    }
}

TEST(Split, RefusesDeletedEdge) {
    Mesh mesh = shapes::grid(2, 2);
    const Edge e = mesh.find_edge(Vertex(1), Vertex(4));
    ASSERT_TRUE(collapse(mesh, e));
    expect_refused(mesh, e, "cannot split: the edge is deleted");
}

}  // namespace
}  // namespace meshedit
