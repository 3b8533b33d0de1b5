// Polygon triangulation by diagonals that never duplicate an existing edge: a fan from
// from_vertex(halfedge(f)) when possible, another fan or any other triangulation otherwise,
// and a refusal when every triangulation would duplicate an edge.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "core/op_test_util.h"
#include "meshedit/core/local_ops.h"
#include "meshedit/core/shapes.h"

namespace meshedit {
namespace {

using test::Indexed;

const std::vector<Vec3> kSquare{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};

// A single quad, fanned from corner 1 (where halfedge(f) starts):
//   3 ----- 2        3 ----- 2
//   |       |        | \     |
//   |       |   =>   |   \   |
//   |       |        |     \ |
//   0 ----- 1        0 ----- 1
TEST(Triangulate, QuadFansFromItsHalfedge) {
    Mesh mesh = test::mesh_from_faces(kSquare, {{0, 1, 2, 3}});
    const Face f(0);
    mesh.set_halfedge(f, mesh.find_halfedge(Vertex(1), Vertex(2)));
    const OpResult<Face> r = triangulate(mesh, f);
    ASSERT_TRUE(r) << r.reason();
    ASSERT_VALID(mesh);
    EXPECT_EQ(*r, f);
    EXPECT_TRUE(mesh.is_triangle(f));
    EXPECT_TRUE(mesh.find_edge(Vertex(1), Vertex(3)).is_valid());
    const Mesh expected = test::mesh_from_faces(kSquare, {{1, 2, 3}, {1, 3, 0}});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// A regular pentagon, fanned from corner 0 by the diagonals 0-2 and 0-3:
//       2 ---- 1            2 ---- 1
//      /        |          / '.    |
//     3         |   =>    3 -- '.  |
//      \        |           \    '.|
//       4 ---- 0            4 ---- 0
TEST(Triangulate, Pentagon) {
    std::vector<Vec3> p;
    for (int i = 0; i < 5; ++i) {
        const double a = 2.0 * std::numbers::pi * i / 5;
        p.push_back({std::cos(a), std::sin(a), 0});
    }
    Mesh mesh = test::mesh_from_faces(p, {{0, 1, 2, 3, 4}});
    const Face f(0);
    mesh.set_halfedge(f, mesh.find_halfedge(Vertex(0), Vertex(1)));
    ASSERT_TRUE(triangulate(mesh, f));
    ASSERT_VALID(mesh);
    EXPECT_EQ(test::euler(mesh), 1);
    const Mesh expected = test::mesh_from_faces(p, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// A closed sphere of three faces: the quad Q = (0,1,2,3), and A = (1,0,2), B = (3,2,0)
// glued along the edge 0-2 outside Q. A fan from 0 would draw 0-2 a second time, so Q is
// cut along 1-3 instead, which makes a tetrahedron.
TEST(Triangulate, AvoidsExistingDiagonal) {
    Mesh mesh = test::mesh_from_faces(kSquare, {{0, 1, 2, 3}, {1, 0, 2}, {3, 2, 0}});
    ASSERT_VALID(mesh);
    const Face q(0);
    mesh.set_halfedge(q, mesh.find_halfedge(Vertex(0), Vertex(1)));
    ASSERT_TRUE(triangulate(mesh, q));
    ASSERT_VALID(mesh);
    const Mesh expected =
        test::mesh_from_faces(kSquare, {{1, 2, 3}, {1, 3, 0}, {1, 0, 2}, {3, 2, 0}});
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected));
}

// Every quad of a quad sphere, each fanned from the start of its halfedge.
TEST(Triangulate, QuadSphere) {
    Mesh mesh = shapes::quad_sphere(2);
    Indexed expected = test::indexed(mesh);
    expected.faces.clear();
    for (Face f : mesh.faces()) {
        std::vector<std::uint32_t> c;
        for (Vertex v : mesh.vertices(f)) {
            c.push_back(v.idx());
        }
        ASSERT_EQ(c.size(), 4u);
        // vertices(f) starts at to_vertex(halfedge(f)); the apex is the corner before it.
        expected.add({c[3], c[0], c[1]});
        expected.add({c[3], c[1], c[2]});
    }
    const std::size_t quads = mesh.n_faces();
    EXPECT_EQ(triangulate(mesh), quads);
    ASSERT_VALID(mesh);
    EXPECT_TRUE(mesh.is_triangle_mesh());
    EXPECT_EQ(mesh.n_faces(), 2 * quads);
    EXPECT_EQ(test::euler(mesh), 2);
    EXPECT_TRUE(test::same_faces_by_position(mesh, expected.build()));
    EXPECT_EQ(triangulate(mesh), 0u) << "nothing left to do";
}

// A triangle is accepted and left exactly as it is.
TEST(Triangulate, TriangleIsUnchanged) {
    Mesh mesh = shapes::icosahedron();
    const Mesh before = mesh;
    EXPECT_TRUE(is_triangulate_ok(mesh, Face(3)));
    const OpResult<Face> r = triangulate(mesh, Face(3));
    ASSERT_TRUE(r);
    EXPECT_EQ(*r, Face(3));
    EXPECT_TRUE(test::identical(mesh, before));
}

// ----------------------------------------------------------------- refusals

// A 3 x 3 torus, vertex (i,j) = 3i + j for i, j mod 3. The cell Q = (0,0)-(1,0)-(1,1)-(0,1)
// stays a quad. The two cells right of it are cut with the long diagonal (1,0)-(3,1), i.e.
// (1,0)-(0,1); the two cells above it with (1,1)-(0,3), i.e. (1,1)-(0,0). Both diagonals of
// Q now exist, and a quad has no other triangulation.
//
//   j=3 (0,0)  .----.----.----.            Q   = cell (0,0)
//              | C /|  / |  / |            R   = cells (1,0), (2,0), holding 3-1
//   j=2        | / /| /  | /  |            C   = cells (0,1), (0,2), holding 4-0
//              |/ / |/   |/   |            the other 4 cells: usual diagonals
//   j=1        .----.----.----.
//              | Q  |  R   _/ |
//   j=0        .----.----.----.
//             i=0  i=1  i=2  i=3
TEST(Triangulate, RefusesWhenEveryTriangulationDuplicatesAnEdge) {
    auto id = [](int i, int j) { return std::uint32_t(3 * (i % 3) + (j % 3)); };
    std::vector<Vec3> p;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            const double u = 2.0 * std::numbers::pi * i / 3, v = 2.0 * std::numbers::pi * j / 3;
            const double rho = 1.0 + 0.4 * std::cos(v);
            p.push_back({rho * std::cos(u), rho * std::sin(u), 0.4 * std::sin(v)});
        }
    }
    std::vector<std::vector<std::uint32_t>> faces{
        {id(0, 0), id(1, 0), id(1, 1), id(0, 1)},  // Q
        {id(1, 0), id(2, 0), id(3, 1)},            // R
        {id(2, 0), id(3, 0), id(3, 1)},           {id(1, 0), id(3, 1), id(2, 1)},
        {id(1, 0), id(2, 1), id(1, 1)},           {id(1, 1), id(1, 2), id(0, 3)},  // C
        {id(1, 2), id(1, 3), id(0, 3)},           {id(0, 3), id(0, 2), id(1, 1)},
        {id(0, 2), id(0, 1), id(1, 1)},
    };
    for (int i = 1; i < 3; ++i) {
        for (int j = 1; j < 3; ++j) {
            faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            faces.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    BuildReport report;
    Mesh mesh = build_mesh(test::soup_from_faces(p, faces), &report);
    ASSERT_FALSE(report.repaired()) << report.summary();
    ASSERT_VALID(mesh);
    ASSERT_EQ(test::euler(mesh), 0);
    const Face q(0);
    ASSERT_EQ(mesh.valence(q), 4u);
    ASSERT_TRUE(mesh.find_edge(Vertex(id(1, 0)), Vertex(id(0, 1))).is_valid());
    ASSERT_TRUE(mesh.find_edge(Vertex(id(0, 0)), Vertex(id(1, 1))).is_valid());

    const Mesh before = mesh;
    const char* reason = "cannot triangulate: every triangulation would duplicate an existing edge";
    EXPECT_EQ(is_triangulate_ok(mesh, q).reason(), reason);
    const OpResult<Face> r = triangulate(mesh, q);
    EXPECT_FALSE(r);
    EXPECT_EQ(r.reason(), reason);
    EXPECT_TRUE(test::identical(mesh, before));
    EXPECT_EQ(triangulate(mesh), 0u);
    EXPECT_TRUE(test::identical(mesh, before));
}

TEST(Triangulate, RefusesDeletedFace) {
    Mesh mesh = shapes::grid(2, 2);
    ASSERT_TRUE(collapse(mesh, mesh.find_edge(Vertex(1), Vertex(4))));
    Face dead;
    for (std::uint32_t i = 0; i < mesh.faces_size(); ++i) {
        if (mesh.is_deleted(Face(i))) {
            dead = Face(i);
        }
    }
    ASSERT_TRUE(dead.is_valid());
    const Mesh before = mesh;
    EXPECT_EQ(triangulate(mesh, dead).reason(), "cannot triangulate: the face is deleted");
    EXPECT_TRUE(test::identical(mesh, before));
}

}  // namespace
}  // namespace meshedit
