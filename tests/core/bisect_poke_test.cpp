// Bisect (a vertex inserted on an edge, no face divided) and poke (a face becomes a fan
// around its centre). Each case draws the input and the result; the expected mesh is the
// input's face list edited by hand.

#include <gtest/gtest.h>

#include <cstdint>

#include "core/op_test_util.h"
#include "meshedit/core/attributes.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

using test::Indexed;

// A quad beside a triangle; they share edge 1-2:
//   3 ----- 2
//   |       | \     quad (0,1,2,3)
//   |  quad |  4    triangle (1,4,2)
//   |       | /
//   0 ----- 1
Mesh quad_and_triangle() {
    return test::mesh_from_faces({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}},
                                 {{0, 1, 2, 3}, {1, 4, 2}});
}

// Bisects b-c, which must succeed, and checks the documented halfedge of m (as split's).
Vertex expect_bisect(Mesh& mesh, std::uint32_t b, std::uint32_t c) {
    const Edge e = mesh.find_edge(Vertex(b), Vertex(c));
    EXPECT_TRUE(e.is_valid());
    const bool boundary = mesh.is_boundary(e);
    const unsigned i = mesh.is_boundary(Mesh::halfedge(e, 1)) ? 1 : 0;
    const Vertex head = mesh.to_vertex(Mesh::halfedge(e, i));
    const std::size_t faces = mesh.n_faces();
    EXPECT_TRUE(is_bisect_ok(mesh, e));
    const OpResult<Vertex> r = bisect(mesh, e);
    EXPECT_TRUE(r) << r.reason();
    if (!r) {
        return Vertex();
    }
    EXPECT_VALID(mesh);
    const Vertex m = *r;
    EXPECT_EQ(mesh.halfedge(m), Mesh::halfedge(e, i));
    EXPECT_EQ(mesh.to_vertex(mesh.halfedge(m)), head);
    EXPECT_EQ(mesh.is_boundary(m), boundary);
    EXPECT_EQ(mesh.valence(m), 2u);
    EXPECT_EQ(mesh.n_faces(), faces) << "bisect divides no face";
    return m;
}

// The diagonal 0-2 gets m = 4; both triangles become quads:
//   3 ----- 2        3 ----- 2
//   |     / |        |     / |
//   |   /   |   =>   |   4   |      (0,1,2) -> (0,1,2,4), (0,2,3) -> (0,4,2,3)
//   | /     |        | /     |
//   0 ----- 1        0 ----- 1
TEST(Bisect, InteriorEdgeBetweenTriangles) {
    Mesh mesh = test::two_triangles();
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex({0.5, 0.5, 0});
    expected.remove({0, 1, 2});
    expected.remove({0, 2, 3});
    expected.add({0, 1, 2, m});
    expected.add({0, m, 2, 3});
    EXPECT_EQ(expect_bisect(mesh, 0, 2), Vertex(m));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// A boundary edge: the quad gains a corner and the boundary loop a vertex.
//   3 ----- 2           3 ----- 2
//   |       | \         |       | \ (1,4,2) unchanged
//   |  quad |  4   =>   |  quad |  4
//   |       | /         |       | /   (0,1,2,3) -> (0,5,1,2,3)
//   0 ----- 1           0 --5-- 1
TEST(Bisect, BoundaryEdgeOfAQuad) {
    Mesh mesh = quad_and_triangle();
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex({0.5, 0, 0});
    expected.remove({0, 1, 2, 3});
    expected.add({0, m, 1, 2, 3});
    EXPECT_EQ(expect_bisect(mesh, 0, 1), Vertex(m));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
    EXPECT_TRUE(mesh.is_boundary(mesh.halfedge(Vertex(m)))) << "boundary anchor";
}

// The shared side of a quad and a triangle: a pentagon and a quad.
TEST(Bisect, SideBetweenAQuadAndATriangle) {
    Mesh mesh = quad_and_triangle();
    Indexed expected = test::indexed(mesh);
    const std::uint32_t m = expected.add_vertex({1, 0.5, 0});
    expected.remove({0, 1, 2, 3});
    expected.remove({1, 4, 2});
    expected.add({0, 1, m, 2, 3});
    expected.add({1, 4, 2, m});
    EXPECT_EQ(expect_bisect(mesh, 1, 2), Vertex(m));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

TEST(Bisect, CreaseLeavesTwoCreases) {
    Mesh mesh = shapes::cube();
    auto crease = mesh.property<Edge, std::uint8_t>(kCreaseProperty, 0);
    const Edge e = mesh.find_edge(Vertex(0), Vertex(1));
    ASSERT_TRUE(e.is_valid());
    crease[e] = 1;
    const Vertex m = expect_bisect(mesh, 0, 1);
    EXPECT_EQ(crease[mesh.find_edge(Vertex(0), m)], 1);
    EXPECT_EQ(crease[mesh.find_edge(m, Vertex(1))], 1);
}

TEST(Bisect, DeletedEdgeIsRefusedAndNothingChanges) {
    Mesh mesh = test::two_triangles();
    ASSERT_TRUE(collapse(mesh, mesh.find_edge(Vertex(0), Vertex(1))));
    const Mesh before = mesh;
    Edge deleted;
    for (std::uint32_t i = 0; i < mesh.edges_size(); ++i) {
        if (mesh.is_deleted(Edge(i))) {
            deleted = Edge(i);
        }
    }
    ASSERT_TRUE(deleted.is_valid());
    const OpResult<Vertex> r = bisect(mesh, deleted);
    EXPECT_FALSE(r);
    EXPECT_EQ(r.reason(), "cannot bisect: the edge is deleted");
    EXPECT_TRUE(test::identical(mesh, before));
}

// Pokes f, which must succeed, and checks what poke() documents: f stays the triangle on
// its old halfedge, halfedge(c) runs to that halfedge's tail, n - 1 faces and n edges are
// new, and c has valence n.
Vertex expect_poke(Mesh& mesh, Face f) {
    const Halfedge h = mesh.halfedge(f);
    const Vertex first = mesh.from_vertex(h);
    const std::size_t n = mesh.valence(f);
    const std::size_t faces = mesh.n_faces();
    const std::size_t edges = mesh.n_edges();
    EXPECT_TRUE(is_poke_ok(mesh, f));
    const OpResult<Vertex> r = poke(mesh, f);
    EXPECT_TRUE(r) << r.reason();
    if (!r) {
        return Vertex();
    }
    EXPECT_VALID(mesh);
    const Vertex c = *r;
    EXPECT_EQ(mesh.to_vertex(mesh.halfedge(c)), first);
    EXPECT_EQ(mesh.face(h), f);
    EXPECT_TRUE(mesh.is_triangle(f));
    EXPECT_EQ(mesh.valence(c), n);
    EXPECT_EQ(mesh.n_faces(), faces + n - 1);
    EXPECT_EQ(mesh.n_edges(), edges + n);
    return c;
}

// The quad becomes four triangles around its centre 5 = (0.5, 0.5):
//   3 ----- 2            3 ----- 2
//   |       | \          | \   / | \ (1,4,2) unchanged
//   |       |  4   =>    |   5   |  4
//   |       | /          | /   \ | /
//   0 ----- 1            0 ----- 1
TEST(Poke, QuadBecomesAFan) {
    Mesh mesh = quad_and_triangle();
    Indexed expected = test::indexed(mesh);
    const std::uint32_t c = expected.add_vertex({0.5, 0.5, 0});
    expected.remove({0, 1, 2, 3});
    expected.add({0, 1, c});
    expected.add({1, 2, c});
    expected.add({2, 3, c});
    expected.add({3, 0, c});
    EXPECT_EQ(expect_poke(mesh, Face(0)), Vertex(c));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
}

// A triangle with a boundary side: three triangles, and the boundary is unchanged.
TEST(Poke, TriangleOnTheBoundary) {
    Mesh mesh = quad_and_triangle();
    Indexed expected = test::indexed(mesh);
    const std::uint32_t c = expected.add_vertex({4.0 / 3.0, 0.5, 0});
    expected.remove({1, 4, 2});
    expected.add({1, 4, c});
    expected.add({4, 2, c});
    expected.add({2, 1, c});
    EXPECT_EQ(expect_poke(mesh, Face(1)), Vertex(c));
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
    EXPECT_TRUE(mesh.is_boundary(Vertex(4)));
    EXPECT_FALSE(mesh.is_boundary(Vertex(c)));
}

// A regular pentagon: the centre is the average of the corners.
TEST(Poke, PentagonCentreIsTheCornerAverage) {
    std::vector<Vec3> corners;
    Vec3 sum{0, 0, 0};
    for (int i = 0; i < 5; ++i) {
        corners.push_back({std::cos(1.0 + 1.25 * i), std::sin(1.0 + 1.25 * i), 0.25 * i});
        sum += corners.back();
    }
    Mesh mesh = test::mesh_from_faces(corners, {{0, 1, 2, 3, 4}});
    const Vertex c = expect_poke(mesh, Face(0));
    const Vec3 expected = sum / 5.0;
    EXPECT_NEAR(mesh.position(c).x, expected.x, 1e-15);
    EXPECT_NEAR(mesh.position(c).y, expected.y, 1e-15);
    EXPECT_NEAR(mesh.position(c).z, expected.z, 1e-15);
}

TEST(Poke, DeletedFaceIsRefusedAndNothingChanges) {
    Mesh mesh = test::two_triangles();
    ASSERT_TRUE(collapse(mesh, mesh.find_edge(Vertex(0), Vertex(1))));
    ASSERT_TRUE(mesh.is_deleted(Face(0)));
    const Mesh before = mesh;
    const OpResult<Vertex> r = poke(mesh, Face(0));
    EXPECT_FALSE(r);
    EXPECT_EQ(r.reason(), "cannot poke: the face is deleted");
    EXPECT_TRUE(test::identical(mesh, before));
}

}  // namespace
}  // namespace meshedit
